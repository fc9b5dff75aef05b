#include "shadows/RayOffset.h"

#include "primitives/Checks.h"

namespace rt {

RayOffset RayOffset::scaled(double relative) {
  requirePositive(relative, "RayOffset::scaled", "relative");
  return RayOffset(true, relative);
}

RayOffset RayOffset::fixed(double delta) {
  requirePositive(delta, "RayOffset::fixed", "delta");
  return RayOffset(false, delta);
}

}  // namespace rt
