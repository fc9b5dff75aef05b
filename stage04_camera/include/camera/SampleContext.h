#pragma once
/// @file SampleContext.h
/// What a tracer is told about the sample it computes, besides the ray: which pixel, which of
/// the pixel's samples, that sample's random numbers, and where to count the rays it casts.
///
/// Nori hands its integrator a sampler (Li(scene, sampler, ray)) and pbrt-v4 starts every pixel
/// sample explicitly (StartPixelSample(pixel, sampleIndex)); this is the same seam. The random
/// numbers are a pure function of (seed, pixel, sample, dimension) (primitives/Random.h), so a
/// sample gives the same colour whoever computes it, in whatever order, on whatever thread. The
/// counts belong to one thread (one block of pixels at a time) and are added up once per block:
/// nothing is shared, nothing is atomic, per ray.

#include <cstdint>

#include "intersections/Intersectable.h"
#include "primitives/Random.h"

namespace rt {

/// Rays cast and what their queries cost, for one block of pixels (or a whole render, once the
/// blocks' counts are added up).
struct RayCounts {
  std::uint64_t primary = 0;    ///< camera rays
  std::uint64_t secondary = 0;  ///< reflected and refracted rays
  std::uint64_t shadow = 0;     ///< shadow rays (towards a light)
  QueryCounts queries;          ///< the intersection tests all of them made

  RayCounts& operator+=(const RayCounts& o) noexcept {
    primary += o.primary;
    secondary += o.secondary;
    shadow += o.shadow;
    queries += o.queries;
    return *this;
  }
  /// Every ray: primary + secondary + shadow.
  std::uint64_t total() const noexcept { return primary + secondary + shadow; }
  bool operator==(const RayCounts&) const = default;
};

struct SampleContext {
  int x = 0, y = 0;          ///< the pixel: column, row
  std::uint32_t sample = 0;  ///< the sample's index within its pixel
  RandomStream random;       ///< this sample's numbers: RandomStream(seed, x, y, sample)
  RayCounts& counts;         ///< where the tracer counts the rays it casts

  /// The context of sample `sample` of pixel (x, y) for a render with the given seed.
  SampleContext(int px, int py, std::uint32_t sampleIndex, std::uint64_t seed,
                RayCounts& rayCounts) noexcept
      : x(px),
        y(py),
        sample(sampleIndex),
        random(seed, static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py), sampleIndex),
        counts(rayCounts) {}
};

}  // namespace rt
