#include "glossy/RayBeam.h"

namespace rt {

int beamCellCount(int grid) noexcept {
  // BEGIN SOLUTION: hint: beamCellCount, the cells whose centre is inside (cellInBeam)
  if (grid <= 1) return 1;
  int count = 0;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) count += cellInBeam(i, j, grid) ? 1 : 0;
  return count;
  // END SOLUTION
}

}  // namespace rt
