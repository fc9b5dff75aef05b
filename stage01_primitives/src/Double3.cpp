#include "primitives/Double3.h"

#include <charconv>
#include <cmath>
#include <ostream>

#include "primitives/Util.h"

namespace rt {

const Double3 Double3::ZERO{0, 0, 0};
const Double3 Double3::ONE{1, 1, 1};

bool Double3::isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }

bool Double3::operator==(const Double3& o) const { return (*this - o).isZero(); }

std::string formatNumber(double v) {
  char buf[32];
  if (v == 0) v = 0;  // print -0 as 0
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc{}) return "?";
  return std::string(buf, end);
}

std::string Double3::str() const {
  std::string s(1, '(');  // appended piece by piece (GCC 12 warns falsely on "(" + string)
  s.append(formatNumber(x)).append(1, ',').append(formatNumber(y)).append(1, ',');
  s.append(formatNumber(z)).append(1, ')');
  return s;
}

std::ostream& operator<<(std::ostream& os, const Double3& v) { return os << v.str(); }

}  // namespace rt
