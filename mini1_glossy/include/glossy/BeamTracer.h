#pragma once
/// @file BeamTracer.h
/// The first mini project's tracer: the Whitted tracer whose glossy surfaces and diffused glass
/// cast beams of secondary rays, and whose lights with a size cast soft shadows.

#include <cstdint>
#include <optional>
#include <vector>

#include "glossy/RayBeam.h"
#include "lighting/LitScene.h"
#include "reflections/WhittedTracer.h"

namespace rt {

/// Where beams are cast.
enum class BeamDepth {
  FirstBounce,  ///< only from the primary hit (the reference report's choice, and the default)
  EveryBounce,  ///< from every hit of the recursion
};

/// The beam tracer's own settings.
struct BeamTracerSettings {
  BeamDepth beamDepth = BeamDepth::FirstBounce;
  /// Trace a beam's rays together (Intersectable::closestHits: the wide BVH's packets) where
  /// that gives the image of tracing them one by one; false: always one by one. The same bytes
  /// either way (secondaryColor below says why); only the speed and the query counts differ.
  bool together = true;
};

/// WhittedTracer plus ray beams and soft shadows (tracer `beams`).
///
///   secondary ray of a material with a beam  →  the average of the beam's rays' colours
///   (Material::reflectedBeam/refractedBeam)     (RayBeam.h), each one the Whitted tracer's
///   light with a size (PointLight::radius r,  →  the transmittance averaged over S shadow rays
///   shadowSamples S)                            to points of the disk of radius r centred on
///                                               the light and facing the shaded point
///
/// The light's intensity and direction (the Phong terms) stay those of its centre: only its
/// visibility is sampled, which is what makes a shadow soft. The disk's S points are a
/// Fibonacci lattice over the unit square (point k at ((k + ½)/S, frac(k·φ⁻¹))), shifted by one
/// random offset per shading point (a Cranley–Patterson rotation: every point uniform, the set
/// evenly spread for any S), mapped to the disk by the concentric mapping.
///
/// Every random number comes from the sample context: the image is a pure function of the scene,
/// the settings and the seed.
///
/// A beam's rays traced together. One by one, each ray's jitter is drawn, the ray traced and
/// shaded, then the next ray's jitter drawn: the shading of a ray could draw numbers (a beam
/// deeper down, a soft shadow) between two jitters. Together, every jitter is drawn first, the
/// rays' closest hits found at once, then each ray shaded in order. That is the same arithmetic
/// exactly when no shading draws a number, and the tracer checks it rather than assumes it:
///
///     start = the stream, before = the counts
///     draw every jitter (the beam's rays)  →  drawn = the stream
///     closestHits(rays)                       (a closest hit depends on its ray alone)
///     for each ray, in order: shade it; the stream is no longer drawn?  →  stream = start,
///                             counts = before, and the beam one by one after all
///
/// Each ray is then shaded with the same hit and the same (untouched) numbers as one by one, and
/// the colours are summed in the same order: the same bits. The tracer tries it only where no
/// shading is expected to draw (beams at the first bounce only, no light with a size) and for
/// beams of at most TOGETHER_GRID² cells (their rays and hits live on the stack).
class BeamTracer : public WhittedTracer {
 public:
  /// @param scene must outlive the tracer.
  /// @throws what scene.validate() throws; std::invalid_argument for invalid settings.
  explicit BeamTracer(const LitScene& scene, const Intersectable* accelerator = nullptr,
                      const WhittedSettings& whitted = {}, const BeamTracerSettings& beams = {},
                      const RayOffset& offset = RayOffset{});

  const BeamTracerSettings& beamSettings() const { return beams_; }

 protected:
  /// A beam instead of one ray when the material blurs this kind of ray and the depth setting
  /// allows one here; else the Whitted tracer's one ray.
  Color secondaryColor(const HitContext& from, const Ray& secondary, SecondaryKind kind, int level,
                       const Double3& kkx, SampleContext& ctx) const override;

  /// Soft shadows for a light with a size; else the shadow tracer's one shadow ray.
  Double3 transmittance(const HitContext& h, std::uint32_t light, const LightSample& sample,
                        const Double3& k, SampleContext& ctx) const override;

 public:
  /// The largest grid whose beams are traced together (TOGETHER_GRID² = 144 rays at most).
  static constexpr int TOGETHER_GRID = 12;

 private:
  /// The beam's colour with its rays traced together, or nullopt when a shading drew numbers
  /// (then ctx is as it was on entry) or together_ is false or the grid is too large.
  std::optional<Color> beamTogether(const HitContext& from, const Ray& secondary,
                                    const BeamSettings& beam, int level, const Double3& kkx,
                                    SampleContext& ctx) const;

  /// A light's disk, computed once per light: radius 0 or one sample is a point.
  struct LightDisk {
    Point centre = Point::ZERO;
    double radius = 0;
    int samples = 1;
    bool isArea() const noexcept { return radius > 0 && samples > 1; }
  };

  BeamTracerSettings beams_;
  std::vector<LightDisk> disks_;  ///< per light
  /// beams_.together, beams at the first bounce only, and no light with a size (computed once).
  bool together_ = false;
};

}  // namespace rt
