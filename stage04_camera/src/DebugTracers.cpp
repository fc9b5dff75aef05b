#include "camera/DebugTracers.h"

#include <algorithm>

namespace rt {

// The normal-map encoding: [-1, 1] onto [0, 255] per channel, c·0.5 + 0.5 then ·255. The
// components of a normalised vector may round a hair beyond ±1; below -1 would be a negative
// colour, so that side is clamped (above 1 is only a channel over 255, which the writer clamps).
Color directionColor(const Vector& unit) noexcept {
  const Double3 c = (unit.xyz() * 0.5 + Double3(0.5)) * 255.0;
  return Color::unchecked(Double3(std::max(c.x, 0.0), std::max(c.y, 0.0), std::max(c.z, 0.0)));
}

Color RaysTracer::traceRay(const Ray& ray, SampleContext&) const {
  return directionColor(ray.direction());
}

// The nearest hit, as the renderer finds it (closestHit, no list), and the normal computed for
// it alone; −direction where the normal is undefined, the fallback stage 5 shades with.
Color NormalsTracer::traceRay(const Ray& ray, SampleContext& ctx) const {
  const std::optional<Hit> hit =
      intersector_.closestHit(ray, INFINITE_DISTANCE, &ctx.counts.queries);
  if (!hit) return scene_.background;
  const Point p = ray.point(hit->t);
  return directionColor(scene_.geometries.hitNormal(hit->geometry, p, -ray.direction()));
}

// Every hit with t > 0 counted, as the course's findIntersections collects them, but through the
// walk it is built on (forEachHit), so no list is made.
Color HitsTracer::traceRay(const Ray& ray, SampleContext& ctx) const {
  std::size_t count = 0;
  intersector_.forEachHit(
      ray, INFINITE_DISTANCE,
      [&count](const Hit&) {
        ++count;
        return true;
      },
      &ctx.counts.queries);
  return colorOf(count);
}

Color HitsTracer::colorOf(std::size_t count) const noexcept {
  if (count == 0) return scene_.background;
  return PALETTE[std::min(count, PALETTE.size()) - 1];
}

}  // namespace rt
