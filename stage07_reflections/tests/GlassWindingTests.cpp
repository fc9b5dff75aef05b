// Stage 7: glassWindingProblems, which finds glass surfaces of polygons and triangles whose faces
// are wound both ways (refraction needs every normal pointing out of the glass).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "geometries/Polygon.h"
#include "geometries/Sphere.h"
#include "geometries/Triangle.h"
#include "lighting/LitScene.h"
#include "lighting/Material.h"
#include "reflections/GlassWinding.h"

namespace rt {
namespace {

using Faces = std::vector<std::uint32_t>;

Material glass(double ior = 1.5, double kT = 1) {
  Material m;
  m.kT = Double3(kT);
  m.ior = ior;
  return m;
}

/// The faces of the unit cube at `origin`, each wound counter-clockwise seen from outside, in
/// the order bottom, top, front (y = 0), back, left (x = 0), right.
std::vector<std::vector<Point>> cube(double origin = 0) {
  const auto p = [origin](double x, double y, double z) {
    return Point(origin + x, origin + y, origin + z);
  };
  return {
      {p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)},
      {p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)},
      {p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)},
      {p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)},
      {p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)},
      {p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)},
  };
}

std::vector<Point> reversed(std::vector<Point> face) { return {face.rbegin(), face.rend()}; }

/// Adds the faces as polygons of one new appearance row.
void addFaces(LitScene& scene, const std::vector<std::vector<Point>>& faces,
              const Material& material, const Color& emission = Color::BLACK) {
  const std::uint32_t row = scene.addAppearance(emission, material);
  for (const std::vector<Point>& f : faces) scene.add(Polygon(f), row);
}

TEST(GlassWindingTests, closedShapes) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a glass box wound right has no problem
  LitScene good;
  addFaces(good, cube(), glass());
  EXPECT_TRUE(glassWindingProblems(good).empty());

  // TC02: one face reversed: that face points inwards, the other five outwards
  std::vector<std::vector<Point>> faces = cube();
  faces[2] = reversed(faces[2]);
  LitScene oneFlipped;
  addFaces(oneFlipped, faces, glass());
  EXPECT_EQ(glassWindingProblems(oneFlipped),
            (std::vector<WindingProblem>{{Faces{2}, Faces{0, 1, 3, 4, 5}, true}}));

  // TC03: five faces reversed: those five point inwards (the signed volume says which class
  // does), not the one face left as it was
  faces = cube();
  for (std::size_t f = 1; f < faces.size(); ++f) faces[f] = reversed(faces[f]);
  LitScene fiveFlipped;
  addFaces(fiveFlipped, faces, glass());
  EXPECT_EQ(glassWindingProblems(fiveFlipped),
            (std::vector<WindingProblem>{{Faces{1, 2, 3, 4, 5}, Faces{0}, true}}));

  // TC04: a box wound inside out throughout is consistent: no problem (only mixed winding is)
  faces = cube();
  for (std::vector<Point>& f : faces) f = reversed(f);
  LitScene insideOut;
  addFaces(insideOut, faces, glass());
  EXPECT_TRUE(glassWindingProblems(insideOut).empty());

  // TC05: two boxes, each with a reversed face, are two problems ordered by the face to reverse
  LitScene two;
  faces = cube(5);
  faces[4] = reversed(faces[4]);
  addFaces(two, faces, glass());  // geometries 0..5
  faces = cube();
  faces[0] = reversed(faces[0]);
  addFaces(two, faces, glass());  // geometries 6..11
  EXPECT_EQ(glassWindingProblems(two),
            (std::vector<WindingProblem>{{Faces{4}, Faces{0, 1, 2, 3, 5}, true},
                                         {Faces{6}, Faces{7, 8, 9, 10, 11}, true}}));
}

TEST(GlassWindingTests, openSurfaces) {
  // TC01: a box without its top, the bottom reversed: the smaller class (the bottom) is named
  std::vector<std::vector<Point>> faces = cube();
  faces.erase(faces.begin() + 1);
  faces[0] = reversed(faces[0]);
  LitScene open;
  addFaces(open, faces, glass());
  EXPECT_EQ(glassWindingProblems(open),
            (std::vector<WindingProblem>{{Faces{0}, Faces{1, 2, 3, 4}, false}}));

  // TC11: two triangles sharing an edge, run the same way in both: a tie, the second named
  LitScene pair;
  const std::uint32_t row = pair.addAppearance(Color::BLACK, glass());
  pair.add(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)), row);
  pair.add(Triangle(Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)), row);
  EXPECT_EQ(glassWindingProblems(pair), (std::vector<WindingProblem>{{Faces{1}, Faces{0}, false}}));
  // TC12: the same two triangles wound alike: no problem
  LitScene alike;
  const std::uint32_t r = alike.addAppearance(Color::BLACK, glass());
  alike.add(Triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)), r);
  alike.add(Triangle(Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)), r);
  EXPECT_TRUE(glassWindingProblems(alike).empty());
}

TEST(GlassWindingTests, facesNotLookedAt) {
  std::vector<std::vector<Point>> faces = cube();
  faces[2] = reversed(faces[2]);
  // TC01: ior 1 does not bend rays: the reversed face changes nothing and is not reported
  LitScene plain;
  addFaces(plain, faces, glass(1));
  EXPECT_TRUE(glassWindingProblems(plain).empty());
  // TC02: without transparency (kT 0) the index changes nothing either
  LitScene opaque;
  addFaces(opaque, faces, glass(1.5, 0));
  EXPECT_TRUE(glassWindingProblems(opaque).empty());
  // TC03: faces of different appearance rows (here another emission) are different surfaces:
  // the reversed face alone and the five others are each consistent
  LitScene split;
  const std::uint32_t a = split.addAppearance(Color::BLACK, glass());
  const std::uint32_t b = split.addAppearance(Color(1, 0, 0), glass());
  for (std::size_t f = 0; f < faces.size(); ++f) split.add(Polygon(faces[f]), f == 2 ? b : a);
  EXPECT_TRUE(glassWindingProblems(split).empty());
  // TC04: shapes that are not faces (a glass sphere) are ignored; an empty scene has no problem
  LitScene ball;
  ball.add(Sphere(Point(0, 0, 0), 1), Color::BLACK, glass());
  EXPECT_TRUE(glassWindingProblems(ball).empty());
  EXPECT_TRUE(glassWindingProblems(LitScene{}).empty());
}

}  // namespace
}  // namespace rt
