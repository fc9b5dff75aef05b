#include "bvh/FloatBox.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

FloatBox FloatBox::enclosing(const Aabb& b) noexcept {
  return FloatBox{{floatBelow(b.lo.x), floatBelow(b.lo.y), floatBelow(b.lo.z)},
                  {floatAbove(b.hi.x), floatAbove(b.hi.y), floatAbove(b.hi.z)}};
}

FloatBox conservativeBox(const Aabb& exact) noexcept {
  const double size = std::max({std::abs(exact.lo.x), std::abs(exact.lo.y), std::abs(exact.lo.z),
                                std::abs(exact.hi.x), std::abs(exact.hi.y), std::abs(exact.hi.z)});
  const Double3 margin(BOX_MARGIN * size);
  return FloatBox::enclosing(Aabb(exact.lo - margin, exact.hi + margin));
}

}  // namespace rt
