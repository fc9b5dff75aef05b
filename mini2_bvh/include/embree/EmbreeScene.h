#pragma once
/// @file EmbreeScene.h
/// Intel's Embree 3 behind the course's Intersectable: a measuring stick for the project's own
/// structures (`rt bench`'s row "Embree 3"), not a renderer option (no --accel names it). Built
/// only where CMake finds Embree (libembree-dev; RT_HAVE_EMBREE=1).
///
/// What goes where:
/// - spheres: Embree's native RTC_GEOMETRY_TYPE_SPHERE_POINT (centre and radius in float);
/// - triangles (the shapes and every triangle of the meshes): RTC_GEOMETRY_TYPE_TRIANGLE;
/// - polygons of four vertices: RTC_GEOMETRY_TYPE_QUAD;
/// - every other bounded shape (polygons of five or more vertices, cylinders):
///   RTC_GEOMETRY_TYPE_USER, its box the project's conservative one (bvh/FloatBox.h), its
///   intersection the project's own exact test (stage 3's intersectRoots, in double);
/// - planes, tubes and shapes beyond the float range have no box: they stay outside Embree and
///   are tested one by one first (bvh/UnboundedShapes.h), as the project's BVH does.
///
/// Float, and why an image through Embree is not always the project's, bit for bit: Embree tests
/// its boxes and its native primitives in float. Every candidate it finds is checked with the
/// project's exact test (in double), and the closest-hit query keeps the smallest exact
/// (t, index) pair among the candidates, as the project's rule says (NearestHit); the t it
/// returns, the t the tracer shades with, is always the project's own. Two things stay float:
/// - which primitives Embree offers at all: a ray that grazes a sphere's rim or a triangle's or
///   quad's edge can miss it in float and hit it in double (a hit the other way round is
///   refused by the exact test), and then another primitive, or none, is found;
/// - the order in which Embree culls: after a hit, it drops every primitive whose float t lies
///   beyond the ray's far end. The far end is set a margin beyond the best exact t (2^-16 of the
///   coordinates' size, hundreds of float ulps), so that a face shared by two shapes, hit at the
///   same exact t but at float t's a few ulps apart, still reaches the exact comparison and the
///   smaller index wins; a float error beyond that margin would lose a nearer primitive.
/// So a few pixels can differ from the project's image (on the galaxies the tests and the bench
/// measure, none did: see mini2_bvh/README.md); the project's own structures never differ (the
/// rule of mini project 2).
///
/// Queries allocate nothing: a query's state lives on the caller's stack and travels to Embree's
/// callbacks through the intersection context. closestHit calls rtcIntersect1 with a context
/// filter that tests each native candidate exactly and accepts it only when its exact pair beats
/// the best so far; forEachHit calls rtcOccluded1 with a filter that visits the exact hits of
/// each candidate and rejects it (so the walk goes on), or accepts it, ending the walk, when
/// visit says stop. A sphere is reported by Embree once per side (entry, exit): each report
/// visits the exact root of that side. A quad's two triangles can both report a ray through its
/// diagonal: the query remembers the quads it visited (up to QUAD_MEMORY of them; beyond, a
/// diagonal hit could be visited twice).
///
/// Threads: one RTCDevice per scene, made with one build thread, so that Embree starts no
/// worker threads and builds the same tree every time; rtcIntersect1 and rtcOccluded1 on the
/// committed scene are safe from many threads at once (the tile pool's). Counts: the exact tests
/// made (Embree does not report its nodes: nodesVisited stays 0).

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "intersections/Primitives.h"

namespace rt {

class EmbreeScene final : public Intersectable {
 public:
  /// Quads a forEachHit query remembers, to visit a quad once when both its halves report.
  static constexpr int QUAD_MEMORY = 32;

  /// Builds Embree's scene over the primitives, which must outlive it unchanged.
  /// @throws std::runtime_error naming Embree's error when the device or the scene fails.
  explicit EmbreeScene(Primitives primitives);
  explicit EmbreeScene(const Geometries& geometries) : EmbreeScene(geometries.primitives()) {}
  EmbreeScene(Geometries&&) = delete;  // would view a temporary
  ~EmbreeScene() override;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// The nearest hit in (0, tMax]: the smallest exact (t, index) pair among the unbounded shapes
  /// and the candidates Embree offers (found in float, each checked by the project's exact test,
  /// whose t is returned).
  std::optional<Hit> closestHit(const Ray& ray, double tMax = INFINITE_DISTANCE,
                                QueryCounts* counts = nullptr) const noexcept override;
  /// Every hit in (0, tMax] of every primitive Embree finds, with the exact t; stops when visit
  /// says so.
  bool forEachHit(const Ray& ray, double tMax, HitVisitor visit,
                  QueryCounts* counts = nullptr) const override;

  /// How many primitives went to each of Embree's geometries, and how many stayed outside.
  struct Census {
    std::uint32_t spheres = 0, triangles = 0, quads = 0, user = 0, unbounded = 0;
  };
  Census census() const noexcept;

  /// Embree's version, "3.13.5".
  static const char* version() noexcept;

  struct Impl;  ///< the Embree objects and the primitive tables (EmbreeScene.cpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace rt
