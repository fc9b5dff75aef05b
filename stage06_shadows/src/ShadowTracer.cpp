#include "shadows/ShadowTracer.h"

namespace rt {

ShadowTracer::ShadowTracer(const LitScene& scene, const Intersectable* accelerator,
                           const RayOffset& offset)
    : PhongTracer(scene, accelerator),
      offset_(offset),
      shadows_(intersector_, scene, MIN_CALC_COLOR_K) {}

}  // namespace rt
