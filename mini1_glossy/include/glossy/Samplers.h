#pragma once
/// @file Samplers.h
/// The super-sampling choices of the first mini project, as pixel samplers (stage 4's seam):
/// anti-aliasing with a jittered grid, depth of field with lens samples, and adaptive
/// super-sampling. Every sample's numbers come from its own SampleContext (seed, pixel, sample
/// index), so a pixel is the same whoever renders it, alone or in a tile of any thread.

#include <cstdint>
#include <memory>

#include "camera/RenderBlock.h"

namespace rt {

/// Anti-aliasing and depth of field: the pixel is cut into an N × N grid of cells, one sample
/// jittered in each (stratified sampling); with a camera aperture each cell's ray is traced
/// through L points of the lens. N = L = 1 is the course's one ray through the centre.
///
///     sample index  s = (j·N + i)·L + l       cell (i, j), lens sample l
///     image point   (x + (i + U)/N, y + (j + V)/N)  (the centre x + ½, y + ½ when N = 1)
///     lens point    the concentric disk image of ((l + ½)/L + δu, l·φ⁻¹ + δv) mod 1: a Fibonacci
///                   lattice with one random shift δ per cell, so the L points are spread evenly
///                   over the lens whatever L is
class JitteredSampler final : public PixelSampler {
 public:
  /// The most cells per side, and lens samples per cell.
  static constexpr int MAX_GRID = 64, MAX_LENS_SAMPLES = 1024;

  /// @throws std::invalid_argument for a grid outside 1..MAX_GRID or lens samples outside
  ///         1..MAX_LENS_SAMPLES.
  JitteredSampler(int grid, int lensSamples = 1, std::uint64_t seed = 0);

  Color pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                   RayCounts& counts) const override;
  int samplesPerPixel() const noexcept override { return grid_ * grid_ * lensSamples_; }

 private:
  int grid_, lensSamples_;
};

/// Adaptive super-sampling: trace the pixel's four corners; where they differ from their mean by
/// more than the threshold (in any channel, on the 0–255 scale), cut the square into four and
/// trace the five new points (the edges' midpoints and the centre), reusing the corners, down to
/// the depth limit. The pixel's colour is the mean of its leaves' means.
///
///     depth 0:  4 rays        a ------- b
///     depth 1:  + 5 rays      |    |    |      a, b, c, d: the corners (reused)
///     depth 2:  + 5 per       |----e----|      e: the centre, and the edges' midpoints
///               square cut    |    |    |
///                             c ------- d
///
/// Every point is a point of the pixel's lattice of (2^depthLimit + 1)² points. Each is traced at
/// most once per pixel (a point shared by two squares, a corner or an edge's midpoint, is looked
/// up, not traced again), and its sample index is its place on the lattice, so its random
/// numbers do not depend on the order of the recursion.
class AdaptiveSampler final : public PixelSampler {
 public:
  static constexpr int MAX_DEPTH = 4;

  /// @throws std::invalid_argument for a negative or non-finite threshold or a depth limit
  ///         outside 0..MAX_DEPTH.
  AdaptiveSampler(double threshold, int depthLimit, std::uint64_t seed = 0);

  Color pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                   RayCounts& counts) const override;
  /// Every square cut to the limit: the whole lattice.
  int samplesPerPixel() const noexcept override {
    const int side = (1 << depthLimit_) + 1;
    return side * side;
  }

 private:
  struct Square;
  struct Lattice;
  Double3 refine(Lattice& lattice, const Square& sq) const;

  double threshold_;
  int depthLimit_;
};

/// The choice of sampler a scene's render settings make.
struct SamplingSettings {
  int samples = 1;                ///< N: N × N jittered samples per pixel (1: the pixel's centre)
  int lensSamples = 1;            ///< rays through the lens per sample (with a camera aperture)
  bool adaptive = false;          ///< adaptive super-sampling instead of the jittered grid
  double adaptiveThreshold = 16;  ///< colour difference (0–255 scale) that makes a square split
  int adaptiveDepth = 2;          ///< the adaptive sampler's depth limit
  std::uint64_t seed = 0;         ///< changes the noise, nothing else

  bool operator==(const SamplingSettings&) const = default;
};

/// The sampler for settings: adaptive, or jittered (which is the course's centre sampler when
/// samples = lensSamples = 1). @throws std::invalid_argument for settings out of range.
std::unique_ptr<PixelSampler> makePixelSampler(const SamplingSettings& settings);

}  // namespace rt
