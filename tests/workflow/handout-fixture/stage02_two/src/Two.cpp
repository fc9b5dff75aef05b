#include "two/Two.h"

namespace fixture {

int checked(int x) {
  // BEGIN SOLUTION: todo: checked, throw std::invalid_argument for a negative x
  if (x < 0) throw x;
  // END SOLUTION
  return x;
}

int plain(int x) noexcept {
  // BEGIN SOLUTION
  return x + 1;
  // END SOLUTION
}

int quoted(int x) {
  // BEGIN SOLUTION: hint: quoted, a "quote" and a \backslash
  return x;
  // END SOLUTION
}

int longHint(int x) {
  // BEGIN SOLUTION: hint: longHint, a hint long enough to need a second line for the stub
  return x;
  // END SOLUTION
}

}  // namespace fixture
