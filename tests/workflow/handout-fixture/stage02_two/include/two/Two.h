#pragma once
/// @file Two.h

#include <vector>

namespace fixture {

template <typename F>
int countIf(const std::vector<int>& values, F&& keep) {
  // BEGIN SOLUTION: hint: countIf, the values keep accepts
  int n = 0;
  for (int v : values) n += keep(v) ? 1 : 0;
  return n;
  // END SOLUTION
}

}  // namespace fixture
