// Stage 2: Polygon constructor validation (the course's given tests TC01-TC04, TC10-TC12, each
// violation with its own message) and normal.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometries/Polygon.h"

#include "ExpectVector.h"

namespace rt {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

using test::expectVector;

std::string messageOf(std::vector<Point> vertices) {
  try {
    Polygon p(std::move(vertices));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "the polygon was accepted";
  return {};
}

// The message fragments that name each violation.
const char* const kFewer = "at least 3 vertices";
const char* const kCoincide = "coincide";
const char* const kNotPlanar = "not in the plane";
const char* const kOnLine = "on the line";
const char* const kOrder = "out of order";
const char* const kConcave = "concave";

TEST(PolygonTests, constructor) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a correct convex quadrangle with vertices in order
  EXPECT_NO_THROW(Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 1, 1)}));
  // TC02: wrong vertex order (the boundary crosses itself)
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(0, 1, 0), Point(1, 0, 0), Point(-1, 1, 1)});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr(kOrder)));
  // TC03: the 4th vertex is not in the plane of the first three
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 2, 2)});
      },
      ThrowsMessage<std::invalid_argument>(AllOf(HasSubstr(kNotPlanar), HasSubstr("(0,2,2)"))));
  // TC04: the course's "concave" quadrangle: its 4th vertex (0.5,0.25,0.5) is in fact off the
  // plane x+y+z=1 of the first three (0.5+0.25+0.5 = 1.25), so that is the violation reported
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0.5, 0.25, 0.5)});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr(kNotPlanar)));
  // TC05: a really concave quadrangle: the 4th vertex (0.25,0.25,0.5) is coplanar and inside
  // the triangle of the first three
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0.25, 0.25, 0.5)});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr(kConcave)));
  // TC06: a convex pentagon, and a triangle given as a polygon
  EXPECT_NO_THROW(
      Polygon({Point(0, 0, 0), Point(2, 0, 0), Point(3, 2, 0), Point(1, 3, 0), Point(-1, 2, 0)}));
  EXPECT_NO_THROW(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}));
  // TC07: the same square in either winding
  EXPECT_NO_THROW(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)}));
  EXPECT_NO_THROW(Polygon({Point(0, 1, 0), Point(1, 1, 0), Point(1, 0, 0), Point(0, 0, 0)}));
  // TC08: a pentagram (regular pentagon's vertices taken every second one): every turn has the
  // same sign, as in a convex polygon, but the boundary winds twice and crosses itself
  {
    std::vector<Point> star;
    for (int k = 0; k < 5; ++k) {
      const double a = 2 * std::numbers::pi * (2 * k % 5) / 5;
      star.emplace_back(std::cos(a), std::sin(a), 0);
    }
    EXPECT_THAT(messageOf(star), HasSubstr(kOrder));
  }
  // TC09: concave "arrow" pentagon in the plane z=3
  EXPECT_THAT(
      messageOf({Point(0, 0, 3), Point(4, 0, 3), Point(4, 4, 3), Point(2, 1, 3), Point(0, 4, 3)}),
      AllOf(HasSubstr(kConcave), HasSubstr("(2,1,3)")));

  // =============== Boundary Values Tests ==================
  // TC10: the 4th vertex (0,0.5,0.5) lies on the edge between its neighbours (0,1,0),(0,0,1)
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0.5, 0.5)});
      },
      ThrowsMessage<std::invalid_argument>(AllOf(HasSubstr(kOnLine), HasSubstr("(0,0.5,0.5)"))));
  // TC11: the last vertex equals the first
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)});
      },
      ThrowsMessage<std::invalid_argument>(HasSubstr(kCoincide)));
  // TC12: two consecutive co-located vertices
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 1, 0)});
      },
      ThrowsMessage<std::invalid_argument>(AllOf(HasSubstr(kCoincide), HasSubstr("(0,1,0)"))));
  // TC13: two vertices, and none, are fewer than 3; the message gives the count
  EXPECT_THAT(
      [] {
        Polygon({Point(0, 0, 0), Point(1, 0, 0)});
      },
      ThrowsMessage<std::invalid_argument>(AllOf(HasSubstr(kFewer), HasSubstr("2"))));
  EXPECT_THAT([] { Polygon(std::vector<Point>{}); },
              ThrowsMessage<std::invalid_argument>(HasSubstr(kFewer)));
  // TC14: the first three vertices collinear (the 2nd on the line of its neighbours)
  EXPECT_THAT(messageOf({Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(1, 1, 0)}),
              AllOf(HasSubstr(kOnLine), HasSubstr("(1,0,0)")));
  // TC15: a later vertex (1,2,0) on the line of its neighbours (2,2,0),(0,2,0)
  EXPECT_THAT(
      messageOf({Point(0, 0, 0), Point(2, 0, 0), Point(2, 2, 0), Point(1, 2, 0), Point(0, 2, 0)}),
      AllOf(HasSubstr(kOnLine), HasSubstr("(1,2,0)")));
  // TC16: a 4th vertex off the plane by 1e-6 is rejected, by 1e-14 (rounding noise) accepted
  EXPECT_THAT(messageOf({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 1e-6)}),
              HasSubstr(kNotPlanar));
  EXPECT_NO_THROW(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 1e-14)}));
  // TC17: an almost straight angle (the 4th vertex 1e-6 outside the line) is still convex
  EXPECT_NO_THROW(Polygon(
      {Point(0, 0, 0), Point(2, 0, 0), Point(2, 2, 0), Point(1, 2 + 1e-6, 0), Point(0, 2, 0)}));
  // ... and 1e-6 inside the line makes it concave
  EXPECT_THAT(messageOf({Point(0, 0, 0), Point(2, 0, 0), Point(2, 2, 0), Point(1, 2 - 1e-6, 0),
                         Point(0, 2, 0)}),
              HasSubstr(kConcave));
  // TC18: far from the origin the plane's test scales with the coordinates: a flat quadrangle
  // about (10^6, 10^6, -10^6), its vertices rounded to doubles (2^-33 apart there), whose 4th
  // vertex the rounding puts 4.6·10^-11 off the plane of the first three, is kept (the course's
  // zero alone, 2^-40, refused it); 10^-5 off that plane is still off it
  const auto farQuad = [](double lift) {
    return std::vector<Point>{
        Point(1000001.904759107, 1000000.0, -999999.4285722679),
        Point(1000000.1347373291, 1000001.8999876599, -999999.9595788013),
        Point(999998.1143027762, 1000000.2687996206, -1000000.5657091672),
        Point(999999.5984847813, 999998.138040606, -1000000.1204545656 + lift)};
  };
  EXPECT_NO_THROW(Polygon(farQuad(0)));
  EXPECT_THAT([&] { Polygon(farQuad(1e-5)); },
              ThrowsMessage<std::invalid_argument>(HasSubstr(kNotPlanar)));
}

TEST(PolygonTests, eachViolationHasItsOwnMessage) {
  // TC01: the six violations produce six different messages, each naming only its own kind
  const std::vector<std::string> messages = {
      messageOf({Point(0, 0, 0), Point(1, 0, 0)}),
      messageOf({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 1, 0)}),
      messageOf({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 2, 2)}),
      messageOf({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0.5, 0.5)}),
      messageOf({Point(0, 0, 1), Point(0, 1, 0), Point(1, 0, 0), Point(-1, 1, 1)}),
      messageOf({Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(0.25, 0.25, 0.5)}),
  };
  const std::vector<const char*> kinds = {kFewer, kCoincide, kNotPlanar, kOnLine, kOrder, kConcave};
  EXPECT_EQ(std::set<std::string>(messages.begin(), messages.end()).size(), messages.size());
  for (std::size_t i = 0; i < messages.size(); ++i) {
    EXPECT_THAT(messages[i], HasSubstr("Polygon"));
    for (std::size_t j = 0; j < kinds.size(); ++j) {
      if (i == j)
        EXPECT_THAT(messages[i], HasSubstr(kinds[j]));
      else
        EXPECT_THAT(messages[i], Not(HasSubstr(kinds[j])));
    }
  }
}

TEST(PolygonTests, normal) {
  // TC01: the course's quad: unit normal orthogonal to every edge
  const std::vector<Point> pts = {Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 1, 1)};
  const Polygon poly(pts);
  const Vector n = poly.normal(Point(0, 0, 1));
  EXPECT_NEAR(n.length(), 1.0, 1e-12);
  for (std::size_t i = 0; i < pts.size(); ++i)
    EXPECT_NEAR(n.dot(pts[i] - pts[(i + 3) % 4]), 0.0, 1e-12) << "edge into vertex " << i;
  // TC02: its exact value: (1,0,-1) x (0,1,-1) = (1,1,1), normalised
  const double k = 1 / std::sqrt(3.0);
  expectVector(n, k, k, k);
  // TC03: the winding orients the normal (right-hand rule): counter-clockwise seen from +z
  expectVector(Polygon({Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)})
                   .normal(Point(0.5, 0.5, 0)),
               0, 0, 1);
  // TC04: the reverse winding gives the opposite normal
  expectVector(Polygon({Point(0, 1, 0), Point(1, 1, 0), Point(1, 0, 0), Point(0, 0, 0)})
                   .normal(Point(0.5, 0.5, 0)),
               0, 0, -1);
  // TC05: the normal is the same everywhere and equals the plane's
  EXPECT_EQ(poly.normal(Point(-1, 1, 1)), poly.plane().normal());
  // TC06: the vertices are kept in the given order
  EXPECT_EQ(poly.vertices().size(), 4u);
  EXPECT_EQ(poly.vertices()[3], Point(-1, 1, 1));
}

}  // namespace
}  // namespace rt
