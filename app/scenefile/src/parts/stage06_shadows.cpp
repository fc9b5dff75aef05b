// The scene format's stage-6 part: no key of its own (a material's kT is stage 5's data), only
// the shadow tracer.
#include "../Format.h"

namespace rt::scenefile {

void registerFormat_stage06_shadows(SceneFormat& format) { format.addTracer("shadow"); }

}  // namespace rt::scenefile
