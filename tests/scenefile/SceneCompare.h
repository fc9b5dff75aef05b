#pragma once
// Bit-for-bit comparison of scene documents, for the round-trip tests: two documents are the
// same when every number of the one has the same bits as the matching number of the other
// (so 0 and -0 differ, and a normal moved by one ulp is caught), meshes' vertices, triangles
// and normals included.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <variant>

#include "scenefile/LitDocument.h"
#include "scenefile/MeshDocument.h"
#include "scenefile/SceneDocument.h"

namespace rt::testing {

inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// Appends every number of the document, in a fixed order, as its bit pattern in hex; two
/// documents are the same exactly when their fingerprints are equal (and a failing comparison
/// shows where they part).
class Fingerprint {
 public:
  explicit Fingerprint(const SceneDocument& d) {
    const CameraSpec& c = d.camera;
    label("camera");
    add(c.location.xyz());
    if (c.target) add(c.target->xyz());
    if (c.to) add(c.to->xyz());
    add(c.up.xyz());
    add(c.vpWidth, c.vpHeight, c.vpDistance);
    add(c.nX);
    add(c.nY);
    label("render " + d.render.tracer);
    add(d.render.maxLevel);
    add(d.render.minK);
    label("scene " + litScene(d).name);
    add(litScene(d).background.rgb());
    add(litScene(d).ambientLight.ia().rgb());
    add(litScene(d).ambientLight.kA());
    for (const LightSource& l : litScene(d).lights) {
      label("light");
      std::visit([this](const auto& light) { addLight(light); }, l);
    }
    for (const auto& [name, m] : namedMaterials(d).materials) {
      label("material " + name);
      add(m);
    }
    for (std::uint32_t i = 0; i < litScene(d).geometries.size(); ++i) {
      label("geometry " + std::to_string(i));
      std::visit([this](const auto& g) { addShape(g); }, litScene(d).geometries[i]);
      add(litScene(d).appearanceOf(i).emission.rgb());
      add(litScene(d).appearanceOf(i).material);
      if (const std::string* name = d.geometryName(i)) label("name " + *name);
      if (const std::string* material = materialNameOf(d, i)) label("uses " + *material);
    }
    for (std::uint32_t k = 0; k < litScene(d).geometries.meshes().size(); ++k) {
      label("mesh " + std::to_string(k));
      addMesh(*litScene(d).geometries.meshes()[k].mesh);
      const std::uint32_t row = litScene(d).meshAppearance[k];
      add(litScene(d).appearances[row].emission.rgb());
      add(litScene(d).appearances[row].material);
      if (const std::string* name = meshName(d, k)) label("name " + *name);
      if (const std::string* material = materialNameOfRow(d, row)) label("uses " + *material);
    }
  }

  const std::string& str() const { return text_; }

 private:
  void label(const std::string& s) { text_ += "\n" + s + ":"; }
  void add(double v) {
    char buf[20];
    std::snprintf(buf, sizeof buf, " %016llx",
                  static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(v)));
    text_ += buf;
  }
  void add(int v) { text_ += " " + std::to_string(v); }
  void add(double a, double b, double c) {
    add(a);
    add(b);
    add(c);
  }
  void add(const Double3& v) { add(v.x, v.y, v.z); }
  void add(const Material& m) {
    add(m.kD);
    add(m.kS);
    add(m.kT);
    add(m.kR);
    add(m.shininess);
    add(m.ior);
  }
  void addLight(const DirectionalLight& l) {
    add(l.intensity.rgb());
    add(l.direction.xyz());
  }
  void addLight(const PointLight& l) {
    add(l.intensity.rgb());
    add(l.position.xyz());
    add(l.kC, l.kL, l.kQ);
  }
  void addLight(const SpotLight& l) {
    addLight(static_cast<const PointLight&>(l));
    add(l.direction.xyz());
    add(l.narrowBeam);
  }
  void addMesh(const TriangleMesh& m) {
    label("vertices");
    for (const Point& v : m.vertices()) add(v.xyz());
    label("triangles");
    for (const TriangleMesh::Indices& t : m.triangles())
      for (std::uint32_t i : t) add(static_cast<int>(i));
    label("normals");
    for (const Vector& n : m.normals()) add(n.xyz());
  }
  void addShape(const Sphere& s) {
    label("sphere");
    add(s.center().xyz());
    add(s.radius());
  }
  void addShape(const Plane& p) {
    label("plane");
    add(p.point().xyz());
    add(p.normal().xyz());
  }
  void addShape(const Triangle& t) {
    label("triangle");
    for (const Point& v : t.vertices()) add(v.xyz());
    add(t.plane().normal().xyz());
  }
  void addShape(const Polygon& p) {
    label("polygon");
    for (const Point& v : p.vertices()) add(v.xyz());
    add(p.plane().normal().xyz());
  }
  void addShape(const Tube& t) {
    label("tube");
    add(t.radius());
    add(t.axis().head().xyz());
    add(t.axis().direction().xyz());
  }
  void addShape(const Cylinder& c) {
    label("cylinder");
    add(c.radius());
    add(c.height());
    add(c.axis().head().xyz());
    add(c.axis().direction().xyz());
  }

  std::string text_;
};

}  // namespace rt::testing
