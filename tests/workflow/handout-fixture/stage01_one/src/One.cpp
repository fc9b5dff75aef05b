#include <cmath>
#include <string>

namespace fixture {

double twice(double x) {
  // BEGIN SOLUTION: hint: twice, 2x
  return 2 * x;
  // END SOLUTION
}

double root(double x) {
  // BEGIN SOLUTION: hint: root, the square root
  if (x < 0) return 0;
  return std::sqrt(x);
  // END SOLUTION
}

}  // namespace fixture
