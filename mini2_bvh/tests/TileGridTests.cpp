// mini2: the tiles of the pool. Every pixel lies in exactly one tile, tiles are squares cut to
// the image, and they are numbered band by band, column by column (TileGrid.h's picture).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <climits>
#include <stdexcept>
#include <vector>

#include "parallel/TileGrid.h"

namespace rt {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// Every pixel is covered by exactly one tile, and every tile is a non-empty block of at most
/// tileSize × tileSize pixels inside the image.
void expectPartition(int nX, int nY, int tileSize) {
  const TileGrid grid(nX, nY, tileSize);
  std::vector<int> covered(static_cast<std::size_t>(nX) * nY, 0);
  for (std::uint64_t i = 0; i < grid.size(); ++i) {
    const PixelBlock b = grid.tile(i);
    ASSERT_TRUE(b.x0 >= 0 && b.y0 >= 0 && b.x1 <= nX && b.y1 <= nY) << i;
    ASSERT_TRUE(b.x0 < b.x1 && b.y0 < b.y1) << i;
    ASSERT_LE(b.x1 - b.x0, tileSize);
    ASSERT_LE(b.y1 - b.y0, tileSize);
    ASSERT_EQ(b.x0 % tileSize, 0);
    ASSERT_EQ(b.y0 % tileSize, 0);
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x) ++covered[static_cast<std::size_t>(y) * nX + x];
  }
  for (std::size_t p = 0; p < covered.size(); ++p)
    ASSERT_EQ(covered[p], 1) << "pixel " << p % nX << "," << p / nX << " of " << nX << "x" << nY
                             << " in tiles of " << tileSize;
}

TEST(TileGridTests, partition) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: sides multiples of the tile size (4 x 4 tiles: one full band)
  expectPartition(64, 64, 16);
  // TC02: sides not multiples of the tile size, and a last band lower than BAND (7 tile rows)
  expectPartition(100, 61, 9);
  // TC03: a wide and a tall image
  expectPartition(300, 7, 4);
  expectPartition(7, 300, 4);
  // =============== Boundary Values Tests ==================
  // TC11: tiles of one pixel
  expectPartition(13, 11, 1);
  // TC12: a 1 x 1 image
  expectPartition(1, 1, 32);
  // TC13: a tile larger than the image: one tile, the whole image
  expectPartition(20, 10, 1000);
}

TEST(TileGridTests, sizeAndOrder) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the header's picture: 5 columns, 6 rows of tiles; band 0 walked column by column
  // (4 tiles each), then band 1, 2 rows high
  const TileGrid grid(50, 60, 10);
  EXPECT_EQ(grid.columns(), 5);
  EXPECT_EQ(grid.rows(), 6);
  EXPECT_EQ(grid.size(), 30u);
  EXPECT_EQ(grid.tile(0), (PixelBlock{0, 0, 10, 10}));
  EXPECT_EQ(grid.tile(3), (PixelBlock{0, 30, 10, 40}));
  EXPECT_EQ(grid.tile(4), (PixelBlock{10, 0, 20, 10}));
  EXPECT_EQ(grid.tile(19), (PixelBlock{40, 30, 50, 40}));
  EXPECT_EQ(grid.tile(20), (PixelBlock{0, 40, 10, 50}));
  EXPECT_EQ(grid.tile(21), (PixelBlock{0, 50, 10, 60}));
  EXPECT_EQ(grid.tile(22), (PixelBlock{10, 40, 20, 50}));
  EXPECT_EQ(grid.tile(29), (PixelBlock{40, 50, 50, 60}));
  // TC02: consecutive tiles of a band share an edge, or start the next column at the band's top
  for (std::uint64_t i = 0; i + 1 < 20; ++i) {
    const PixelBlock a = grid.tile(i), b = grid.tile(i + 1);
    EXPECT_TRUE((a.x0 == b.x0 && a.y1 == b.y0) || (a.x1 == b.x0 && b.y0 == 0)) << i;
  }
  // TC03: the right column and the bottom row are cut to the image
  const TileGrid cut(25, 13, 10);
  EXPECT_EQ(cut.size(), 6u);
  EXPECT_EQ(cut.tile(1), (PixelBlock{0, 10, 10, 13}));
  EXPECT_EQ(cut.tile(5), (PixelBlock{20, 10, 25, 13}));
  // =============== Boundary Values Tests ==================
  // TC11: a tile size of INT_MAX: one tile, with no overflow in its corners
  const TileGrid huge(7, 5, INT_MAX);
  EXPECT_EQ(huge.size(), 1u);
  EXPECT_EQ(huge.tile(0), (PixelBlock{0, 0, 7, 5}));
  // TC12: the largest image in tiles of one pixel: 2^30 tiles, the last one in the corner
  const TileGrid largest(1 << 15, 1 << 15, 1);
  EXPECT_EQ(largest.size(), std::uint64_t{1} << 30);
  EXPECT_EQ(largest.tile(largest.size() - 1),
            (PixelBlock{(1 << 15) - 1, (1 << 15) - 1, 1 << 15, 1 << 15}));
}

TEST(TileGridTests, invalidArguments) {
  // =============== Boundary Values Tests ==================
  // TC11: tile size 0 and -3 are refused, naming the value
  EXPECT_THAT([] { TileGrid(10, 10, 0); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("tileSize is 0")));
  EXPECT_THAT([] { TileGrid(10, 10, -3); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("tileSize is -3")));
  // TC12: an empty image is refused, naming its size
  EXPECT_THAT([] { TileGrid(0, 10, 8); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("the image is 0x10")));
}

}  // namespace
}  // namespace rt
