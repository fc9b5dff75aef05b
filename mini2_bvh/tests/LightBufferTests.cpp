// mini2: the light buffers (LightBuffer.h, LightBuffers.h). A shadow ray aimed at a point light
// gets, through its cell of the light's buffer, every crossing a linear scan finds in [tMin, tMax]
// with the scan's t, bit for bit (a certified flat shape: some t in the range), and a ray not
// aimed at it gets the walk's; the shadow query's transmittance and a rendered image are the same
// bits with and without buffers. Also: which lights get a buffer, the build's errors, budget and
// resolution, the cells a primitive is listed in, no allocation per ray, and how many flat
// shapes' crossings are certified without their solver.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bvh/Acceleration.h"
#include "bvh/FlatShapes.h"
#include "camera/Camera.h"
#include "camera/Image.h"
#include "camera/RenderBlock.h"
#include "geometries/UtahTeapot.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "lightbuffer/LightBuffer.h"
#include "lightbuffer/LightBuffers.h"
#include "shadows/RayOffset.h"
#include "shadows/ShadowCrossings.h"
#include "shadows/ShadowQuery.h"
#include "shadows/ShadowTracer.h"
#include "support/AllocationCounter.h"

#include "RandomScenes.h"
#include "support/SameBits.h"

namespace rt {
namespace {

using test::Random;
using test::sameBits;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// ---- Scenes ----

const Aabb kBox(Double3(-30), Double3(30));
/// The mixed scene's point light, inside its box, and its spot light, above it. Dyadic
/// coordinates of few bits: light + s·e below is exact for the small dyadic s·e of the edge rays.
const Point kPointAt(3.5, 12.25, -4.75);
const Point kSpotAt(-20.5, 35.25, 10.5);

/// Directions with two or three equal largest components: on the edges and corners of a light's
/// cube of cells, where a direction belongs to two or three faces.
const Double3 kEdgeDirections[] = {{1, 1, 0.25}, {-1, 1, -0.5}, {0.5, -1, -1}, {1, 0.75, -1},
                                   {1, 1, 1},    {-1, -1, -1},  {1, -1, 0},    {0, -1, 1}};

Double3 unit(const Double3& v) { return v / std::sqrt(v.lengthSquared()); }

/// A unit vector across the unit vector u.
Double3 across(const Double3& u) {
  const Double3 a = std::abs(u.x) < 0.6 ? Double3(1, 0, 0) : Double3(0, 1, 0);
  return unit(u.cross(a));
}

/// n convex pentagons and hexagons on integer coordinates (so exactly flat): in the planes
/// x, y or z = an integer, or tilted (p + x·u + y·v with RandomScenes' orthogonal integer u, v).
void addManySided(Geometries& g, Random& random, int n) {
  static const double pentagon[][2] = {{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}};
  static const double hexagon[][2] = {{0, 0}, {3, 0}, {5, 2}, {4, 5}, {1, 5}, {-1, 2}};
  for (int i = 0; i < n; ++i) {
    const Double3 p = random.gridPoint(Aabb(Double3(-25), Double3(20)));
    Double3 u, v;
    switch (i % 4) {
      case 0:
        u = Double3(1, 0, 0), v = Double3(0, 1, 0);
        break;
      case 1:
        u = Double3(0, 1, 0), v = Double3(0, 0, 1);
        break;
      case 2:
        u = Double3(0, 0, 1), v = Double3(1, 0, 0);
        break;
      default: {
        const double a = random.integer(1, 2), b = random.integer(-1, 1);
        const double k = random.integer(-1, 1), h = random.integer(1, 2);
        u = Double3(a, b, 0), v = Double3(-b * k, a * k, h);
      }
    }
    std::vector<Point> vertices;
    const auto add = [&](const double(&xy)[2]) {
      vertices.emplace_back(p + u * xy[0] + v * xy[1]);
    };
    if (i % 2 == 0)
      for (const auto& xy : pentagon) add(xy);
    else
      for (const auto& xy : hexagon) add(xy);
    g.add(Polygon(std::move(vertices)));
  }
}

/// Every bounded kind (spheres, triangles, rectangles axis-aligned and tilted, cylinders),
/// pentagons and hexagons, two planes and two tubes, copies (ties), a small teapot mesh; along
/// each edge direction from the point light a sphere and a triangle across it; a tiny sphere
/// 0.01 from the point light (within its near radius: the scene's size is about 35, R0 about
/// 0.035).
Geometries mixedShapes(Random& random) {
  Geometries g;
  test::addMixedShapes(g, random, 400, kBox);
  addManySided(g, random, 24);
  test::addUnbounded(g, kBox);
  test::addCopies(g, random, 30);
  for (const Double3& e : kEdgeDirections) {
    const Double3 u = unit(e), a = across(u), b = u.cross(a);
    g.add(Sphere(Point(kPointAt.xyz() + u * 6), 0.5));
    const Double3 m = kPointAt.xyz() + u * 11;
    g.add(
        Triangle(Point(m + a * 1.5), Point(m - a * 0.75 + b * 1.3), Point(m - a * 0.75 - b * 1.3)));
  }
  g.add(Sphere(Point(kPointAt.xyz() + Double3(0.01, 0, 0)), 0.005));
  g.addMesh(test::movedMesh(utahTeapot(2), Double3(-12, 6, 8)));
  return g;
}

/// A material of transparency kT (the same on every channel).
Material seeThrough(double kT) {
  Material m;
  m.kT = Double3(kT);
  return m;
}

/// The shapes as a lit scene whose looks are all partly transparent, 16 different kT from 0.55
/// to 0.925 (shape i gets row i mod 16): no crossing ever ends a shadow walk early, and the
/// product of kT tells which shapes were crossed.
LitScene seeThroughScene(const Geometries& shapes) {
  LitScene scene;
  for (int row = 0; row < 16; ++row)
    scene.addAppearance(Color::BLACK, seeThrough(0.55 + 0.025 * row));
  for (std::uint32_t i = 0; i < shapes.size(); ++i) scene.add(Geometry(shapes[i]), i % 16);
  for (const PlacedMesh& m : shapes.meshes()) scene.addMesh(m.mesh, 3);
  return scene;
}

/// The mixed scene, see-through, with its point light and its spot light.
LitScene mixedScene(std::uint64_t seed) {
  Random random(seed);
  LitScene scene = seeThroughScene(mixedShapes(random));
  scene.addLight(PointLight(Color(100, 100, 100), kPointAt));
  scene.addLight(SpotLight(Color(100, 80, 60), kSpotAt, Vector(0.5, -1, -0.25)));
  return scene;
}

/// The galaxy at 7 arms of 12 stars (its glass box, frame and pedestal: polygons; its floor: a
/// plane; three spot lights), a point light added inside the glass box above the core.
GalaxySetup smallGalaxy() {
  GalaxySetup g = galaxy(GalaxyParams{.arms = 7, .perArm = 12, .diffusion = false});
  g.scene.addLight(PointLight(Color(50, 50, 50), Point(4.5, 12.25, 4.25)));
  return g;
}

// ---- Shadow rays ----

/// Whether a light buffer must take a ray (Taken), must leave it to the walk (Walked), or may
/// do either (near the limits of LightBuffer.h's proof).
enum class Aim { Taken, Walked, Either };

struct ShadowRay {
  Ray ray;
  double tMin, tMax;
  std::uint32_t light;
  Aim aim;
};

/// Whether a buffer of near radius r0 must take the shadow ray from p to a light at distance d
/// that ShadowTracer::shadowQuery makes (below): yes when d >= 2·r0 and the shift ε(p) of its
/// origin is at most AIM·r0/2 (then w·g >= d − ε >= r0, tMax = d − ε <= w·g + r0/2, and the line
/// passes within ε plus rounding of the light: within AIM·R0); no when d < r0/2 (w·g < r0). A
/// point far out on a plane, where ε = 10^-9·|p| exceeds AIM·R0 (10^-8 to 10^-7 of the scene's
/// size), may be walked.
Aim aimOf(const Point& p, double d, double r0) {
  if (d < 0.5 * r0) return Aim::Walked;
  return d >= 2 * r0 && RayOffset().epsilon(p) <= 0.5 * LightBuffer::AIM * r0 ? Aim::Taken
                                                                              : Aim::Either;
}

/// The shadow ray from p (on a surface of normal n) towards light number `light`, as
/// ShadowTracer::shadowQuery makes it: from p shifted by the default RayOffset along ±n, along the
/// unit direction to the light, over [ε, d − ε].
void addShadowRay(std::vector<ShadowRay>& rays, const LitScene& scene, std::uint32_t light,
                  const Point& p, const Vector& n, double r0) {
  const std::optional<LightSample> sample = illuminate(scene.lights[light], p);
  if (!sample) return;
  const RayOffset offset;
  const RayOffset::Range range = offset.shadowRange(p, sample->distance);
  rays.push_back({offset.ray(p, n, -sample->l), range.tMin, range.tMax, light,
                  aimOf(p, sample->distance, r0)});
}

Point lightPosition(const LightSource& light) {
  if (const auto* s = std::get_if<SpotLight>(&light)) return s->position;
  return std::get<PointLight>(light).position;
}

/// Shadow rays of every kind towards each light of the scene (all with buffers, near radius
/// r0[light]): from the hit points of `primaries`; from points within a few near radii of the
/// light; from inside spheres; from points exactly on polygons (midpoints of integer or dyadic
/// vertices) and on the planes y = const; from points along the edge directions (two or three
/// equal largest components, exactly); and rays not aimed at the light: random directions, a
/// range that reaches past the light, a line 3·AIM·R0 from the light (Walked), and a line
/// AIM·R0/4 from it (Taken: within the proof's slack).
std::vector<ShadowRay> shadowRays(const LitScene& scene, const std::vector<double>& r0,
                                  const std::vector<Ray>& primaries, Random& random) {
  const Geometries& shapes = scene.geometries;
  const RayOffset offset;
  std::vector<ShadowRay> rays;
  for (std::uint32_t k = 0; k < scene.lights.size(); ++k) {
    const Point light = lightPosition(scene.lights[k]);
    for (const Ray& primary : primaries) {
      const std::optional<Hit> hit = shapes.closestHit(primary);
      if (!hit) continue;
      const Point p = primary.point(hit->t);
      const Vector n = shapes.hitNormal(hit->geometry, p, -primary.direction());
      addShadowRay(rays, scene, k, p, n, r0[k]);
      // Not aimed at the light, from the same point.
      const Vector stray(random.direction());
      rays.push_back(
          {offset.ray(p, n, stray), offset.epsilon(p), random.uniform(0, 80), k, Aim::Walked});
      const std::optional<LightSample> s = illuminate(scene.lights[k], p);
      if (!s) continue;
      const Double3 side = across(s->l.xyz());
      // Lines 3·AIM·R0 and AIM·R0/4 from the light (the shift ε moves them by at most ε): the
      // first walked and the second taken when ε <= AIM·R0/4 (and the second's range ends
      // before the light).
      const double aim = LightBuffer::AIM * r0[k], e = offset.epsilon(p);
      for (const double off : {3.0, 0.25}) {
        const Double3 to = light.xyz() + side * (off * aim) - p.xyz();
        const double d = std::sqrt(to.lengthSquared());
        if (d < 2 * r0[k]) continue;
        const Aim expected = e > 0.25 * aim ? Aim::Either : off > 1 ? Aim::Walked : Aim::Taken;
        rays.push_back({offset.ray(p, n, Vector(to / d)), e, d - e, k, expected});
      }
      if (s->distance >= 2 * r0[k]) {  // aimed, but the range reaches r0 past the light
        rays.push_back(
            {offset.ray(p, n, -s->l), offset.epsilon(p), s->distance + r0[k], k, Aim::Walked});
      }
    }
    for (const double r : {0.2, 0.6, 0.99, 1.01, 1.5, 2.5, 10.0, 100.0})
      for (int i = 0; i < 4; ++i) {
        const Point head(light.xyz() + random.direction() * (r * r0[k]));
        addShadowRay(rays, scene, k, head, Vector(random.direction()), r0[k]);
      }
    for (const Geometry& g : shapes.shapes()) {
      if (const auto* sphere = std::get_if<Sphere>(&g)) {
        if (random.chance(0.2)) {
          const Double3 out = random.direction();
          const Point head(sphere->center().xyz() +
                           out * (sphere->radius() * random.uniform(0, 0.9)));
          addShadowRay(rays, scene, k, head, Vector(random.direction()), r0[k]);
        }
      } else if (const auto* polygon = std::get_if<Polygon>(&g)) {
        const std::vector<Point>& v = polygon->vertices();
        const Vector& n = polygon->plane().normal();
        addShadowRay(rays, scene, k, Point((v[0].xyz() + v[2].xyz()) * 0.5), n, r0[k]);
        addShadowRay(rays, scene, k, v[1], n, r0[k]);  // on an edge's end
      } else if (const auto* plane = std::get_if<Plane>(&g)) {
        if (plane->normal().xyz() == Double3(0, 1, 0) || plane->normal().xyz() == Double3(0, -1, 0))
          for (int i = 0; i < 8; ++i) {
            const double x = random.integer(-20, 20);
            const Point head(x, plane->point().xyz().y, random.integer(-20, 20));
            addShadowRay(rays, scene, k, head, plane->normal(), r0[k]);
          }
      }
    }
    for (const Double3& e : kEdgeDirections)
      for (const double s : {3.0, 7.5, 14.0, 26.0})
        addShadowRay(rays, scene, k, Point(light.xyz() + e * s), Vector(random.direction()), r0[k]);
  }
  return rays;
}

// ---- Comparing hits ----

/// A shadow ray's hits as (geometry, t), sorted: two walks in different orders compare equal.
using Crossings = std::vector<std::pair<std::uint32_t, double>>;

Crossings scanCrossings(const Geometries& shapes, const Ray& ray, double tMax) {
  Crossings hits;
  shapes.forEachHit(ray, tMax, [&hits](const Hit& h) {
    hits.emplace_back(h.geometry, h.t);
    return true;
  });
  std::sort(hits.begin(), hits.end());
  return hits;
}

/// The t of geometry's hits among sorted crossings, before tMin and from tMin on.
std::pair<std::vector<double>, std::vector<double>> hitsOf(const Crossings& c,
                                                           std::uint32_t geometry, double tMin) {
  std::pair<std::vector<double>, std::vector<double>> split;
  for (const auto& [g, t] : c)
    if (g == geometry) (t < tMin ? split.first : split.second).push_back(t);
  return split;
}

std::string describe(const std::vector<double>& ts) {
  std::ostringstream os;
  os.precision(17);
  os << "{";
  for (const double t : ts) os << " " << t;
  os << " }";
  return os.str();
}

/// "" when the buffer's hits `got` agree with the scan's: for every primitive, the same hits from
/// tMin on, t for t (bit for bit), except a triangle or polygon that both cross once from tMin
/// on, whose buffer t may be any value in [tMin, tMax] (a certified crossing, LightOccluders.h:
/// counted in relaxed); and the buffer's hits before tMin are some of the scan's there. Else
/// what differs.
std::string compareCrossings(const Geometries& shapes, const Crossings& scan, const Crossings& got,
                             double tMin, double tMax, int& relaxed) {
  std::set<std::uint32_t> ids;
  for (const auto& h : scan) ids.insert(h.first);
  for (const auto& h : got) ids.insert(h.first);
  for (const std::uint32_t id : ids) {
    const auto [scanBefore, scanFrom] = hitsOf(scan, id, tMin);
    const auto [gotBefore, gotFrom] = hitsOf(got, id, tMin);
    const std::string what = "primitive " + std::to_string(id) + ": scan " + describe(scanFrom) +
                             ", buffer " + describe(gotFrom);
    if (gotFrom != scanFrom) {
      const bool flat = id < shapes.size() && FlatShapes::isFlat(shapes[id]);
      if (!(flat && scanFrom.size() == 1 && gotFrom.size() == 1 && gotFrom[0] <= tMax)) return what;
      ++relaxed;
    }
    if (!std::includes(scanBefore.begin(), scanBefore.end(), gotBefore.begin(), gotBefore.end()))
      return what + "; before tMin: scan " + describe(scanBefore) + ", buffer " +
             describe(gotBefore);
  }
  return "";
}

/// The entry of primitive i in a list, or null.
const LightBuffer::Entry* entryOf(std::span<const LightBuffer::Entry> list, std::uint32_t i) {
  for (const LightBuffer::Entry& e : list)
    if (e.index() == i) return &e;
  return nullptr;
}

/// What a run of shadow rays met.
struct Tally {
  int taken = 0, walked = 0, relaxed = 0, hits = 0, flatHits = 0;
  std::uint64_t tests = 0, certified = 0;
};

/// Every ray through buffers against the linear scan of the scene's shapes: LightBuffer::
/// forEachHit (taken or not as the ray's aim says; its hits as compareCrossings wants; stopped
/// at its first hit when told), and LightBuffers::crossingsTowards (the same crossings counted
/// from tMin on and the same product of kT as the scan's hits handed to a ShadowCrossings; the
/// buffer's tests as the counts, or for a ray the buffer does not take the walk's own counts).
Tally expectLikeTheScan(const LitScene& scene, const LightBuffers& buffers,
                        const std::vector<ShadowRay>& rays) {
  const Geometries& shapes = scene.geometries;
  Tally tally;
  int failures = 0;
  const auto fail = [&failures](const ShadowRay& r, const std::string& what) {
    if (++failures <= 5)
      ADD_FAILURE() << what << " for " << r.ray << " [" << r.tMin << ", " << r.tMax << "] light "
                    << r.light;
  };
  for (const ShadowRay& r : rays) {
    const LightBuffer* buffer = buffers.buffer(r.light);
    const Crossings scan = scanCrossings(shapes, r.ray, r.tMax);
    Crossings got;
    std::uint64_t tests = 0, certified = 0;
    const std::optional<bool> done = buffer->forEachHit(
        r.ray, r.tMin, r.tMax,
        [&got](const Hit& h) {
          got.emplace_back(h.geometry, h.t);
          return true;
        },
        tests, certified);
    if (done.has_value() ? r.aim == Aim::Walked : r.aim == Aim::Taken) {
      fail(r, done ? "taken, expected walked" : "walked, expected taken");
      continue;
    }
    if (done) {
      ++tally.taken;
      tally.tests += tests;
      tally.certified += certified;
      std::sort(got.begin(), got.end());
      if (!*done) fail(r, "forEachHit returned false, nothing stopped it");
      const std::string difference =
          compareCrossings(shapes, scan, got, r.tMin, r.tMax, tally.relaxed);
      if (!difference.empty()) fail(r, difference);
      for (const auto& [g, t] : scan)
        if (t >= r.tMin) {
          ++tally.hits;
          if (g < shapes.size() && FlatShapes::isFlat(shapes[g])) ++tally.flatHits;
        }
      if (!got.empty()) {  // told to stop at its first hit: one visit, and false
        int calls = 0;
        std::uint64_t t2 = 0, c2 = 0;
        const std::optional<bool> stopped = buffer->forEachHit(
            r.ray, r.tMin, r.tMax, [&calls](const Hit&) { return ++calls > 1; }, t2, c2);
        if (stopped != std::optional<bool>(false) || calls != 1) fail(r, "did not stop");
      }
    } else {
      ++tally.walked;
      if (!got.empty() || tests != 0 || certified != 0) fail(r, "visited a ray it did not take");
    }
    // Through the seam the shadow query uses.
    ShadowCrossings viaBuffers(scene, 0, true, r.tMin, Double3::ONE),
        viaScan(scene, 0, true, r.tMin, Double3::ONE);
    QueryCounts counts;
    if (!buffers.crossingsTowards(r.light, r.ray, r.tMin, r.tMax, viaBuffers, &counts))
      fail(r, "crossingsTowards stopped, nothing stopped it");
    for (const auto& [g, t] : scan) viaScan.add(Hit{t, g});
    if (viaBuffers.count() != viaScan.count() || viaBuffers.overflow() != viaScan.overflow())
      fail(r, "crossingsTowards: " + std::to_string(viaBuffers.count()) + " crossings, the scan " +
                  std::to_string(viaScan.count()));
    else if (!viaScan.overflow() && !sameBits(viaBuffers.product(), viaScan.product()))
      fail(r, "crossingsTowards: another product");
    QueryCounts walked;
    if (!done)
      buffers.walk().forEachHit(
          r.ray, r.tMax, [](const Hit&) { return true; }, &walked);
    if (counts != (done ? QueryCounts{tests, 0} : walked))
      fail(r, "crossingsTowards: other counts");
  }
  EXPECT_EQ(failures, 0) << "of " << rays.size() << " rays";
  return tally;
}

/// The scene's buffers over the plain list of its shapes and over the wide BVH (what a render
/// asks makeAcceleration for), the same rays through both.
/// certifies: whether some crossings must be certified (not where the scene's size S, from the
/// origin, puts the certainty margins 10^-3·S beyond its shapes).
void expectBuffersLikeTheScan(const LitScene& scene, const std::vector<Ray>& primaries,
                              Random& random, const std::string& name, bool certifies = true) {
  SCOPED_TRACE(name);
  const LightBuffers plain(scene.geometries, scene.geometries.primitives(), scene.lights);
  const std::unique_ptr<Intersectable> made =
      makeAcceleration("bvh4", scene.geometries, scene.lights, true);
  const auto* wide = dynamic_cast<const LightBuffers*>(made.get());
  ASSERT_NE(wide, nullptr);
  std::vector<double> r0;
  for (std::uint32_t k = 0; k < scene.lights.size(); ++k) {
    ASSERT_NE(plain.buffer(k), nullptr) << "light " << k;
    ASSERT_NE(wide->buffer(k), nullptr) << "light " << k;
    r0.push_back(plain.buffer(k)->nearRadius());
    EXPECT_EQ(wide->buffer(k)->nearRadius(), r0.back());
  }
  const std::vector<ShadowRay> rays = shadowRays(scene, r0, primaries, random);
  const Tally a = expectLikeTheScan(scene, plain, rays);
  const Tally b = expectLikeTheScan(scene, *wide, rays);
  // The same buffers over both walks: the same rays taken, tests and certified crossings.
  EXPECT_EQ(a.taken, b.taken);
  EXPECT_EQ(a.tests, b.tests);
  EXPECT_EQ(a.certified, b.certified);
  // Not vacuous: of every hit point's five rays, two are aimed (and most taken), three are
  // not; the taken rays meet many crossings, some certified (and every crossing whose t
  // differs from the solver's is one of them).
  EXPECT_GT(a.taken, static_cast<int>(rays.size()) / 3);
  EXPECT_GT(a.walked, static_cast<int>(rays.size()) / 3);
  EXPECT_GT(a.hits, a.taken / 2);
  if (certifies) {
    EXPECT_GT(a.certified, 0u);
  }
  EXPECT_LE(static_cast<std::uint64_t>(a.relaxed), a.certified);
  ::testing::Test::RecordProperty(name + " rays", std::to_string(rays.size()));
  ::testing::Test::RecordProperty(name + " taken", std::to_string(a.taken));
  ::testing::Test::RecordProperty(name + " certified", std::to_string(a.certified));
}

TEST(LightBufferTests, crossingsAreTheLinearScans) {
  // Every scene's rays (shadowRays) hold the partitions and the boundaries at once:
  // ============ Equivalence Partitions Tests ==============
  // TC01: shadow rays from hit points to a point light and to a spot light, through buffers over
  // the scene's list and over the wide BVH: the scan's crossings
  // TC02: rays from inside spheres, from points exactly on polygons and planes
  // TC03: rays not aimed at the light (random directions, lines 3·AIM·R0 from it, ranges past
  // it): walked, the walk's crossings
  // =============== Boundary Values Tests ==================
  // TC11: origins 0.2 to 100 near radii from the light (within R0/2: walked; from 2·R0: taken)
  // TC12: directions on the cube's edges and corners (two or three equal largest components)
  // TC13: a line AIM·R0/4 from the light: taken, within the proof's slack
  //
  // Scene 1: every kind of shape (spheres, triangles, rectangles, pentagons, hexagons,
  // cylinders, planes, tubes, copies, a mesh), a point light inside the scene with a tiny sphere
  // on its near list, and a spot light above it
  {
    Random random(7);
    const LitScene scene = mixedScene(71);
    const LightBuffers buffers(scene.geometries, scene.geometries.primitives(), scene.lights);
    ASSERT_NE(buffers.buffer(0), nullptr);
    const std::uint32_t tiny = scene.geometries.size() - 1;  // mixedShapes' last shape
    EXPECT_NE(entryOf(buffers.buffer(0)->nearList(), tiny), nullptr);
    std::vector<Ray> primaries;
    for (const test::Query& q : test::randomQueries(random, 500, kBox)) primaries.push_back(q.ray);
    expectBuffersLikeTheScan(scene, primaries, random, "mixed");
  }
  // Scene 2: the galaxy (7 arms of 12 stars) with its three spot lights and a point light inside
  // the glass box, its looks made see-through; rays from the camera's hits and random rays' hits
  {
    Random random(8);
    GalaxySetup g = smallGalaxy();
    for (std::size_t row = 0; row < g.scene.appearances.size(); ++row)
      g.scene.appearances[row].material.kT = Double3(0.55 + 0.025 * static_cast<double>(row % 16));
    const Camera camera = g.camera.builder().build();
    std::vector<Ray> primaries;
    for (int i = 0; i < 18; ++i)
      for (int j = 0; j < 32; ++j) primaries.push_back(camera.constructRay(32, 18, j, i));
    for (const test::Query& q :
         test::randomQueries(random, 200, Aabb(Double3(-7, 0, -7), Double3(19, 15, 15))))
      primaries.push_back(q.ray);
    expectBuffersLikeTheScan(g.scene, primaries, random, "galaxy");
  }
}

TEST(LightBufferTests, farFromTheOrigin) {
  // The mixed shapes in a box of side 60 whose centre is (10240, −20480, 5120), a point light
  // among them and a spot light above, as in scene 1 of crossingsAreTheLinearScans: the scene's
  // size S is about 20 500 (its largest coordinate) while the shapes lie within about 100 of each
  // light, so the near radius is the floor 10^-4·S, about 2.05, not 10^-3·S, about 20.5 (which
  // would put the shapes around the light on the near list); a small sphere 1 from the point
  // light lies within it.
  // ============ Equivalence Partitions Tests ==============
  // TC01: the near radius at its floor, a buffer for both lights, a near list of 3 (the tubes
  // and the small sphere) and 2 (the tubes)
  // TC02: shadow rays of every kind (shadowRays): the scan's crossings through the buffers over
  // the list and over the wide BVH (no certified crossing: the certainty margins, 10^-3·S, are
  // wider than the shapes)
  const Double3 offset(10240, -20480, 5120);
  const Aabb box(offset - Double3(30), offset + Double3(30));
  Random random(91);
  Geometries shapes;
  test::addMixedShapes(shapes, random, 400, box);
  test::addUnbounded(shapes, box);
  shapes.add(Sphere(Point(offset + kPointAt.xyz() + Double3(0, 0, 1)), 0.25));
  LitScene scene = seeThroughScene(shapes);
  scene.addLight(PointLight(Color(100, 100, 100), Point(offset + kPointAt.xyz())));
  scene.addLight(
      SpotLight(Color(100, 80, 60), Point(offset + kSpotAt.xyz()), Vector(0.5, -1, -0.25)));
  const LightBuffers buffers(scene.geometries, scene.geometries.primitives(), scene.lights);
  for (std::uint32_t k = 0; k < 2; ++k) {
    ASSERT_NE(buffers.buffer(k), nullptr) << "light " << k;
    const double r0 = buffers.buffer(k)->nearRadius();
    // S = 20 514.0 (some shapes stick out of the box): R0 = S/10^4
    EXPECT_NEAR(r0, 2.05140, 1e-5) << "light " << k;
    // The two tubes, and for the point light the small sphere (at 10^-3·S, more shapes than
    // nearPrimitives would lie within R0: no buffer at all)
    EXPECT_EQ(buffers.buffer(k)->nearList().size(), k == 0 ? 3u : 2u) << "light " << k;
  }
  std::vector<Ray> primaries;
  for (const test::Query& q : test::randomQueries(random, 500, box)) primaries.push_back(q.ray);
  expectBuffersLikeTheScan(scene, primaries, random, "far", false);
}

TEST(LightBufferTests, nearRadiusAndNearList) {
  // ============ Equivalence Partitions Tests ==============
  // TC01: R0 = max(10^-4·S, 10^-3·min(S, E)): the scene's size S when the shapes reach at least
  // as far from the light (E >= S); their reach E when it is smaller; the floor 10^-4·S
  EXPECT_DOUBLE_EQ(LightBuffer::nearRadiusOf(40, 80), 0.04);
  EXPECT_DOUBLE_EQ(LightBuffer::nearRadiusOf(100, 50), 0.05);
  EXPECT_DOUBLE_EQ(LightBuffer::nearRadiusOf(10000, 20), 1);
  // =============== Boundary Values Tests ==================
  // TC11: E = S, and E = S/10, where the floor and 10^-3·E meet
  EXPECT_DOUBLE_EQ(LightBuffer::nearRadiusOf(64, 64), 0.064);
  EXPECT_DOUBLE_EQ(LightBuffer::nearRadiusOf(500, 50), 0.05);
  // TC12: a light at the origin, a sphere of radius 1 at (99, 0, 0) (S = 100, E a little more:
  // R0 = 0.1) and n tiny spheres 0.05 from the light, within R0: up to nearPrimitives (8) on
  // the near list, one more and no buffer (the walk answers); tubes, tested by the walk too,
  // do not count; a limit of 9 takes 9
  const std::vector<LightSource> origin{PointLight(Color(100, 100, 100), Point(0, 0, 0))};
  const auto withTiny = [](int n, int tubes) {
    Geometries g;
    g.add(Sphere(Point(99, 0, 0), 1));
    for (int i = 0; i < n; ++i) {
      const double a = 0.7 * i;
      g.add(Sphere(Point(0.05 * std::cos(a), 0.05 * std::sin(a), 0), 0.001));
    }
    for (int i = 0; i < tubes; ++i) g.add(Tube(0.5, Ray(Point(0, 10 + i, 0), Vector(1, 0, 0))));
    return g;
  };
  /// The near list's length of the origin's buffer, or -1 when there is none.
  const auto nearOf = [&origin](const Geometries& g, std::size_t limit) {
    const LightBuffers buffers(g, g.primitives(), origin, {.buffer = {.nearPrimitives = limit}});
    if (buffers.buffer(0) == nullptr) return -1;
    EXPECT_NEAR(buffers.buffer(0)->nearRadius(), 0.1, 1e-7);
    return static_cast<int>(buffers.buffer(0)->nearList().size());
  };
  EXPECT_EQ(nearOf(withTiny(0, 0), 8), 0);
  EXPECT_EQ(nearOf(withTiny(8, 0), 8), 8);
  EXPECT_EQ(nearOf(withTiny(9, 0), 8), -1);
  EXPECT_EQ(nearOf(withTiny(8, 10), 8), 18);
  EXPECT_EQ(nearOf(withTiny(9, 0), 9), 9);
  EXPECT_EQ(nearOf(withTiny(9, 0), 0), -1);
  EXPECT_EQ(nearOf(withTiny(0, 3), 0), 3);
}

TEST(LightBufferTests, certifiedCrossingsAtTheirMargins) {
  // A point light at the origin and a sphere whose box reaches x = 40: the scene's size S = 40,
  // so R0 = S/1000 = 0.04 (LightBuffer.cpp), and the certainty margins (how far behind a flat
  // shape's plane an origin must be, how far inside or outside its edges a crossing)
  // CERTAIN_MARGIN·S = 0.04. Squares and triangles on axis-aligned planes 0.02 to 3 from the light,
  // either side (square k: centre c, half sides a and b along the plane's axes u and v).
  Random random(77);
  Geometries shapes;
  shapes.add(Sphere(Point(39, 0, 0), 1));
  struct Flat {
    Double3 c, u, v;
    double a, b;
  };
  std::vector<Flat> flats;
  const Double3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 120; ++i) {
    const Double3 n = axes[i % 3], u = axes[(i + 1) % 3], v = axes[(i + 2) % 3];
    const double depth = (i % 2 != 0 ? -1 : 1) * random.uniform(0.02, 3);
    const double alongU = random.uniform(-2, 2);
    const Double3 c = n * depth + u * alongU + v * random.uniform(-2, 2);
    const double a = random.uniform(0.05, 2), b = random.uniform(0.05, 2);
    flats.push_back({c, u, v, a, b});
    if (i % 4 == 0)
      shapes.add(Triangle(Point(c - u * a - v * b), Point(c + u * a - v * b), Point(c + v * b)));
    else
      shapes.add(Polygon({Point(c - u * a - v * b), Point(c + u * a - v * b),
                          Point(c + u * a + v * b), Point(c - u * a + v * b)}));
  }
  LitScene scene = seeThroughScene(shapes);
  scene.addLight(PointLight(Color(1, 1, 1), Point(0, 0, 0)));
  const LightBuffers buffers(scene.geometries, scene.geometries.primitives(), scene.lights);
  ASSERT_NE(buffers.buffer(0), nullptr);
  const double r0 = buffers.buffer(0)->nearRadius();
  ASSERT_NEAR(r0, 0.04, 1e-6);  // the box is widened to floats: S a few float ulps above 40
  const double depth = LightBuffer::CERTAIN_MARGIN * 1000 * r0;
  // =============== Boundary Values Tests ==================
  // TC11: origins behind each shape (on the side away from the light) by 0, 0.5, 0.99, 1, 1.01,
  // 1.5, 3 and 30 times the certainty depth, near the shape's edges u = ±a (within 0.1): shadow
  // rays as the tracer makes them, and from the exact points (no offset); the scan's crossings,
  // certified or solved
  std::vector<ShadowRay> rays;
  for (const Flat& f : flats) {
    const Double3 n = f.u.cross(f.v);
    const double away = n.dot(f.c) > 0 ? 1 : -1;
    for (const double d : {0.0, 0.5, 0.99, 1.0, 1.01, 1.5, 3.0, 30.0})
      for (int k = 0; k < 6; ++k) {
        const double x = (k < 3 ? 1 : -1) * f.a + random.uniform(-0.1, 0.1);
        const Double3 p = f.c + f.u * x + f.v * random.uniform(-f.b, f.b) + n * (away * d * depth);
        addShadowRay(rays, scene, 0, Point(p), Vector(n), r0);
        const double distance = std::sqrt(p.lengthSquared());
        rays.push_back({Ray::withUnitDirection(Point(p), Vector::unchecked(-p / distance)), 1e-9,
                        distance - 1e-9, 0, Aim::Either});
      }
  }
  const Tally margins = expectLikeTheScan(scene, buffers, rays);
  EXPECT_GT(margins.taken, static_cast<int>(rays.size()) / 2);
  EXPECT_GT(margins.certified, 0u);
  EXPECT_LE(static_cast<std::uint64_t>(margins.relaxed), margins.certified);
  // TC12: grazing rays: rectangles and triangles 5 to 50 wide on the planes z = ±(0.1 … 1.5),
  // origins up to 150 away from the light (at the origin, and at (0.5, −0.25, 0.05)): slopes
  // |n·dir| from 10^-4 up, through MIN_SLOPE (a crossing's slope to be certified) and
  // 2·MIN_SLOPE (a cell's, to be INSIDE or OUTSIDE)
  Geometries flatLand;
  for (int i = 0; i < 60; ++i) {
    const double h = (i % 2 != 0 ? 1 : -1) * random.uniform(0.1, 1.5);
    const double x = random.uniform(-100, 50), y = random.uniform(-100, 50);
    const double a = random.uniform(5, 50), b = random.uniform(5, 50);
    if (i % 3 == 0)
      flatLand.add(Triangle(Point(x, y, h), Point(x + a, y, h), Point(x, y + b, h)));
    else
      flatLand.add(Polygon(
          {Point(x, y, h), Point(x + a, y, h), Point(x + a, y + b, h), Point(x, y + b, h)}));
  }
  LitScene grazed = seeThroughScene(flatLand);
  grazed.addLight(PointLight(Color(1, 1, 1), Point(0, 0, 0)));
  grazed.addLight(PointLight(Color(1, 1, 1), Point(0.5, -0.25, 0.05)));
  const LightBuffers grazedBuffers(grazed.geometries, grazed.geometries.primitives(),
                                   grazed.lights);
  ASSERT_NE(grazedBuffers.buffer(0), nullptr);
  ASSERT_NE(grazedBuffers.buffer(1), nullptr);
  std::vector<ShadowRay> grazing;
  for (std::uint32_t k = 0; k < 2; ++k)
    for (int i = 0; i < 4000; ++i)
      addShadowRay(grazing, grazed, k,
                   Point(random.inBox(Double3(-150, -150, -2), Double3(150, 150, 2))),
                   Vector(0, 0, 1), grazedBuffers.buffer(k)->nearRadius());
  const Tally slopes = expectLikeTheScan(grazed, grazedBuffers, grazing);
  EXPECT_GT(slopes.taken, static_cast<int>(grazing.size()) / 2);
  EXPECT_GT(slopes.certified, 0u);
  EXPECT_LE(static_cast<std::uint64_t>(slopes.relaxed), slopes.certified);
}

/// The mixed shapes with looks for shadows: rows of kT 0 (opaque: 1 in 4), 1 (clear: 1 in 8) and
/// partly transparent, a different kT per channel in [0.1, 0.95]; the point and the spot light.
LitScene shadedScene(std::uint64_t seed) {
  Random random(seed);
  const Geometries shapes = mixedShapes(random);
  LitScene scene;
  for (int row = 0; row < 24; ++row) {
    Material m;
    m.kD = Double3(0.5);
    m.kT = row % 4 == 0 ? Double3(0) : row % 8 == 1 ? Double3(1) : random.inCube(0.1, 0.95);
    scene.addAppearance(Color(10, 10, 10), m);
  }
  for (std::uint32_t i = 0; i < shapes.size(); ++i)
    scene.add(Geometry(shapes[i]), static_cast<std::uint32_t>(random.integer(0, 23)));
  for (const PlacedMesh& m : shapes.meshes()) scene.addMesh(m.mesh, 2);
  scene.addLight(PointLight(Color(100, 100, 100), kPointAt));
  scene.addLight(SpotLight(Color(100, 80, 60), kSpotAt, Vector(0.5, -1, -0.25)));
  return scene;
}

TEST(LightBufferTests, transmittanceIsTheSameBits) {
  const LitScene scene = shadedScene(72);
  const LightBuffers plain(scene.geometries, scene.geometries.primitives(), scene.lights);
  const std::unique_ptr<Intersectable> wide =
      makeAcceleration("bvh4", scene.geometries, scene.lights, true);
  ASSERT_NE(plain.buffer(0), nullptr);
  ASSERT_NE(plain.buffer(1), nullptr);
  Random random(9);
  std::vector<Ray> primaries;
  for (const test::Query& q : test::randomQueries(random, 400, kBox)) primaries.push_back(q.ray);
  // ============ Equivalence Partitions Tests ==============
  // TC01: the shadow tracer's query from the hit points of random rays to each light, for a
  // path weight drawn per ray (the cut-off applies to the product times it): the factor and
  // whether the walk stopped early, bit for bit, through the scene's list, through buffers over
  // the list and through buffers over the wide BVH; the buffered walks visit no node
  const ShadowTracer linear(scene), buffered(scene, &plain), widened(scene, wide.get());
  int partial = 0, blocked = 0, clear = 0, queries = 0;
  for (const Ray& primary : primaries) {
    const std::optional<Hit> hit = scene.geometries.closestHit(primary);
    if (!hit) continue;
    const Point p = primary.point(hit->t);
    const Vector n = scene.geometries.hitNormal(hit->geometry, p, -primary.direction());
    for (std::uint32_t k = 0; k < scene.lights.size(); ++k) {
      const std::optional<LightSample> sample = illuminate(scene.lights[k], p);
      ASSERT_TRUE(sample.has_value());
      const Double3 weight = random.inCube(0.002, 1);
      RayCounts a, b, c;
      const Transmittance expected = linear.shadowQuery(p, n, *sample, weight, a, k);
      const Transmittance viaList = buffered.shadowQuery(p, n, *sample, weight, b, k);
      const Transmittance viaWide = widened.shadowQuery(p, n, *sample, weight, c, k);
      ++queries;
      EXPECT_TRUE(sameBits(viaList.factor, expected.factor)) << primary << " light " << k;
      EXPECT_TRUE(sameBits(viaWide.factor, expected.factor)) << primary << " light " << k;
      EXPECT_EQ(viaList.stoppedEarly, expected.stoppedEarly);
      EXPECT_EQ(viaWide.stoppedEarly, expected.stoppedEarly);
      // A ray the buffer takes walks the tree only for the canonical product of more than
      // CAPACITY crossings.
      if (aimOf(p, sample->distance, plain.buffer(k)->nearRadius()) == Aim::Taken &&
          (viaWide.stoppedEarly || viaWide.crossings <= ShadowCrossings::CAPACITY)) {
        EXPECT_EQ(c.queries.nodesVisited, 0u) << primary << " light " << k;
      }
      if (expected.factor.isExactlyZero())
        ++blocked;
      else if (sameBits(expected.factor, Double3::ONE))
        ++clear;
      else
        ++partial;
    }
  }
  // Every kind of answer met often (more than one query in ten): cut off, unshadowed, and
  // partly shadowed. The scene's numbers (support/TestRandom.h) are the same on every compiler:
  // 127 cut off, 381 unshadowed, 174 partly shadowed of 682.
  const auto counts = [&] {
    return std::to_string(blocked) + " cut off, " + std::to_string(clear) + " unshadowed, " +
           std::to_string(partial) + " partly shadowed of " + std::to_string(queries);
  };
  RecordProperty("cutOff", blocked);
  RecordProperty("unshadowed", clear);
  RecordProperty("partlyShadowed", partial);
  EXPECT_GT(blocked, queries / 10) << counts();
  EXPECT_GT(clear, queries / 10) << counts();
  EXPECT_GT(partial, queries / 10) << counts();
  // TC02: ShadowQuery itself over every kind of shadow ray (near the light, inside spheres, on
  // polygons and planes, on the cube's edges, not aimed at the light), the same bits
  const std::vector<double> r0{plain.buffer(0)->nearRadius(), plain.buffer(1)->nearRadius()};
  const std::vector<ShadowRay> rays = shadowRays(scene, r0, primaries, random);
  const double cutOff = PhongTracer::MIN_CALC_COLOR_K;
  const ShadowQuery scanned(scene.geometries, scene, cutOff), viaBuffers(plain, scene, cutOff),
      viaWide(*wide, scene, cutOff);
  int differences = 0;
  for (const ShadowRay& r : rays) {
    const Double3 weight(random.uniform(0.002, 1));
    const Transmittance expected = scanned(r.ray, r.tMin, r.tMax, weight);
    for (const ShadowQuery* query : {&viaBuffers, &viaWide}) {
      const Transmittance got = (*query)(r.ray, r.tMin, r.tMax, weight, nullptr, r.light);
      if ((!sameBits(got.factor, expected.factor) || got.stoppedEarly != expected.stoppedEarly) &&
          ++differences <= 3)
        ADD_FAILURE() << r.ray << " [" << r.tMin << ", " << r.tMax << "] light " << r.light;
    }
  }
  EXPECT_EQ(differences, 0) << "of " << rays.size() << " rays";
}

TEST(LightBufferTests, aBufferForEachPointLikeLight) {
  Geometries shapes;
  shapes.add(Sphere(Point(0, 0, 0), 1), Sphere(Point(4, 0, 0), 1),
             Triangle(Point(-3, 0, -3), Point(3, 0, -3), Point(0, 0, 3)),
             Plane(Point(0, -2, 0), Vector(0, 1, 0)));
  shapes.addMesh(std::make_shared<const TriangleMesh>(utahTeapot(1)));
  const Color c(100, 100, 100);
  const std::vector<LightSource> lights{
      PointLight(c, Point(0, 10, 0)),
      SpotLight(c, Point(5, 10, 0), Vector(0, -1, 0)),
      PointLight(c, Point(0, 10, 5)).setRadius(2).setShadowSamples(4),
      SpotLight(c, Point(5, 10, 5), Vector(0, -1, 0)).setRadius(1).setShadowSamples(2),
      DirectionalLight(c, Vector(0, -1, 0)),
      PointLight(c, Point(-5, 10, 0)).setRadius(2),
      PointLight(c, Point(-5, 10, 5)).setShadowSamples(8),
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: a point light and a spot light get a buffer around their position; an area light
  // (radius > 0, several shadow samples: its rays aim at points of a disk) and a directional
  // light do not; a light with a radius but one shadow sample, or several samples of no radius,
  // is a point (its one ray aims at the centre)
  const LightBuffers buffers(shapes, shapes.primitives(), lights);
  const bool expected[] = {true, true, false, false, false, true, true};
  for (std::uint32_t k = 0; k < lights.size(); ++k) {
    SCOPED_TRACE("light " + std::to_string(k));
    EXPECT_EQ(buffers.buffer(k) != nullptr, expected[k]);
    if (buffers.buffer(k) != nullptr) {
      EXPECT_EQ(buffers.buffer(k)->light().xyz(), lightPosition(lights[k]).xyz());
    }
  }
  // =============== Boundary Values Tests ==================
  // TC11: a light number past the scene's lights: none
  EXPECT_EQ(buffers.buffer(7), nullptr);
  // TC12: more primitives than maxPrimitives (mesh triangles count: 4 shapes and the teapot's
  // triangles): no buffer at all; exactly maxPrimitives: buffers
  const std::uint32_t primitives = shapes.primitiveCount();
  ASSERT_EQ(primitives, 4 + utahTeapotTriangleCount(1));
  const LightBuffers over(shapes, shapes.primitives(), lights,
                          {.maxPrimitives = primitives - 1, .buffer = {}});
  const LightBuffers atLimit(shapes, shapes.primitives(), lights,
                             {.maxPrimitives = primitives, .buffer = {}});
  const LightBuffers shapesOnly(shapes, shapes.primitives(), lights,
                                {.maxPrimitives = 4, .buffer = {}});
  for (std::uint32_t k = 0; k < lights.size(); ++k) {
    EXPECT_EQ(over.buffer(k), nullptr) << k;
    EXPECT_EQ(shapesOnly.buffer(k), nullptr) << k;
    EXPECT_EQ(atLimit.buffer(k) != nullptr, expected[k]) << k;
  }
  // TC13: makeAcceleration wraps the structure in buffers only when asked and the scene has
  // lights; over "none" the buffers fall back on the scene's own list
  const auto isBuffers = [](const std::unique_ptr<Intersectable>& s) {
    return dynamic_cast<const LightBuffers*>(s.get()) != nullptr;
  };
  EXPECT_TRUE(isBuffers(makeAcceleration("bvh4", shapes, lights, true)));
  EXPECT_FALSE(isBuffers(makeAcceleration("bvh4", shapes, lights, false)));
  EXPECT_FALSE(isBuffers(makeAcceleration("bvh4", shapes, {}, true)));
  EXPECT_TRUE(makeAcceleration("none", shapes, lights, false) == nullptr);
  const std::unique_ptr<Intersectable> overList = makeAcceleration("none", shapes, lights, true);
  ASSERT_TRUE(isBuffers(overList));
  EXPECT_EQ(&static_cast<const LightBuffers&>(*overList).walk(),
            static_cast<const Intersectable*>(&shapes));
}

/// Six squares facing a light at the origin: square k (k = 10 … 15) at x = k, y and z in
/// [−k, k]. Seen from the light each fills the face +x of its cube (u = y/x and v = z/x span
/// [−1, 1]), and its box's points with y (or −y, z, −z) above the light project on that face
/// to v = x/y >= 1 (or u): its last row (or column), whose cells reach 1.001. So a square is
/// listed in n² + 4·n cells at n cells a side (none on the face −x, behind the light).
Geometries facingSquares() {
  Geometries g;
  for (int k = 10; k <= 15; ++k) {
    const double s = k;
    g.add(Polygon({Point(s, -s, -s), Point(s, s, -s), Point(s, s, s), Point(s, -s, s)}));
  }
  return g;
}

/// n spheres of radius 0.05 at distance 50 from the origin, on a golden-angle spiral.
Geometries sphereShell(int n) {
  Geometries g;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), phi = 2.399963 * i;
    g.add(Sphere(Point(50 * r * std::cos(phi), 50 * r * std::sin(phi), 50 * z), 0.05));
  }
  return g;
}

TEST(LightBufferTests, resolutionAndBudget) {
  const std::vector<LightSource> origin{PointLight(Color(100, 100, 100), Point(0, 0, 0))};
  /// The resolution of the buffer of a point light at the origin over g, or 0 when none is made.
  const auto resolution = [&origin](const Geometries& g, const LightBufferOptions& options) {
    const LightBuffers buffers(g, g.primitives(), origin, {.buffer = options});
    return buffers.buffer(0) != nullptr ? buffers.buffer(0)->resolution() : 0;
  };
  // ============ Equivalence Partitions Tests ==============
  // TC01: the default resolution, 16 to 128 cells a side, doubled while n² < 2·(bounded
  // primitives): 128 spheres (n² = 256 = 2·128) 16; 129: 32; 512: 32; 513: 64; 2048: 64;
  // 2049: 128 (the largest); a plane and a tube are not bounded: 128 spheres with them, still 16
  for (const auto& [spheres, n] : std::vector<std::pair<int, int>>{
           {1, 16}, {128, 16}, {129, 32}, {512, 32}, {513, 64}, {2048, 64}, {2049, 128}})
    EXPECT_EQ(resolution(sphereShell(spheres), {}), n) << spheres << " spheres";
  Geometries unbounded = sphereShell(128);
  unbounded.add(Plane(Point(0, -60, 0), Vector(0, 1, 0)),
                Tube(1, Ray(Point(0, 70, 0), Vector(1, 0, 0))));
  EXPECT_EQ(resolution(unbounded, {}), 16);
  // TC02: a resolution asked for is kept (any integer from 8, not only powers of 2)
  const Geometries few = sphereShell(20);
  for (const int n : {8, 12, 37}) EXPECT_EQ(resolution(few, {.resolution = n}), n);
  // TC03: the budget, 6·n² + entriesPerPrimitive·(listed primitives) entries. The six squares
  // take 6·(n² + 4n) entries (facingSquares): at n = 16, 1920 = 6·256 + 64·6, the default
  // budget exactly: n = 16 kept, all of it used
  const Geometries squares = facingSquares();
  {
    const LightBuffers buffers(squares, squares.primitives(), origin);
    ASSERT_NE(buffers.buffer(0), nullptr);
    EXPECT_EQ(buffers.buffer(0)->resolution(), 16);
    EXPECT_EQ(buffers.buffer(0)->entryCount(), 1920u);
  }
  // TC04: one entry per primitive less: 1920 > 1914, halved to 8, where 6·(64 + 32) = 576 fits
  // in 6·64 + 63·6 = 762
  {
    const LightBuffers buffers(squares, squares.primitives(), origin,
                               {.buffer = {.entriesPerPrimitive = 63}});
    ASSERT_NE(buffers.buffer(0), nullptr);
    EXPECT_EQ(buffers.buffer(0)->resolution(), 8);
    EXPECT_EQ(buffers.buffer(0)->entryCount(), 576u);
  }
  // TC05: halved as often as needed from the resolution asked for: 40 (6·1760 = 10560 entries >
  // 9600 + 384), 20 (6·480 = 2880 > 2400 + 384), 10 (6·140 = 840 <= 600 + 384)
  EXPECT_EQ(resolution(squares, {.resolution = 40}), 10);
  // =============== Boundary Values Tests ==================
  // TC11: at 8 cells a side, 576 entries against 384 + 6·entriesPerPrimitive: 32 fits exactly,
  // 31 does not, and there is no coarser grid: no buffer
  EXPECT_EQ(resolution(squares, {.entriesPerPrimitive = 32}), 8);
  EXPECT_EQ(resolution(squares, {.entriesPerPrimitive = 31}), 0);
  // TC12: a resolution asked for below 8, or halved below 8 (9 over budget: 4): no buffer
  EXPECT_EQ(resolution(few, {.resolution = 7}), 0);
  EXPECT_EQ(resolution(few, {.resolution = 1}), 0);
  EXPECT_EQ(resolution(squares, {.resolution = 9, .entriesPerPrimitive = 0}), 0);
  // TC13: resolution 1024, the largest: kept
  const Geometries one = sphereShell(1);
  EXPECT_EQ(resolution(one, {.resolution = 1024}), 1024);
  // TC14: negative or above 1024: std::invalid_argument naming the value, from the build and
  // through LightBuffers
  for (const int n : {-1, 1025, -2147483647 - 1}) {
    EXPECT_THAT(
        [&] {
          LightBuffer::build(one.primitives(), Point(0, 0, 0), FlatShapes(), {}, {.resolution = n});
        },
        ThrowsMessage<std::invalid_argument>(HasSubstr("resolution " + std::to_string(n))));
    EXPECT_THAT([&] { resolution(one, {.resolution = n}); },
                ThrowsMessage<std::invalid_argument>(HasSubstr(std::to_string(n))));
  }
}

TEST(LightBufferTests, cellsListWhatTheLightSees) {
  const Point light(1.5, -2.25, 0.75);
  const Double3 c = light.xyz();
  Random random(11);
  Geometries g;
  // Spheres 0 … 39: radius 0.5 at distance 20 from the light, in random directions.
  std::vector<Double3> directions;
  for (int i = 0; i < 40; ++i) {
    directions.push_back(random.direction());
    g.add(Sphere(Point(c + directions.back() * 20), 0.5));
  }
  const std::uint32_t tiny = g.add(Sphere(Point(c + Double3(0.005, 0, 0)), 0.002));
  const std::uint32_t around = g.add(Sphere(Point(c + Double3(0, 0, 1)), 2));  // holds the light
  const std::uint32_t floor = g.add(Plane(Point(0, c.y - 5, 0), Vector(0, -1, 0)));
  const std::uint32_t through = g.add(Plane(Point(c), Vector(0, 0, 1)));  // through the light
  const std::uint32_t tube = g.add(Tube(1, Ray(Point(c + Double3(0, 8, 0)), Vector(1, 0, 0))));
  // Two triangles 12 above the light, one the other's vertices reversed (opposite normals), and
  // one in the plane y = c.y through the light.
  const Point a(c + Double3(-2, 12, -2)), b(c + Double3(3, 12, -1)), d(c + Double3(0, 12, 3));
  const std::uint32_t front = g.add(Triangle(a, b, d));
  const std::uint32_t back = g.add(Triangle(a, d, b));
  const std::uint32_t edgeOn = g.add(Triangle(
      Point(c + Double3(5, 0, -1)), Point(c + Double3(5, 0, 1)), Point(c + Double3(7, 0, 0))));
  const std::uint32_t cylinder =
      g.add(Cylinder(0.5, Ray(Point(c + Double3(0, 0, -15)), Vector(0, 0, -1)), 2));
  const LightBuffers buffers(g, g.primitives(),
                             std::vector<LightSource>{PointLight(Color(1, 1, 1), light)});
  const LightBuffer* lb = buffers.buffer(0);
  ASSERT_NE(lb, nullptr);
  // 46 bounded primitives (2·46 <= 16²): 16 cells a side. The scene's size S, the largest
  // coordinate of the boxes, is between 20.5 − 2.25 and 20.5 + 2.25 (the spheres' boxes reach
  // 20.5 from the light, whose coordinates are at most 2.25), the boxes' farthest corner E at
  // least 20.5 from the light, and R0 = min(S, E)/1000: the tiny sphere's box (within 0.007 of
  // the light) is within R0.
  EXPECT_EQ(lb->resolution(), 16);
  const double r0 = lb->nearRadius();
  ASSERT_GE(r0, 0.01825);
  ASSERT_LE(r0, 0.02275 * (1 + 1e-6));
  // ============ Equivalence Partitions Tests ==============
  // TC01: each sphere is listed, as a sphere, in the cell of its direction from the light, at a
  // distance between its box's (at least 20 − 0.5·√3) and its own (19.5); not in the cell of
  // the opposite direction (its box is behind the light on that face's axis)
  for (std::uint32_t i = 0; i < 40; ++i) {
    const auto [face, col, row] = lb->cellOf(directions[i]);
    const LightBuffer::Entry* e = entryOf(lb->cell(face, col, row), i);
    ASSERT_NE(e, nullptr) << "sphere " << i;
    EXPECT_TRUE(e->flags() & LightBuffer::SPHERE);
    EXPECT_LE(e->distance, 19.5f);
    EXPECT_GE(e->distance, (20 - 0.5 * std::sqrt(3.0)) * (1 - 1e-6));
    const auto [oface, ocol, orow] = lb->cellOf(-directions[i]);
    EXPECT_EQ(entryOf(lb->cell(oface, ocol, orow), i), nullptr) << "sphere " << i;
  }
  // TC02: each cell's list sorted by distance (the query stops at the first beyond its reach)
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const auto list = lb->cell(face, i, j);
        EXPECT_TRUE(
            std::is_sorted(list.begin(), list.end(),
                           [](const auto& x, const auto& y) { return x.distance < y.distance; }))
            << face << " " << i << " " << j;
      }
  // TC03: the two facing triangles are flat entries in the cell straight above the light, one
  // of them BACK (its normal away from the light); the triangle whose plane holds the light and
  // the cylinder are tested with their own solvers (neither SPHERE nor FLAT)
  // (A flat entry numbers its shape's record: the flat shapes in their order, front 0, back 1.)
  const auto [upFace, upI, upJ] = lb->cellOf(Double3(0, 1, 0));
  std::vector<std::uint32_t> flatRecords;
  for (const LightBuffer::Entry& e : lb->cell(upFace, upI, upJ)) {
    if (!(e.flags() & LightBuffer::FLAT)) continue;
    flatRecords.push_back(e.index());
    const Triangle& t = std::get<Triangle>(g[e.index() == 0 ? front : back]);
    const bool away = t.plane().normal().xyz().dot(c - a.xyz()) < 0;
    EXPECT_EQ((e.flags() & LightBuffer::BACK) != 0, away) << "record " << e.index();
  }
  std::sort(flatRecords.begin(), flatRecords.end());
  EXPECT_EQ(flatRecords, (std::vector<std::uint32_t>{0, 1}));
  const auto [eFace, eI, eJ] = lb->cellOf(Double3(1, 0, 0));
  const LightBuffer::Entry* e = entryOf(lb->cell(eFace, eI, eJ), edgeOn);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->flags() & (LightBuffer::SPHERE | LightBuffer::FLAT), 0u);
  const auto [cFace, cI, cJ] = lb->cellOf(Double3(0, 0, -1));
  const LightBuffer::Entry* ce = entryOf(lb->cell(cFace, cI, cJ), cylinder);
  ASSERT_NE(ce, nullptr);
  EXPECT_EQ(ce->flags() & (LightBuffer::SPHERE | LightBuffer::FLAT), 0u);
  // TC04: the near list: the tiny sphere within R0, the sphere around the light (distance 0),
  // the plane through the light, the tube (unbounded, not a plane: at least 7 − 1 − rounding)
  const auto near = lb->nearList();
  EXPECT_EQ(near.size(), 4u);
  ASSERT_NE(entryOf(near, tiny), nullptr);
  EXPECT_LE(entryOf(near, tiny)->distance, r0);
  ASSERT_NE(entryOf(near, around), nullptr);
  EXPECT_EQ(entryOf(near, around)->distance, 0.0f);
  ASSERT_NE(entryOf(near, through), nullptr);
  ASSERT_NE(entryOf(near, tube), nullptr);
  EXPECT_LE(entryOf(near, tube)->distance, 7.0f);
  EXPECT_GE(entryOf(near, tube)->distance, 7 * (1 - 1e-6));
  // TC05: the plane y = c.y − 5, given with its normal down, is kept with the normal towards
  // the light, (0, 1, 0), and offset n·q = c.y − 5
  ASSERT_EQ(lb->planes().size(), 1u);
  const LightBuffer::PlaneEntry& plane = lb->planes()[0];
  EXPECT_EQ(plane.primitive, floor);
  EXPECT_EQ(plane.normal.x, 0.0);
  EXPECT_EQ(plane.normal.y, 1.0);
  EXPECT_EQ(plane.normal.z, 0.0);
  EXPECT_EQ(plane.offset, c.y - 5);
  EXPECT_GT(plane.normal.dot(c) - plane.offset, 0.0);
  // The near primitives and the plane are in no cell.
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i)
        for (const std::uint32_t p : {tiny, around, floor, through, tube})
          EXPECT_EQ(entryOf(lb->cell(face, i, j), p), nullptr) << p;
  // =============== Boundary Values Tests ==================
  // TC11: the axes' directions fall in the middle of their faces: (u, v) = (0, 0), at the corner
  // of cells 8 and 8 (16 a side, face = 2·axis + negative)
  EXPECT_EQ(lb->cellOf(Double3(1, 0, 0)), (std::array<int, 3>{0, 8, 8}));
  EXPECT_EQ(lb->cellOf(Double3(-1, 0, 0)), (std::array<int, 3>{1, 8, 8}));
  EXPECT_EQ(lb->cellOf(Double3(0, 0, -1)), (std::array<int, 3>{5, 8, 8}));
  // TC12: on the cube's edges and corners the first axis wins (x before y before z); u = 1 is
  // in the last cell and −1 in the first (the face reaches ±1.001: 8 ± 8/1.001 = 15.99, 0.008)
  EXPECT_EQ(lb->cellOf(Double3(1, 1, 0)), (std::array<int, 3>{0, 15, 8}));
  EXPECT_EQ(lb->cellOf(Double3(-1, 1, -1)), (std::array<int, 3>{1, 15, 0}));
  EXPECT_EQ(lb->cellOf(Double3(0, -1, 1)), (std::array<int, 3>{3, 15, 8}));
  EXPECT_EQ(lb->cellOf(Double3(1, 1, 1)), (std::array<int, 3>{0, 15, 15}));
}

TEST(LightBufferTests, shadowRaysAllocateNothing) {
  // TC01: every kind of shadow ray (taken by the buffers or walked) through crossingsTowards,
  // LightBuffer::forEachHit and the shadow query, over the list and over the wide BVH
  const LitScene scene = mixedScene(73);
  const LightBuffers plain(scene.geometries, scene.geometries.primitives(), scene.lights);
  const std::unique_ptr<Intersectable> made =
      makeAcceleration("bvh4", scene.geometries, scene.lights, true);
  const auto& wide = dynamic_cast<const LightBuffers&>(*made);
  const std::vector<double> r0{plain.buffer(0)->nearRadius(), plain.buffer(1)->nearRadius()};
  Random random(12);
  std::vector<Ray> primaries;
  for (const test::Query& q : test::randomQueries(random, 150, kBox)) primaries.push_back(q.ray);
  const std::vector<ShadowRay> rays = shadowRays(scene, r0, primaries, random);
  const double cutOff = PhongTracer::MIN_CALC_COLOR_K;
  const ShadowQuery viaList(plain, scene, cutOff), viaWide(wide, scene, cutOff);
  int crossings = 0, visits = 0, taken = 0;
  const long allocations = testing::allocationsDuring([&] {
    for (const ShadowRay& r : rays) {
      for (const LightBuffers* buffers : {&plain, &wide}) {
        ShadowCrossings gathered(scene, 0, true, r.tMin, Double3::ONE);
        QueryCounts counts;
        buffers->crossingsTowards(r.light, r.ray, r.tMin, r.tMax, gathered, &counts);
        crossings += gathered.count();
        std::uint64_t tests = 0, certified = 0;
        if (buffers->buffer(r.light)->forEachHit(
                r.ray, r.tMin, r.tMax, [&visits](const Hit&) { return ++visits > 0; }, tests,
                certified))
          ++taken;
      }
      const Double3 weight(0.5);
      crossings += viaList(r.ray, r.tMin, r.tMax, weight, nullptr, r.light).crossings;
      crossings += viaWide(r.ray, r.tMin, r.tMax, weight, nullptr, r.light).crossings;
    }
  });
  EXPECT_EQ(allocations, 0);
  // The work was done: many crossings and visits, most rays taken by the buffers.
  EXPECT_GT(crossings, static_cast<int>(rays.size()));
  EXPECT_GT(visits, static_cast<int>(rays.size()) / 2);
  EXPECT_GT(taken, static_cast<int>(rays.size()));  // of 2 per ray
}

TEST(LightBufferTests, glassCrossingsAreCertified) {
  // TC01: the galaxy's shadow rays from the camera's hits (64 x 36) to its spot lights and to a
  // point light inside the glass box: what share of the flat shapes' crossings (the glass box,
  // the frame, the pedestal: polygons) the buffers decide without their solver
  const GalaxySetup g = smallGalaxy();
  const LitScene& scene = g.scene;
  const LightBuffers buffers(scene.geometries, scene.geometries.primitives(), scene.lights);
  const Camera camera = g.camera.builder().build();
  std::uint64_t tests = 0, certified = 0;
  int flatCrossings = 0, rays = 0;
  for (int i = 0; i < 36; ++i)
    for (int j = 0; j < 64; ++j) {
      const Ray primary = camera.constructRay(64, 36, j, i);
      const std::optional<Hit> hit = scene.geometries.closestHit(primary);
      if (!hit) continue;
      const Point p = primary.point(hit->t);
      const Vector n = scene.geometries.hitNormal(hit->geometry, p, -primary.direction());
      for (std::uint32_t k = 0; k < scene.lights.size(); ++k) {
        std::vector<ShadowRay> one;
        addShadowRay(one, scene, k, p, n, buffers.buffer(k)->nearRadius());
        for (const ShadowRay& r : one) {
          ++rays;
          const auto done = buffers.buffer(k)->forEachHit(
              r.ray, r.tMin, r.tMax,
              [&](const Hit& h) {
                if (h.t >= r.tMin && h.geometry < scene.geometries.size() &&
                    FlatShapes::isFlat(scene.geometries[h.geometry]))
                  ++flatCrossings;
                return true;
              },
              tests, certified);
          EXPECT_TRUE(done.has_value());
        }
      }
    }
  // Most pixels look at the glass box, so most shadow rays cross one or two of its faces (25 by
  // 11, and 22 by 11): far from the faces' edges and from the rays' origins compared with the
  // certainty margins (10^-3 of the scene's size S of about 30: 0.03), so that most of these
  // crossings are certified; those near an edge or a corner of the frame and the pedestal, or
  // in a cell that straddles an edge, go to the solver. Certified crossings are at least half
  // of the flat crossings met, and at least half of the flat entries decided (each certified or
  // solved: tests, which also counts the spheres solved, is more than the flat ones).
  ASSERT_GT(flatCrossings, rays / 2);
  EXPECT_GT(2 * certified, static_cast<std::uint64_t>(flatCrossings));
  EXPECT_GT(certified, tests);
  RecordProperty("rays", rays);
  RecordProperty("tests", std::to_string(tests));
  RecordProperty("certified", std::to_string(certified));
  RecordProperty("flat crossings", flatCrossings);
}

/// The first pixel whose bits differ, as "x,y", or "" when the images are the same bits.
std::string firstDifference(const Image& a, const Image& b) {
  for (int y = 0; y < a.nY(); ++y)
    for (int x = 0; x < a.nX(); ++x)
      if (!sameBits(a.pixel(x, y).rgb(), b.pixel(x, y).rgb()))
        return std::to_string(x) + "," + std::to_string(y);
  return "";
}

TEST(LightBufferTests, galaxyImageIsTheSameBits) {
  // TC01: the galaxy (7 arms of 12 stars, its glass's beams of 2 x 2 cells) from its main view
  // at 32 x 18, one ray per pixel, through the default acceleration with and without light
  // buffers: the same image, bit for bit, and the same rays; with buffers the shadow rays
  // visit no node of the tree
  GalaxySetup g = galaxy(GalaxyParams{.arms = 7, .perArm = 12});
  for (Appearance& a : g.scene.appearances)
    if (a.material.refractedBeam.isBeam())
      a.material.reflectedBeam = a.material.refractedBeam =
          BeamSettings{.distance = 12, .radius = 0.3, .grid = 2};
  CameraSpec view = g.camera;
  view.nX = 32;
  view.nY = 18;
  const Camera camera = view.builder().build();
  const Geometries& shapes = g.scene.geometries;
  const std::unique_ptr<Intersectable> walked =
      makeAcceleration(DEFAULT_ACCELERATION, shapes, g.scene.lights, false);
  const std::unique_ptr<Intersectable> buffered =
      makeAcceleration(DEFAULT_ACCELERATION, shapes, g.scene.lights, true);
  const auto* buffers = dynamic_cast<const LightBuffers*>(buffered.get());
  ASSERT_NE(buffers, nullptr);
  for (std::uint32_t k = 0; k < 3; ++k) ASSERT_NE(buffers->buffer(k), nullptr) << k;
  const BeamTracer plainTracer(g.scene, walked.get()), bufferedTracer(g.scene, buffered.get());
  const CenterSampler sampler;
  const PixelBlock all{0, 0, 32, 18};
  Image plainImage(32, 18), bufferedImage(32, 18);
  const RayCounts plainCounts = renderBlock({camera, plainTracer, sampler}, all, plainImage);
  const RayCounts bufferedCounts =
      renderBlock({camera, bufferedTracer, sampler}, all, bufferedImage);
  EXPECT_EQ(firstDifference(plainImage, bufferedImage), "");
  EXPECT_EQ(bufferedCounts.primary, plainCounts.primary);
  EXPECT_EQ(bufferedCounts.secondary, plainCounts.secondary);
  EXPECT_EQ(bufferedCounts.shadow, plainCounts.shadow);
  // Not vacuous: many shadow rays, taken by the buffers (the closest hits visit the same nodes
  // either way, the shadow rays the buffers take none), and a lit image.
  EXPECT_GT(plainCounts.shadow, 1000u);
  EXPECT_LT(bufferedCounts.queries.nodesVisited, plainCounts.queries.nodesVisited);
  int lit = 0;
  for (int y = 0; y < 18; ++y)
    for (int x = 0; x < 32; ++x) lit += plainImage.pixel(x, y).rgb().isExactlyZero() ? 0 : 1;
  EXPECT_EQ(lit, 32 * 18);
}

}  // namespace
}  // namespace rt
