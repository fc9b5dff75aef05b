// Stage 5, beyond the course: triangle meshes in a lit scene. One appearance row per mesh
// (LitScene::addMesh, meshAppearance, rowOf, appearanceOf), what validate() says when the rows
// and the meshes do not fit, a Scene with meshes made lit, and the Phong tracer on meshes: a flat
// mesh gives the pixels of the same triangles as Triangle shapes, bit for bit; a smooth one
// shades with the interpolated normal, worked out by hand.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "TestSupport.h"
#include "geometries/UtahTeapot.h"
#include "lighting/LitScene.h"
#include "lighting/PhongTracer.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::colorNear;
using test::sameBits;
using test::thrownMessage;
using ::testing::ThrowsMessage;
using Indices = TriangleMesh::Indices;

/// A triangle mesh of one triangle in z = -10 facing +z, with the given vertex normals.
std::shared_ptr<const TriangleMesh> oneTriangle(std::vector<Double3> normals = {}) {
  return std::make_shared<const TriangleMesh>(
      std::vector<Point>{Point(0, 0, -10), Point(10, 0, -10), Point(0, 10, -10)},
      std::vector<Indices>{{0, 1, 2}}, std::move(normals));
}

Material shiny() {
  Material m;
  m.kD = Double3(0.5, 0.25, 1);
  m.kS = Double3(0.4);
  m.shininess = 20;
  return m;
}

TEST(MeshLightingTests, addMesh) {
  LitScene scene;
  scene.add(Sphere(Point(0, 0, -50), 1), Color(1, 0, 0));  // row 0
  // ============ Equivalence Partitions Tests ==============
  // TC01: a mesh with an existing row: its index among the meshes, its row in meshAppearance
  const std::uint32_t row = scene.addAppearance(Color(0, 1, 0), shiny());
  EXPECT_EQ(scene.addMesh(oneTriangle(), row), 0u);
  EXPECT_EQ(scene.addMesh(oneTriangle(), 0), 1u);
  EXPECT_EQ(scene.meshAppearance, (std::vector<std::uint32_t>{1, 0}));
  EXPECT_EQ(scene.geometries.meshes().size(), 2u);
  EXPECT_EQ(scene.appearanceIndex.size(), 1u);  // the shapes' rows are untouched
  EXPECT_NO_THROW(scene.validate());
  // TC02: a null mesh: Geometries' refusal, and no row is recorded
  EXPECT_THAT([&] { scene.addMesh(nullptr, 0); },
              ThrowsMessage<std::invalid_argument>("Geometries::addMesh: the mesh is null"));
  EXPECT_EQ(scene.meshAppearance.size(), 2u);
  // =============== Boundary Values Tests ==================
  // TC11: one row past the table (2 rows: 2 is the first that does not exist): refused, nothing
  // added
  EXPECT_THAT([&] { scene.addMesh(oneTriangle(), 2); },
              ThrowsMessage<std::out_of_range>(
                  "LitScene::addMesh: appearance 2 does not exist (the table has 2 rows)"));
  EXPECT_EQ(scene.geometries.meshes().size(), 2u);
  EXPECT_EQ(scene.meshAppearance.size(), 2u);
  // TC12: an empty scene has no row 0 yet
  LitScene empty;
  EXPECT_THAT([&] { empty.addMesh(oneTriangle(), 0); },
              ThrowsMessage<std::out_of_range>(
                  "LitScene::addMesh: appearance 0 does not exist (the table has 0 rows)"));
  EXPECT_TRUE(empty.geometries.meshes().empty());
}

TEST(MeshLightingTests, validate) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a mesh added to the geometries behind LitScene's back has no row: both counts named,
  // through the tracer's constructor
  LitScene missing;
  missing.add(Sphere(Point(0, 0, -50), 1));
  missing.geometries.addMesh(oneTriangle());
  EXPECT_EQ(thrownMessage<std::logic_error>([&] { missing.validate(); }),
            "LitScene: 1 meshes but 0 mesh appearance indices; every mesh needs one (use "
            "LitScene::addMesh)");
  EXPECT_THROW(PhongTracer{missing}, std::logic_error);
  // TC02: a row for a mesh that is not there: the same message
  LitScene extra;
  extra.add(Sphere(Point(0, 0, -50), 1));
  extra.meshAppearance.push_back(0);
  EXPECT_EQ(thrownMessage<std::logic_error>([&] { extra.validate(); }),
            "LitScene: 0 meshes but 1 mesh appearance indices; every mesh needs one (use "
            "LitScene::addMesh)");
  // =============== Boundary Values Tests ==================
  // TC11: a mesh's row one past the table: the mesh, its row and the table's size
  LitScene bad;
  bad.add(Sphere(Point(0, 0, -50), 1));
  bad.addMesh(oneTriangle(), 0);
  bad.addMesh(oneTriangle(), 0);
  bad.meshAppearance[1] = 1;
  EXPECT_EQ(thrownMessage<std::logic_error>([&] { PhongTracer tracer(bad); }),
            "LitScene: mesh 1 uses appearance 1 but the table has 1 rows");
  // TC12: the last row is a valid one
  bad.meshAppearance[1] = 0;
  EXPECT_NO_THROW(PhongTracer{bad});
}

TEST(MeshLightingTests, rowOfAndAppearanceOf) {
  // Shape 0 (row 0), mesh 0 (row 1, 2 triangles), shape 1 (row 2), mesh 1 (row 0, 1 triangle):
  // primitives 0 and 1 are the shapes, 2 and 3 mesh 0's triangles, 4 mesh 1's.
  LitScene scene;
  scene.add(Sphere(Point(0, 0, -50), 1), Color(1, 0, 0));
  const std::uint32_t meshRow = scene.addAppearance(Color(0, 1, 0), shiny());
  scene.addMesh(std::make_shared<const TriangleMesh>(
                    std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)},
                    std::vector<Indices>{{0, 1, 2}, {0, 2, 1}}),
                meshRow);
  scene.add(Sphere(Point(0, 0, 50), 1), Color(0, 0, 1));
  scene.addMesh(oneTriangle(), 0);
  ASSERT_EQ(scene.geometries.primitiveCount(), 5u);
  // ============ Equivalence Partitions Tests ==============
  // TC01: a shape's row is its own, whenever it was added
  EXPECT_EQ(scene.rowOf(0), 0u);
  EXPECT_EQ(scene.rowOf(1), 2u);
  // TC02: a mesh triangle's row is its mesh's
  EXPECT_EQ(scene.rowOf(2), 1u);
  EXPECT_EQ(scene.rowOf(3), 1u);
  EXPECT_EQ(scene.rowOf(4), 0u);
  // TC03: appearanceOf is that row of the table, for reading and for writing
  EXPECT_EQ(&scene.appearanceOf(3), &scene.appearances[1]);
  EXPECT_EQ(scene.appearanceOf(1).emission.rgb().z, 1.0);
  scene.appearanceOf(4).emission = Color(7, 7, 7);
  EXPECT_EQ(scene.appearances[0].emission.rgb().x, 7.0);
  // =============== Boundary Values Tests ==================
  // TC11: the last shape and the first mesh triangle; the last primitive
  EXPECT_EQ(&scene.appearanceOf(1), &scene.appearances[2]);
  EXPECT_EQ(&scene.appearanceOf(2), &scene.appearances[1]);
  EXPECT_EQ(&std::as_const(scene).appearanceOf(4), &scene.appearances[0]);
}

TEST(MeshLightingTests, fromScene) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: a stage-4 Scene with two shapes and a mesh: one default row that every shape and the
  // mesh use; valid
  Scene base;
  base.geometries.add(Sphere(Point(0, 0, -50), 1));
  base.geometries.addMesh(oneTriangle());
  base.geometries.add(Sphere(Point(0, 0, 50), 1));
  const LitScene lit(base);
  EXPECT_EQ(lit.appearances.size(), 1u);
  EXPECT_EQ(lit.appearanceIndex, (std::vector<std::uint32_t>{0, 0}));
  EXPECT_EQ(lit.meshAppearance, (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(lit.rowOf(2), 0u);
  EXPECT_NO_THROW(lit.validate());
  EXPECT_EQ(lit.geometries.meshes()[0].mesh, base.geometries.meshes()[0].mesh);  // shared
  // =============== Boundary Values Tests ==================
  // TC11: a Scene of one mesh and no shape still gets its row
  Scene onlyMesh;
  onlyMesh.geometries.addMesh(oneTriangle());
  const LitScene litMesh(onlyMesh);
  EXPECT_EQ(litMesh.appearances.size(), 1u);
  EXPECT_TRUE(litMesh.appearanceIndex.empty());
  EXPECT_EQ(litMesh.meshAppearance.size(), 1u);
  EXPECT_NO_THROW(PhongTracer{litMesh});
  // TC12: an empty Scene: no row at all
  EXPECT_TRUE(LitScene(Scene{}).appearances.empty());
}

/// Every light kind around the teapot (z up, 0 <= z <= 3.15), seen from +y and above.
void lightTheTeapot(LitScene& scene) {
  scene.ambientLight = AmbientLight(Color(30, 30, 30), 0.2);
  scene.addLight(DirectionalLight(Color(80, 60, 40), Vector(-1, -2, -1)));
  scene.addLight(PointLight(Color(300, 300, 300), Point(4, 6, 6)).setKl(0.01).setKq(0.002));
  scene.addLight(SpotLight(Color(200, 100, 300), Point(-5, 5, 2), Vector(1, -1, 0)).setKl(0.02));
}

/// The colour of every ray of a 40 x 40 view of the teapot from (0, 10, 4).
std::vector<Color> pixels(const LitScene& scene) {
  const PhongTracer tracer(scene);
  const Camera camera =
      CameraSpec::squareView(Point(0, 10, 4), Point(0, 0, 1.5), 10, 14, 40).builder().build();
  std::vector<Color> colors;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      colors.push_back(tracer.traceRay(camera.constructRay(40, 40, j, i)));
  return colors;
}

TEST(MeshLightingTests, flatMeshShadesAsTriangleShapes) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: the teapot's 992 triangles without their normals (flat), one appearance, every light
  // kind, against the same triangles as Triangle shapes of that appearance: every pixel the
  // same bits; about a fifth of them see the teapot (351 of 1600)
  const TriangleMesh smooth = utahTeapot(4);
  const auto flat = std::make_shared<const TriangleMesh>(smooth.vertices(), smooth.triangles());
  LitScene meshes, shapes;
  for (LitScene* scene : {&meshes, &shapes}) lightTheTeapot(*scene);
  meshes.addMesh(flat, meshes.addAppearance(Color(10, 0, 0), shiny()));
  const std::uint32_t row = shapes.addAppearance(Color(10, 0, 0), shiny());
  for (std::size_t t = 0; t < flat->triangleCount(); ++t) {
    const std::array<Point, 3> c = flat->corners(t);
    shapes.add(Triangle(c[0], c[1], c[2]), row);
  }
  const std::vector<Color> a = pixels(meshes), b = pixels(shapes);
  int differ = 0, teapot = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    differ += sameBits(a[i], b[i]) ? 0 : 1;
    teapot += a[i].rgb().x > 0 ? 1 : 0;  // the background is black; the teapot emits red
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(teapot, 300);
}

TEST(MeshLightingTests, smoothMeshShadesWithTheInterpolatedNormal) {
  // The triangle (0,0,-10), (10,0,-10), (0,10,-10) with normals (0,0,1) at its first and third
  // corners and (1,0,0) at the second, lit by a directional light along (0,0,-1) with I = (100,
  // 200, 300); kD = (0.5,0.25,1), no kS, seen along -z.
  Material m;
  m.kD = Double3(0.5, 0.25, 1);
  auto sceneOf = [&](std::shared_ptr<const TriangleMesh> mesh) {
    LitScene scene;
    scene.addMesh(std::move(mesh), scene.addAppearance(Color::BLACK, m));
    scene.addLight(DirectionalLight(Color(100, 200, 300), Vector(0, 0, -1)));
    return scene;
  };
  const LitScene smooth = sceneOf(oneTriangle({{0, 0, 1}, {1, 0, 0}, {0, 0, 1}}));
  const LitScene flat = sceneOf(oneTriangle());
  const PhongTracer smoothTracer(smooth), flatTracer(flat);
  // ============ Equivalence Partitions Tests ==============
  // TC01: at (5,2,-10), b1 = 0.5 and b2 = 0.2, the normal is normalize(0.3·(0,0,1) + 0.5·(1,0,0)
  // + 0.2·(0,0,1)) = (1,0,1)/sqrt(2): |n·l| = 1/sqrt(2), so kD·I/sqrt(2) = (50,50,300)/sqrt(2);
  // the flat mesh gives kD·I = (50,50,300)
  const Ray halfway(Point(5, 2, 0), Vector(0, 0, -1));
  const double k = std::sqrt(0.5);
  EXPECT_TRUE(colorNear(smoothTracer.traceRay(halfway), 50 * k, 50 * k, 300 * k));
  EXPECT_TRUE(colorNear(flatTracer.traceRay(halfway), 50, 50, 300));
  // TC02: at (2.5,1,-10), b1 = 0.25 and b2 = 0.1: n = normalize(0.25·(1,0,0) + 0.75·(0,0,1)) =
  // (1,0,3)/sqrt(10), |n·l| = 3/sqrt(10)
  const double q = 3 / std::sqrt(10.0);
  EXPECT_TRUE(colorNear(smoothTracer.traceRay(Ray(Point(2.5, 1, 0), Vector(0, 0, -1))), 50 * q,
                        50 * q, 300 * q));
  // =============== Boundary Values Tests ==================
  // TC11: vertex normals all equal to the flat normal: the blend is the flat normal (0,0,1)
  // exactly, so the smooth mesh shades as the flat one, bit for bit, anywhere on it
  const LitScene same = sceneOf(oneTriangle({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}));
  const PhongTracer sameTracer(same);
  for (const Ray& ray : {halfway, Ray(Point(2.5, 3.5, 0), Vector(0, 0, -1)),
                         Ray(Point(0, 0, 0), Vector(0.3, 0.2, -1))})
    EXPECT_TRUE(sameBits(sameTracer.traceRay(ray), flatTracer.traceRay(ray))) << ray;
  // TC12: the hit point is the flat triangle's, whatever the normals: the same t, 10
  ASSERT_TRUE(smooth.geometries.closestHit(halfway).has_value());
  EXPECT_EQ(smooth.geometries.closestHit(halfway)->t, 10.0);
}

}  // namespace
}  // namespace rt
