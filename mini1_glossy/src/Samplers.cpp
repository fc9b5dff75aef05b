#include "glossy/Samplers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "camera/Camera.h"
#include "primitives/Checks.h"

namespace rt {

namespace {

/// A dimension far beyond what a path uses, for the per-cell lens shift: read with uniform(), a
/// pure function of the cell's stream, whatever its samples draw.
constexpr std::uint32_t LENS_SHIFT_DIMENSION = 0xfffffff0u;

}  // namespace

// ---------------------------------------------------------------------------------------------
// JitteredSampler

JitteredSampler::JitteredSampler(int grid, int lensSamples, std::uint64_t seed)
    : PixelSampler(seed), grid_(grid), lensSamples_(lensSamples) {
  requireBetween(grid, 1, MAX_GRID, "JitteredSampler", "grid");
  requireBetween(lensSamples, 1, MAX_LENS_SAMPLES, "JitteredSampler", "lensSamples");
}

Color JitteredSampler::pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                                  RayCounts& counts) const {
  // BEGIN SOLUTION: hint: JitteredSampler, the mean of N x N jittered cells x lens samples
  const bool lens = camera.aperture() > 0;
  const int n = grid_, lensCount = lens ? lensSamples_ : 1;
  Double3 sum;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto cell = static_cast<std::uint32_t>((j * n + i) * lensCount);
      // One shift of the lens lattice per cell, from the cell's first sample's stream (drawn
      // only when there is a lens to sample).
      Sample2 shift{};
      if (lens) {
        const RandomStream cellStream(seed(), static_cast<std::uint32_t>(x),
                                      static_cast<std::uint32_t>(y), cell);
        shift = {cellStream.uniform(LENS_SHIFT_DIMENSION),
                 cellStream.uniform(LENS_SHIFT_DIMENSION + 1)};
      }
      for (int l = 0; l < lensCount; ++l) {
        SampleContext ctx = context(x, y, cell + static_cast<std::uint32_t>(l), counts);
        double px = x + 0.5, py = y + 0.5;
        if (n > 1) {
          const Sample2 p = jitteredCell(i, j, n, ctx.random);
          px = x + p.u;
          py = y + p.v;
        }
        const Sample2 onLens = lens ? diskLatticePoint(l, lensCount, shift) : Sample2{};
        sum = sum + traceSample(camera, tracer, ctx, px, py, onLens).rgb();
      }
    }
  }
  return Color::unchecked(sum / (n * n * lensCount));
  // END SOLUTION
}

// ---------------------------------------------------------------------------------------------
// AdaptiveSampler

/// A square of the pixel's lattice: its corner (a, b) and side, in lattice steps.
struct AdaptiveSampler::Square {
  int a, b, side;
};

/// The lattice points of one pixel traced so far (on the stack: at most 17 x 17 of them).
struct AdaptiveSampler::Lattice {
  static constexpr int MAX_SIDE = (1 << MAX_DEPTH) + 1;
  const AdaptiveSampler& sampler;
  const Camera& camera;
  const RayTracer& tracer;
  int x, y, steps;
  RayCounts& counts;
  bool traced[MAX_SIDE * MAX_SIDE] = {};
  Double3 colour[MAX_SIDE * MAX_SIDE] = {};

  /// The colour at lattice point (a, b): traced the first time it is asked for.
  const Double3& at(int a, int b) {
    const int index = b * (steps + 1) + a;
    if (!traced[index]) {
      SampleContext ctx = sampler.context(x, y, static_cast<std::uint32_t>(index), counts);
      colour[index] = sampler
                          .traceSample(camera, tracer, ctx, x + static_cast<double>(a) / steps,
                                       y + static_cast<double>(b) / steps)
                          .rgb();
      traced[index] = true;
    }
    return colour[index];
  }
};

AdaptiveSampler::AdaptiveSampler(double threshold, int depthLimit, std::uint64_t seed)
    : PixelSampler(seed), threshold_(threshold), depthLimit_(depthLimit) {
  requireNonNegative(threshold, "AdaptiveSampler", "threshold");
  requireBetween(depthLimit, 0, MAX_DEPTH, "AdaptiveSampler", "depthLimit");
}

Double3 AdaptiveSampler::refine(Lattice& lattice, const Square& sq) const {
  // BEGIN SOLUTION: hint: AdaptiveSampler::refine, the corners' mean or 4 refined quarters'
  const int a = sq.a, b = sq.b, s = sq.side;
  const Double3 c00 = lattice.at(a, b), c10 = lattice.at(a + s, b), c01 = lattice.at(a, b + s),
                c11 = lattice.at(a + s, b + s);
  const Double3 mean = (c00 + c10 + c01 + c11) / 4;
  const auto far = [&](const Double3& c) {
    const Double3 d = c - mean;
    return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > threshold_;
  };
  if (s == 1 || !(far(c00) || far(c10) || far(c01) || far(c11))) return mean;
  const int h = s / 2;
  return (refine(lattice, {a, b, h}) + refine(lattice, {a + h, b, h}) +
          refine(lattice, {a, b + h, h}) + refine(lattice, {a + h, b + h, h})) /
         4;
  // END SOLUTION
}

Color AdaptiveSampler::pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                                  RayCounts& counts) const {
  // BEGIN SOLUTION: hint: AdaptiveSampler, refine the whole pixel on its lattice
  const int steps = 1 << depthLimit_;
  Lattice lattice{*this, camera, tracer, x, y, steps, counts};
  return Color::unchecked(refine(lattice, {0, 0, steps}));
  // END SOLUTION
}

// ---------------------------------------------------------------------------------------------

std::unique_ptr<PixelSampler> makePixelSampler(const SamplingSettings& s) {
  if (s.adaptive)
    return std::make_unique<AdaptiveSampler>(s.adaptiveThreshold, s.adaptiveDepth, s.seed);
  return std::make_unique<JitteredSampler>(s.samples, s.lensSamples, s.seed);
}

}  // namespace rt
