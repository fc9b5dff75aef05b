#include "bvh/FloatBox.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

constexpr float FLOAT_MAX = std::numeric_limits<float>::max();
constexpr float FLOAT_INF = std::numeric_limits<float>::infinity();

/// The largest float <= x. (A double beyond the float range must not be cast: undefined.)
float floatBelow(double x) noexcept {
  if (x >= FLOAT_MAX) return FLOAT_MAX;
  if (x < -FLOAT_MAX) return -FLOAT_INF;
  const float f = static_cast<float>(x);  // round to nearest: may land above x
  return f > x ? std::nextafter(f, -FLOAT_INF) : f;
}

/// The smallest float >= x.
float floatAbove(double x) noexcept { return -floatBelow(-x); }

}  // namespace

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
