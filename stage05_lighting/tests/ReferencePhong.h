#pragma once
// An independent oracle for the render tests: the first hit found through the course's
// findGeoIntersections (sorted list, stage 3) and the catalogue's formulas written out term by
// term, so a test can say which term a pixel owes its colour to.

#include <cmath>
#include <cstdint>
#include <optional>

#include "geometries/Geometry.h"
#include "lighting/LightSource.h"
#include "lighting/LitScene.h"
#include "primitives/Double3.h"
#include "primitives/Ray.h"
#include "primitives/Util.h"

namespace rt::test {

struct ReferenceShading {
  bool hit = false;
  std::uint32_t geometry = 0;
  Double3 point, normal;
  Double3 base;      ///< background on a miss; else ambient + emission
  Double3 diffuse;   ///< Σ I_L·kD·|n·l| over the lights on the viewer's side
  Double3 specular;  ///< Σ I_L·kS·max(0,-v·r)^nSh
  int litBy = 0;     ///< how many lights are on the viewer's side
  Double3 total() const { return base + diffuse + specular; }
};

inline ReferenceShading referencePhong(const LitScene& scene, const Ray& ray) {
  ReferenceShading out;
  const auto hits = scene.geometries.findGeoIntersections(ray);
  if (hits.empty()) {
    out.base = scene.background.rgb();
    return out;
  }
  out.hit = true;
  out.geometry = hits.front().geometry;
  const Point p = hits.front().point;
  const Vector n = normalAt(scene.geometries[out.geometry], p);
  const Vector& v = ray.direction();
  const Appearance& a = scene.appearances[out.geometry];
  out.point = p.xyz();
  out.normal = n.xyz();
  out.base = scene.ambientLight.intensity().rgb() + a.emission.rgb();
  const double nv = alignZero(n.dot(v));
  if (nv == 0) return out;
  for (const LightSource& light : scene.lights) {
    const auto s = illuminate(light, p);
    if (!s) continue;
    const double nl = alignZero(n.dot(s->l));
    if (nl * nv <= 0) continue;
    ++out.litBy;
    const Double3 i = s->intensity.rgb();
    out.diffuse = out.diffuse + i * a.material.kD * std::abs(nl);
    const Double3 r = s->l.xyz() - n.xyz() * (2 * n.dot(s->l));
    const double minusVR = alignZero(-v.xyz().dot(r));
    if (minusVR > 0)
      out.specular = out.specular + i * a.material.kS * std::pow(minusVR, a.material.shininess);
  }
  return out;
}

}  // namespace rt::test
