#pragma once
/// @file RenderBlock.h
/// The render loop, apart from the camera: the camera makes rays, a pixel sampler decides which
/// rays estimate a pixel, a tracer turns each ray into a colour, and renderBlock does that for a
/// rectangle of pixels. Camera::renderImage calls it row by row; a pool of threads (the second
/// mini project) calls it on square tiles, each thread with its own counts, added up once per
/// tile (pbrt-v4's ImageTileIntegrator::Render over ParallelFor2D is the model).
///
///     renderBlock({camera, tracer, sampler}, block, image)
///       for each pixel (x, y) of block:
///         image(x, y) = sampler.pixelColor(camera, tracer, x, y, counts)
///       return counts
///
/// Blocks write disjoint pixels and share only const state (the camera, the tracer, the
/// sampler), so disjoint blocks may be rendered at the same time.

#include <cstdint>

#include "camera/Image.h"
#include "camera/RayTracer.h"
#include "camera/SampleContext.h"
#include "primitives/Color.h"
#include "primitives/Ray.h"

namespace rt {

class Camera;

/// A rectangle of pixels, half-open: columns [x0, x1), rows [y0, y1). One row, one square tile
/// or the whole image: the unit of work of renderBlock.
struct PixelBlock {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  /// How many pixels it holds.
  std::uint64_t pixels() const noexcept {
    return static_cast<std::uint64_t>(x1 - x0) * static_cast<std::uint64_t>(y1 - y0);
  }
  bool operator==(const PixelBlock&) const = default;
};

/// How a pixel's colour is estimated from camera rays: one ray through its centre here (the
/// course's), jittered, adaptive and lens samples in the first mini project. Every sample's
/// random numbers come from its SampleContext, made from (seed, pixel, sample index).
class PixelSampler {
 public:
  /// @param seed the render's seed: changing it changes the noise, nothing else.
  explicit PixelSampler(std::uint64_t seed = 0) noexcept : seed_(seed) {}
  virtual ~PixelSampler() = default;

  /// The colour of pixel (x, y). Counts its camera rays into counts.primary (the tracer counts
  /// the rays it casts). Must not allocate or throw, and must be safe to call from several
  /// threads at once.
  virtual Color pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                           RayCounts& counts) const = 0;

  /// Camera rays per pixel: exactly, or at most for an adaptive sampler.
  virtual int samplesPerPixel() const noexcept = 0;

  std::uint64_t seed() const noexcept { return seed_; }

 protected:
  /// The context of sample `sample` of pixel (x, y) in this render: its numbers are
  /// RandomStream(seed, x, y, sample), its rays are counted in counts.
  SampleContext context(int x, int y, std::uint32_t sample, RayCounts& counts) const noexcept {
    return SampleContext(x, y, sample, seed_, counts);
  }
  /// Traces the sample ctx: the camera ray through the image point (px, py) — with a lens point
  /// drawn from the sample's next two numbers when the camera has an aperture — counted as one
  /// primary ray. A sampler that jitters the image point draws its jitter from ctx first.
  Color traceSample(const Camera& camera, const RayTracer& tracer, SampleContext& ctx, double px,
                    double py) const;
  /// The same with the lens point given (a point of the unit disk; ignored without an aperture).
  Color traceSample(const Camera& camera, const RayTracer& tracer, SampleContext& ctx, double px,
                    double py, const Sample2& lens) const;

 private:
  std::uint64_t seed_;
};

/// The course's sampling: one ray through each pixel's centre (sample 0).
class CenterSampler final : public PixelSampler {
 public:
  using PixelSampler::PixelSampler;
  Color pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                   RayCounts& counts) const override;
  int samplesPerPixel() const noexcept override { return 1; }
};

/// What every block of one render shares, read-only and from any thread: the camera that makes
/// the rays, the tracer that colours them and the sampler that chooses them per pixel. The row
/// loop of Camera::renderImage, the tile pool of the second mini project, `rt bench` and the
/// distributed renderer all take one; the three must outlive it.
struct RenderContext {
  const Camera& camera;
  const RayTracer& tracer;
  const PixelSampler& sampler;
};

/// Renders block into image: each pixel's colour by the context's sampler, with its tracer,
/// through its camera. Everything is checked once, before the first ray; then nothing allocates
/// or throws unless the tracer does.
/// @returns the block's ray counts (to be added to the render's once per block).
/// @throws std::invalid_argument when the block is empty or not inside the camera's image, or
///         image is not the camera's nX x nY.
RayCounts renderBlock(const RenderContext& context, const PixelBlock& block, Image& image);

}  // namespace rt
