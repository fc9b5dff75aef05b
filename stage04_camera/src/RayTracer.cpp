#include "camera/RayTracer.h"

namespace rt {

Color RayTracer::traceRay(const Ray& ray) const {
  RayCounts uncounted;
  SampleContext ctx(0, 0, 0, 0, uncounted);
  return traceRay(ray, ctx);
}

// The course's SimpleRayTracer: only whether the ray hits something matters, so the closest-hit
// query is enough (and it allocates nothing).
Color AmbientTracer::traceRay(const Ray& ray, SampleContext& ctx) const {
  // BEGIN SOLUTION: hint: AmbientTracer, the ambient light on a hit, else the background
  return intersector_.closestHit(ray, INFINITE_DISTANCE, &ctx.counts.queries)
             ? scene_.ambientLight.intensity()
             : scene_.background;
  // END SOLUTION
}

}  // namespace rt
