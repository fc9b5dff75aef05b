#include "glossy/RayBeam.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "primitives/Checks.h"

namespace rt {

void BeamSettings::validate(const char* what) const {
  requirePositive(distance, what, "distance");
  if (!(std::isfinite(radius) && radius >= 0)) {
    throw std::invalid_argument(std::string(what) +
                                ": radius must be a non-negative finite number, got " +
                                formatNumber(radius));
  }
  if (grid < 1 || grid > MAX_GRID) {
    throw std::invalid_argument(std::string(what) + ": grid must be between 1 and " +
                                std::to_string(MAX_GRID) + ", got " + std::to_string(grid));
  }
}

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
