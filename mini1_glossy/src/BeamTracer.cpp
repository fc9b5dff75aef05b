#include "glossy/BeamTracer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <new>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <variant>

#include "glossy/Frame.h"
#include "primitives/Overloaded.h"

namespace rt {

BeamTracer::BeamTracer(const LitScene& scene, const Intersectable* accelerator,
                       const WhittedSettings& whitted, const BeamTracerSettings& beams,
                       const RayOffset& offset)
    : WhittedTracer(scene, accelerator, whitted, offset), beams_(beams) {
  // The materials' beams and the lights' sizes were validated with the scene (PhongTracer).
  disks_.reserve(scene.lights.size());
  for (const LightSource& light : scene.lights) {
    disks_.push_back(
        std::visit(Overloaded{[](const DirectionalLight&) { return LightDisk{}; },
                              [](const PointLight& l) {
                                return LightDisk{l.position, l.radius, l.shadowSamples};
                              }},
                   light));
  }
  together_ =
      beams_.together && beams_.beamDepth == BeamDepth::FirstBounce &&
      std::none_of(disks_.begin(), disks_.end(), [](const LightDisk& d) { return d.isArea(); });
}

Color BeamTracer::secondaryColor(const HitContext& from, const Ray& secondary, SecondaryKind kind,
                                 int level, const Double3& kkx, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: BeamTracer::secondaryColor, the mean colour of the beam's rays
  const Material& m = from.appearance->material;
  const BeamSettings& beam = kind == SecondaryKind::Reflected ? m.reflectedBeam : m.refractedBeam;
  const bool here = beams_.beamDepth == BeamDepth::EveryBounce || level == settings_.maxLevel;
  if (!here || !beam.isBeam())
    return WhittedTracer::secondaryColor(from, secondary, kind, level, kkx, ctx);
  // Every ray of the beam leaves from the secondary ray's origin (already shifted to the side
  // the beam goes to: samples on the other side are dropped) and is traced as the Whitted
  // tracer traces one.
  if (const std::optional<Color> together = beamTogether(from, secondary, beam, level, kkx, ctx))
    return *together;
  Double3 sum;
  const int count =
      forEachBeamRay(secondary.direction(), from.normal, beam, ctx.random, [&](const Vector& dir) {
        const Color c = WhittedTracer::secondaryColor(
            from, Ray::withUnitDirection(secondary.head(), dir), kind, level, kkx, ctx);
        sum = sum + c.rgb();
      });
  return Color::unchecked(sum / count);
  // END SOLUTION
}

std::optional<Color> BeamTracer::beamTogether(const HitContext& from, const Ray& secondary,
                                              const BeamSettings& beam, int level,
                                              const Double3& kkx, SampleContext& ctx) const {
  constexpr int MOST = TOGETHER_GRID * TOGETHER_GRID;  // a beam's rays: at most its cells
  if (!together_ || beam.grid > TOGETHER_GRID) return std::nullopt;
  const RandomStream start = ctx.random;
  const RayCounts before = ctx.counts;
  // Ray has no default constructor: the beam's rays are made in place in raw storage (a Ray is
  // trivially destructible, so nothing is to be destroyed).
  alignas(Ray) std::byte storage[sizeof(Ray) * MOST];
  Ray* const rays = reinterpret_cast<Ray*>(storage);
  int n = 0;
  const int count =
      forEachBeamRay(secondary.direction(), from.normal, beam, ctx.random, [&](const Vector& dir) {
        ::new (static_cast<void*>(rays + n++)) Ray(Ray::withUnitDirection(secondary.head(), dir));
      });
  const std::span<const Ray> beamRays(std::launder(rays), static_cast<std::size_t>(n));
  std::array<std::optional<Hit>, MOST> hits;
  const std::span<std::optional<Hit>> beamHits = std::span(hits).first(beamRays.size());
  intersector_.closestHits(beamRays, INFINITE_DISTANCE, beamHits, &ctx.counts.queries);
  const RandomStream drawn = ctx.random;
  Double3 sum;
  for (std::size_t i = 0; i < beamRays.size(); ++i) {
    sum = sum + secondaryHitColor(beamRays[i], beamHits[i], level, kkx, ctx).rgb();
    if (!(ctx.random == drawn)) {  // this shading drew numbers: one by one would differ
      ctx.random = start;
      ctx.counts = before;
      return std::nullopt;
    }
  }
  return Color::unchecked(sum / count);
}

Double3 BeamTracer::transmittance(const HitContext& h, std::uint32_t lightIndex,
                                  const LightSample& sample, const Double3& k,
                                  SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: BeamTracer::transmittance, the mean over the light's disk
  const LightDisk& light = disks_[lightIndex];
  if (!light.isArea()) return ShadowTracer::transmittance(h, lightIndex, sample, k, ctx);
  // The disk faces the shaded point: its plane is orthogonal to l (light → point).
  const Frame disk = Frame::around(sample.l.xyz());
  const Double3& centre = light.centre.xyz();
  const Sample2 shift = ctx.random.next2D();
  const int n = light.samples;
  Double3 sum;
  for (int s = 0; s < n; ++s) {
    const Sample2 d = diskLatticePoint(s, n, shift);
    const Double3 onDisk = centre + disk.inPlane(d.u * light.radius, d.v * light.radius);
    const Double3 toLight = onDisk - h.point.xyz();
    const double distance = std::sqrt(toLight.lengthSquared());
    // A disk point at the shaded point itself (a light touching a surface) lights it fully.
    if (!(distance > 0)) {
      sum = sum + Double3::ONE;
      continue;
    }
    sum = sum + shadowQuery(h.point, h.normal, Vector::unchecked(toLight / distance), distance, k,
                            ctx.counts)
                    .factor;
  }
  return sum / n;
  // END SOLUTION
}

}  // namespace rt
