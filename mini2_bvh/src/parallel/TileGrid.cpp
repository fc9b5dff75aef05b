#include "parallel/TileGrid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

int checkedTileSize(int nX, int nY, int tileSize) {
  if (nX < 1 || nY < 1)
    throw std::invalid_argument("TileGrid: the image is " + std::to_string(nX) + "x" +
                                std::to_string(nY) + ", expected at least 1x1");
  if (tileSize < 1)
    throw std::invalid_argument("TileGrid: tileSize is " + std::to_string(tileSize) +
                                ", expected 1 or more");
  return tileSize;
}

/// ⌈n / d⌉ for n >= 1, d >= 1, without the overflow of n + d - 1.
int ceilDiv(int n, int d) { return n / d + (n % d != 0 ? 1 : 0); }

}  // namespace

TileGrid::TileGrid(int nX, int nY, int tileSize)
    : nX_(nX),
      nY_(nY),
      tileSize_(checkedTileSize(nX, nY, tileSize)),
      columns_(ceilDiv(nX, tileSize)),
      rows_(ceilDiv(nY, tileSize)) {}

PixelBlock TileGrid::tile(std::uint64_t index) const noexcept {
  // BEGIN SOLUTION: hint: TileGrid::tile, band by band, column by column, cut to the image
  // Every band before this one is full: BAND rows of `columns_` tiles.
  const std::uint64_t bandTiles = static_cast<std::uint64_t>(BAND) * columns_;
  const auto band = static_cast<int>(index / bandTiles);
  const auto inBand = static_cast<int>(index % bandTiles);
  const int height = std::min(BAND, rows_ - band * BAND);  // the last band may be lower
  const int column = inBand / height, row = band * BAND + inBand % height;
  const int x0 = column * tileSize_, y0 = row * tileSize_;
  // x0 + tileSize_ may exceed INT_MAX for a huge tile size: cut to the image before adding.
  return PixelBlock{x0, y0, x0 + std::min(tileSize_, nX_ - x0), y0 + std::min(tileSize_, nY_ - y0)};
  // END SOLUTION
}

}  // namespace rt
