#include "camera/RayTracer.h"

namespace rt {

// The course's SimpleRayTracer: only whether the ray hits something matters, so the closest-hit
// query is enough (and it allocates nothing).
Color AmbientTracer::traceRay(const Ray& ray) const {
  return intersector_.closestHit(ray) ? scene_.ambientLight.intensity() : scene_.background;
}

}  // namespace rt
