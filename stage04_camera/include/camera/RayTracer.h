#pragma once
/// @file RayTracer.h
/// The tracer family: ambient (this stage) -> Phong (stage 5) -> shadows (stage 6) ->
/// Whitted (stage 7) -> beams (mini project 1). Each stage adds a tracer class on top of the
/// one below, so one scene can be rendered by any of them and compared.

#include "camera/SampleContext.h"
#include "camera/Scene.h"
#include "intersections/Intersectable.h"
#include "primitives/Color.h"
#include "primitives/Ray.h"

namespace rt {

class RayTracer {
 public:
  /// @param scene must outlive the tracer.
  /// @param accelerator what to intersect instead of scene.geometries (a BVH built over the same
  ///        shapes, so the same indices); nullptr means scene.geometries. Must outlive the tracer.
  explicit RayTracer(const Scene& scene, const Intersectable* accelerator = nullptr)
      : scene_(scene), intersector_(accelerator ? *accelerator : scene.geometries) {}
  virtual ~RayTracer() = default;
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  /// The colour seen along the ray, for the sample ctx describes: its random numbers come from
  /// ctx.random, the rays it casts beyond this one are counted in ctx.counts (the caller counts
  /// this one). Must not allocate, must not throw, and must be safe to call from several
  /// threads at once, each with its own context.
  virtual Color traceRay(const Ray& ray, SampleContext& ctx) const = 0;

  /// The course's traceRay(ray): the sample of pixel (0, 0), index 0, seed 0, counted nowhere.
  /// (A derived tracer says `using RayTracer::traceRay;` to keep this form visible.)
  Color traceRay(const Ray& ray) const;

  const Scene& scene() const { return scene_; }
  const Intersectable& intersector() const { return intersector_; }

 protected:
  const Scene& scene_;
  const Intersectable& intersector_;
};

/// The course's SimpleRayTracer of stage 5: the ambient light's intensity where the ray hits a
/// shape, the background where it misses.
class AmbientTracer : public RayTracer {
 public:
  using RayTracer::RayTracer;
  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override;
};

}  // namespace rt
