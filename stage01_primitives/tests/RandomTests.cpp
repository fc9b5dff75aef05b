// The counter-based random source: a pure function of (seed, x, y, sample, dimension), uniform,
// without correlation between neighbouring dimensions or pixels, and without allocation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "primitives/Random.h"
#include "support/AllocationCounter.h"

namespace rt {
namespace {

/// Pearson's χ² statistic of counts against a uniform expectation.
double chiSquare(const std::vector<long>& counts, double expected) {
  double chi2 = 0;
  for (long c : counts) {
    const double diff = static_cast<double>(c) - expected;
    chi2 += diff * diff / expected;
  }
  return chi2;
}

/// Pearson's correlation coefficient of the pairs (a[i], b[i]).
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= n;
  mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

// χ² thresholds: with 100 bins there are 99 degrees of freedom, and a truly uniform source gives
// χ² > 148.2 with probability 0.001 (the 99.9th percentile of the χ²(99) distribution). The seeds
// are fixed, so each test is deterministic: it passes or fails the same way every run, and a
// failure means the generator is off, not that the run was unlucky.
constexpr int BINS = 100;
constexpr double CHI2_99_AT_0_001 = 148.2;

// Correlation thresholds: for n independent pairs, r is approximately normal with standard
// deviation 1/√n; |r| < 4/√n holds with probability 0.99994 for an uncorrelated source.
double correlationBound(std::size_t n) { return 4 / std::sqrt(static_cast<double>(n)); }

TEST(RandomTests, mix64) {
  // TC01: SplitMix64's published first output for the seed 0 (state 0 + γ)
  EXPECT_EQ(0xe220a8397b1dcdafULL, mix64(RandomStream::GAMMA));
  // TC11: 0 is a fixed point of the finaliser (why the stream adds γ before mixing)
  EXPECT_EQ(0u, mix64(0));
}

TEST(RandomTests, sameCoordinatesSameNumbers) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: two streams made from the same coordinates give the same numbers, dimension by
  // dimension, and next() reads the same numbers as uniform()
  RandomStream a(42, 17, 99, 3), b(42, 17, 99, 3);
  for (std::uint32_t d = 0; d < 64; ++d) {
    EXPECT_EQ(a.uniform(d), b.uniform(d)) << d;
    EXPECT_EQ(a.uniform(d), b.next()) << d;
  }
  EXPECT_EQ(64u, b.dimension());
  // TC02: uniform() is pure: reading a dimension twice gives the same number
  EXPECT_EQ(a.uniform(5), a.uniform(5));
  // =============== Boundary Values Tests ==================
  // TC11: setDimension rewinds the cursor; next2D reads two consecutive dimensions
  b.setDimension(10);
  const Sample2 s = b.next2D();
  EXPECT_EQ(a.uniform(10), s.u);
  EXPECT_EQ(a.uniform(11), s.v);
  // TC12: the default stream is the one of (0, 0, 0, 0)
  EXPECT_EQ(RandomStream(0, 0, 0, 0), RandomStream());
}

TEST(RandomTests, everyCoordinateChangesTheStream) {
  // ============ Equivalence Partitions Tests ==============
  // TC01..TC04: a different seed, column, row or sample index gives different numbers in every
  // one of the first 32 dimensions
  const RandomStream base(7, 100, 200, 5);
  const RandomStream others[] = {RandomStream(8, 100, 200, 5), RandomStream(7, 101, 200, 5),
                                 RandomStream(7, 100, 201, 5), RandomStream(7, 100, 200, 6)};
  for (const RandomStream& other : others)
    for (std::uint32_t d = 0; d < 32; ++d) EXPECT_NE(base.bits(d), other.bits(d)) << d;
  // TC05: a different dimension of the same stream gives a different number
  for (std::uint32_t d = 0; d < 32; ++d) EXPECT_NE(base.bits(d), base.bits(d + 1)) << d;
  // =============== Boundary Values Tests ==================
  // TC11: x and y are not interchangeable (pixel (1,2) is not pixel (2,1))
  EXPECT_NE(RandomStream(0, 1, 2, 0).bits(0), RandomStream(0, 2, 1, 0).bits(0));
  // TC12: the largest coordinates are as good as any
  EXPECT_NE(RandomStream(~0ULL, ~0U, ~0U, ~0U).bits(0), RandomStream(~0ULL, ~0U, ~0U, 0).bits(0));
}

TEST(RandomTests, uniformInUnitInterval) {
  // TC01: 10^5 numbers of many samples and dimensions all lie in [0, 1)
  for (std::uint32_t s = 0; s < 1000; ++s) {
    const RandomStream r(1, s % 37, s / 37, s);
    for (std::uint32_t d = 0; d < 100; ++d) {
      const double u = r.uniform(d);
      ASSERT_GE(u, 0.0);
      ASSERT_LT(u, 1.0);
    }
  }
  // TC11: the largest value the conversion can give is 1 - 2^-53, below 1
  EXPECT_LT(static_cast<double>(~0ULL >> 11) * 0x1p-53, 1.0);
}

TEST(RandomTests, chiSquareUniformity) {
  // TC01: along the dimensions of one stream after another (what a path consumes): 10^5 numbers
  // in 100 bins
  std::vector<long> counts(BINS, 0);
  for (std::uint32_t s = 0; s < 1000; ++s) {
    RandomStream r(2024, 3, 4, s);
    for (int d = 0; d < 100; ++d) ++counts[static_cast<int>(r.next() * BINS)];
  }
  EXPECT_LT(chiSquare(counts, 1000.0), CHI2_99_AT_0_001);
  // TC02: across pixels, dimension 0 of each (what neighbouring pixels' first jitter sees)
  std::vector<long> pixels(BINS, 0);
  for (std::uint32_t y = 0; y < 250; ++y)
    for (std::uint32_t x = 0; x < 400; ++x)
      ++pixels[static_cast<int>(RandomStream(99, x, y, 0).uniform(0) * BINS)];
  EXPECT_LT(chiSquare(pixels, 1000.0), CHI2_99_AT_0_001);
  // TC03: across seeds, one pixel and dimension (what --seed changes)
  std::vector<long> seeds(BINS, 0);
  for (std::uint64_t seed = 0; seed < 100000; ++seed)
    ++seeds[static_cast<int>(RandomStream(seed, 10, 10, 0).uniform(3) * BINS)];
  EXPECT_LT(chiSquare(seeds, 1000.0), CHI2_99_AT_0_001);
}

TEST(RandomTests, noCorrelationBetweenNeighbours) {
  constexpr std::size_t N = 100000;
  std::vector<double> a, b, c, d;
  for (std::uint32_t i = 0; i < N; ++i) {
    const RandomStream r(5, i % 300, i / 300, 0);
    // TC01: dimension d against dimension d + 1 of the same sample
    a.push_back(r.uniform(4));
    b.push_back(r.uniform(5));
    // TC02: the same dimension of horizontally neighbouring pixels
    c.push_back(r.uniform(0));
    d.push_back(RandomStream(5, i % 300 + 1, i / 300, 0).uniform(0));
  }
  EXPECT_LT(std::abs(correlation(a, b)), correlationBound(N));
  EXPECT_LT(std::abs(correlation(c, d)), correlationBound(N));
  // TC03: consecutive samples of one pixel, same dimension
  std::vector<double> e, f;
  for (std::uint32_t s = 0; s < N; ++s) {
    e.push_back(RandomStream(5, 7, 7, s).uniform(0));
    f.push_back(RandomStream(5, 7, 7, s + 1).uniform(0));
  }
  EXPECT_LT(std::abs(correlation(e, f)), correlationBound(N));
}

TEST(RandomTests, jitteredCell) {
  RandomStream r(3, 0, 0, 0);
  // ============ Equivalence Partitions Tests ==============
  // TC01: every point of a 7x7 grid lies in its own cell
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const Sample2 s = jitteredCell(i, j, 7, r);
      EXPECT_GE(s.u, i / 7.0);
      EXPECT_LT(s.u, (i + 1) / 7.0);
      EXPECT_GE(s.v, j / 7.0);
      EXPECT_LT(s.v, (j + 1) / 7.0);
    }
  // =============== Boundary Values Tests ==================
  // TC11: a 1x1 grid is the whole square, and the point is the stream's next two numbers
  RandomStream q(3, 0, 0, 0);
  const Sample2 whole = jitteredCell(0, 0, 1, q);
  EXPECT_EQ(RandomStream(3, 0, 0, 0).uniform(0), whole.u);
  EXPECT_EQ(RandomStream(3, 0, 0, 0).uniform(1), whole.v);
}

TEST(RandomTests, squareToDisk) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the square's centre goes to the disk's centre, the middle of its right edge to (1, 0),
  // of its top edge to (0, 1)
  const Sample2 centre = squareToDisk({0.5, 0.5});
  EXPECT_EQ(0.0, centre.u);
  EXPECT_EQ(0.0, centre.v);
  const Sample2 right = squareToDisk({1, 0.5});
  EXPECT_DOUBLE_EQ(1.0, right.u);
  EXPECT_NEAR(0.0, right.v, 1e-15);
  const Sample2 top = squareToDisk({0.5, 1});
  EXPECT_NEAR(0.0, top.u, 1e-15);
  EXPECT_DOUBLE_EQ(1.0, top.v);
  // TC02: area is preserved: of 10^5 uniform points, those within radius 1/2 are a quarter (the
  // binomial standard deviation is √(n·p·(1−p)) ≈ 137, the bound is 4 of them), and every
  // point is inside the unit disk
  RandomStream r(11, 0, 0, 0);
  long inner = 0;
  for (int k = 0; k < 100000; ++k) {
    const Sample2 d = squareToDisk(r.next2D());
    const double r2 = d.u * d.u + d.v * d.v;
    ASSERT_LE(r2, 1.0 + 1e-12);
    if (r2 < 0.25) ++inner;
  }
  EXPECT_NEAR(25000.0, static_cast<double>(inner), 4 * 137.0);
  // =============== Boundary Values Tests ==================
  // TC11: a corner of the square goes to the circle at 45 degrees
  const Sample2 corner = squareToDisk({1, 1});
  EXPECT_NEAR(std::sqrt(0.5), corner.u, 1e-15);
  EXPECT_NEAR(std::sqrt(0.5), corner.v, 1e-15);
}

TEST(RandomTests, diskLatticePoint) {
  const double invPhi = (std::sqrt(5.0) - 1) / 2;
  // ============ Equivalence Partitions Tests ==============
  // TC01: point k of n is the lattice point ((k + 1/2)/n, k·φ⁻¹) shifted, then mapped to the disk
  const Sample2 p = diskLatticePoint(1, 4, {0.25, 0.125});
  const Sample2 expected = squareToDisk({1.5 / 4 + 0.25, invPhi + 0.125});
  EXPECT_EQ(expected.u, p.u);
  EXPECT_EQ(expected.v, p.v);
  // TC02: a shifted coordinate past 1 wraps around (modulo 1)
  const Sample2 wrapped = diskLatticePoint(3, 4, {0.5, 0.5});
  const Sample2 expectedWrapped = squareToDisk({3.5 / 4 + 0.5 - 1, 3 * invPhi + 0.5 - 2});
  EXPECT_EQ(expectedWrapped.u, wrapped.u);
  EXPECT_EQ(expectedWrapped.v, wrapped.v);
  // TC03: 64 points of one set are inside the unit disk, and the lattice spreads them evenly:
  // 17 lie within radius 1/2, one off the quarter (16) that area says, where 64 independent
  // points would scatter by √(64·¼·¾) ≈ 3.5
  int inner = 0;
  for (int k = 0; k < 64; ++k) {
    const Sample2 d = diskLatticePoint(k, 64, {0.3, 0.7});
    const double r2 = d.u * d.u + d.v * d.v;
    ASSERT_LE(r2, 1.0);
    if (r2 < 0.25) ++inner;
  }
  EXPECT_EQ(17, inner);
  // =============== Boundary Values Tests ==================
  // TC11: one point with the shift (0, 1/2) is the square's centre, the disk's centre
  const Sample2 centre = diskLatticePoint(0, 1, {0, 0.5});
  EXPECT_EQ(0.0, centre.u);
  EXPECT_EQ(0.0, centre.v);
}

TEST(RandomTests, allocatesNothing) {
  // TC01: making streams and drawing numbers, squares, disks and disk lattices allocates nothing
  double sum = 0;
  const long n = testing::allocationsDuring([&] {
    for (std::uint32_t s = 0; s < 1000; ++s) {
      RandomStream r(1, s, s, s);
      // One draw a statement: the order of the draws is the code's, not the compiler's.
      sum += r.next();
      sum += jitteredCell(1, 2, 4, r).u;
      sum += squareToDisk(r.next2D()).v;
      sum += diskLatticePoint(3, 8, r.next2D()).u;
    }
  });
  EXPECT_EQ(0, n);
  EXPECT_GT(sum, 0);
  // TC02: the counter sees an allocation (otherwise TC01 could not fail)
  EXPECT_EQ(1, testing::allocationsDuring([] { ::operator delete(::operator new(16)); }));
}

}  // namespace
}  // namespace rt
