#include "glossy/BeamTracer.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <variant>

#include "glossy/Frame.h"
#include "primitives/Overloaded.h"

namespace rt {

namespace {

/// The golden ratio's conjugate φ⁻¹ = (√5 − 1)/2: the lattice's second coordinate steps by it.
constexpr double INV_PHI = 0.6180339887498949;

/// x − floor(x) for x >= 0.
double fraction(double x) noexcept { return x - std::floor(x); }

}  // namespace

BeamTracer::BeamTracer(const GlossyScene& scene, const Intersectable* accelerator,
                       const WhittedSettings& whitted, const BeamTracerSettings& beams,
                       const RayOffset& offset)
    : WhittedTracer(scene, accelerator, whitted, offset), glossy_(scene), beams_(beams) {
  scene.validate();  // the blurs and light sizes too; LitScene's part was checked by PhongTracer
  blurOfRow_.reserve(scene.appearances.size());
  for (std::uint32_t row = 0; row < scene.appearances.size(); ++row)
    blurOfRow_.push_back(scene.blurOfRow(row));
  for (std::uint32_t i = 0; i < scene.lights.size(); ++i) {
    sizeOfLight_.push_back(scene.sizeOfLight(i));
    centreOfLight_.push_back(
        std::visit(Overloaded{[](const DirectionalLight&) { return Point::ZERO; },
                              [](const PointLight& l) { return l.position; },
                              [](const SpotLight& l) { return l.position; }},
                   scene.lights[i]));
  }
}

Color BeamTracer::secondaryColor(const HitContext& from, const Ray& secondary, SecondaryKind kind,
                                 int level, const Double3& kkx, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: BeamTracer::secondaryColor, the mean colour of the beam's rays
  const Blur& blur = blurOfRow_[from.appearanceRow];
  const BeamSettings& beam = kind == SecondaryKind::Reflected ? blur.reflected : blur.refracted;
  const bool here = beams_.beamDepth == BeamDepth::EveryBounce || level == settings_.maxLevel;
  if (!here || !beam.isBeam())
    return WhittedTracer::secondaryColor(from, secondary, kind, level, kkx, ctx);
  // Every ray of the beam leaves from the secondary ray's origin (already shifted to the side
  // the beam goes to: samples on the other side are dropped) and is traced as the Whitted
  // tracer traces one.
  Double3 sum;
  const int count =
      forEachBeamRay(secondary.direction(), from.normal, beam, ctx.random, [&](const Vector& dir) {
        const Color c =
            WhittedTracer::secondaryColor(from, Ray(secondary.head(), dir), kind, level, kkx, ctx);
        sum = sum + c.rgb();
      });
  return Color::unchecked(sum / count);
  // END SOLUTION
}

Double3 BeamTracer::transmittance(const HitContext& h, std::uint32_t light,
                                  const LightSample& sample, const Double3& k,
                                  SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: BeamTracer::transmittance, the mean over the light's disk
  const LightSize& size = sizeOfLight_[light];
  if (!size.isArea()) return ShadowTracer::transmittance(h, light, sample, k, ctx);
  // The disk faces the shaded point: its plane is orthogonal to l (light → point).
  const Frame disk = Frame::around(sample.l.xyz());
  const Double3& centre = centreOfLight_[light].xyz();
  const Sample2 shift = ctx.random.next2D();
  const int n = size.samples;
  Double3 sum;
  for (int s = 0; s < n; ++s) {
    const Sample2 unit{fraction((s + 0.5) / n + shift.u), fraction(s * INV_PHI + shift.v)};
    const Sample2 d = squareToDisk(unit);
    const Double3 onDisk = centre + disk.inPlane(d.u * size.radius, d.v * size.radius);
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
