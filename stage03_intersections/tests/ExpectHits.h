#pragma once
// Test helper for stage 3: checks both queries of a case at once.
//
//   EXPECT_TRUE(hits(shape, ray, {expected points...}[, maxDistance]));
//
// passes when findIntersections returns exactly the expected points, in order of distance,
// each within 1e-9, AND closestHit agrees: no hit when none is expected, else the t of the first
// expected point (ray.point(t) equal to it within 1e-9).

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "intersections/Geometries.h"
#include "intersections/Intersect.h"

namespace rt::test {

inline constexpr double kTolerance = 1e-9;

inline bool near(const Point& a, const Point& b, double tol = kTolerance) {
  return std::abs(a.x() - b.x()) <= tol && std::abs(a.y() - b.y()) <= tol &&
         std::abs(a.z() - b.z()) <= tol;
}

inline std::string describe(const std::vector<Point>& points) {
  std::ostringstream os;
  os.precision(17);
  os << "[";
  for (std::size_t i = 0; i < points.size(); ++i) os << (i ? ", " : "") << points[i];
  os << "]";
  return os.str();
}

inline ::testing::AssertionResult compareHits(const Ray& ray, const std::vector<Point>& found,
                                              std::optional<double> closest,
                                              const std::vector<Point>& expected) {
  bool ok = found.size() == expected.size();
  for (std::size_t i = 0; ok && i < found.size(); ++i) ok = near(found[i], expected[i]);
  if (!ok) {
    return ::testing::AssertionFailure() << "findIntersections: expected " << describe(expected)
                                         << ", got " << describe(found) << " for " << ray;
  }
  if (expected.empty() != !closest.has_value()) {
    return ::testing::AssertionFailure()
           << "closestHit: expected " << (expected.empty() ? "no hit" : "a hit") << ", got "
           << (closest ? "t = " + std::to_string(*closest) : std::string("none")) << " for " << ray;
  }
  if (closest) {
    const double expectedT = ray.head().distance(expected.front());
    if (std::abs(*closest - expectedT) > kTolerance ||
        !near(ray.point(*closest), expected.front())) {
      return ::testing::AssertionFailure()
             << "closestHit: expected t = " << expectedT << ", got " << *closest << " for " << ray;
    }
  }
  return ::testing::AssertionSuccess();
}

/// Both queries on one shape against the expected, distance-sorted points.
template <typename Shape>
::testing::AssertionResult hits(const Shape& shape, const Ray& ray,
                                const std::vector<Point>& expected,
                                double maxDistance = INFINITE_DISTANCE) {
  return compareHits(ray, findIntersections(shape, ray, maxDistance),
                     closestHit(shape, ray, maxDistance), expected);
}

/// Both queries on a Geometries composite.
inline ::testing::AssertionResult hits(const Geometries& geometries, const Ray& ray,
                                       const std::vector<Point>& expected,
                                       double maxDistance = INFINITE_DISTANCE) {
  const std::optional<Hit> hit = geometries.closestHit(ray, maxDistance);
  return compareHits(ray, geometries.findIntersections(ray, maxDistance),
                     hit ? std::optional<double>(hit->t) : std::nullopt, expected);
}

}  // namespace rt::test
