#pragma once
/// @file TileGrid.h
/// An image cut into square tiles, numbered in the order a tile pool hands them out.
///
/// The order keeps consecutive tiles close together in the image, so the tiles rendered at the
/// same moment (by the pool's threads, one after the other by one thread) see nearby parts of
/// the scene and share the BVH nodes and shapes in the caches. Tile rows are grouped in bands
/// of BAND tiles; a band is walked column by column, each column top to bottom:
///
///        column:   0    1    2    3    4
///               +----+----+----+----+----+
///     band 0    |  0 |  4 |  8 | 12 | 16 |     tile rows 0..3
///               |  1 |  5 |  9 | 13 | 17 |
///               |  2 |  6 | 10 | 14 | 18 |
///               |  3 |  7 | 11 | 15 | 19 |
///               +----+----+----+----+----+
///     band 1    | 20 | 22 | 24 | 26 | 28 |     the last band may be lower (here 2 rows)
///               | 21 | 23 | 25 | 27 | 29 |
///               +----+----+----+----+----+
///
/// Any 8 consecutive tiles form a block of about 2 × 4 tiles (row after row, they would form a
/// strip of 8 × 1), and index → tile is a closed formula: nothing is stored per tile, so any
/// image and tile size costs the same. The tiles of the right column and the bottom row are
/// cut to the image.

#include <cstdint>

#include "camera/RenderBlock.h"

namespace rt {

class TileGrid {
 public:
  /// Tile rows per band.
  static constexpr int BAND = 4;

  /// @throws std::invalid_argument unless nX, nY >= 1 and tileSize >= 1, naming the value.
  TileGrid(int nX, int nY, int tileSize);

  /// How many tiles: ⌈nX / tileSize⌉ · ⌈nY / tileSize⌉.
  std::uint64_t size() const noexcept {
    return static_cast<std::uint64_t>(columns_) * static_cast<std::uint64_t>(rows_);
  }
  /// Tile `index` (0 <= index < size()) in the pool's order: a square of tileSize pixels, or
  /// less at the right and bottom edges.
  PixelBlock tile(std::uint64_t index) const noexcept;

  int tileSize() const noexcept { return tileSize_; }
  /// Tiles per row and per column of the image.
  int columns() const noexcept { return columns_; }
  int rows() const noexcept { return rows_; }

 private:
  int nX_, nY_, tileSize_, columns_, rows_;
};

}  // namespace rt
