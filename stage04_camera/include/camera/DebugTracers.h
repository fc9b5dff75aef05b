#pragma once
/// @file DebugTracers.h
/// Three debugging views: tracers that show what stages 1 to 3 compute, through this stage's
/// camera. They are tools given to students (no solution regions), for the day a stage-2 normal
/// or a stage-3 root is wrong and the tests alone do not say where:
///
///   rays     the ray's unit direction as a colour: the camera's rays (stage 1's Vector and Ray)
///   normals  the nearest hit's outward unit normal as a colour (stage 2's normals)
///   hits     how many times the ray crosses the shapes, as a palette colour (stage 3's roots)
///
/// Like every tracer they allocate nothing and never throw per ray.

#include <array>
#include <cstddef>

#include "camera/RayTracer.h"
#include "primitives/Vector.h"

namespace rt {

/// A unit vector as a colour, the usual normal-map encoding: each component c in [-1, 1] becomes
/// (c·0.5 + 0.5)·255, so (0,0,1) is (127.5, 127.5, 255) and (-1,0,0) is (0, 127.5, 127.5). A
/// component a rounding below -1 is taken as -1 (a colour is never negative).
Color directionColor(const Vector& unit) noexcept;

/// The ray's own unit direction as a colour (directionColor); the scene is not looked at. On a
/// camera's rays it shows the view frame: x (vRight) in red, y (vUp) in green, z in blue.
class RaysTracer : public RayTracer {
 public:
  using RayTracer::RayTracer;
  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override;
};

/// The nearest hit's outward unit normal as a colour (directionColor: stage 2's normalAt, or
/// −direction where it is undefined, as stage 5 shades); the background where the ray misses.
/// A flat shape shows the normal of its winding, also when it faces away from the camera.
class NormalsTracer : public RayTracer {
 public:
  using RayTracer::RayTracer;
  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override;
};

/// How many times the ray crosses the shapes: every hit with t > 0, as many as the course's
/// findIntersections returns (a sphere 2, a plane 1, overlaps adding up), as a colour of
/// PALETTE; the background for none.
class HitsTracer : public RayTracer {
 public:
  /// The colours of 1, 2, 3 and 4 or more hits: blue, green, yellow, red.
  static constexpr std::array<Color, 4> PALETTE = {
      Color::unchecked(Double3(40, 90, 230)), Color::unchecked(Double3(40, 190, 70)),
      Color::unchecked(Double3(250, 210, 40)), Color::unchecked(Double3(230, 40, 40))};

  using RayTracer::RayTracer;
  using RayTracer::traceRay;
  Color traceRay(const Ray& ray, SampleContext& ctx) const override;

  /// The colour of a count: the background for 0, else PALETTE[min(count, 4) − 1].
  Color colorOf(std::size_t count) const noexcept;
};

}  // namespace rt
