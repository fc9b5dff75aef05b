#pragma once
/// @file TilePool.h
/// The parallel renderer: a small pool of std::threads that hands out square tiles of the image
/// from one atomic counter, each tile rendered by stage 4's renderBlock. The render loop stays
/// apart from the camera: the camera only makes rays, and the pool, like the camera's own row
/// loop, hands blocks of pixels to renderBlock (pbrt-v4's ImageTileIntegrator::Render over
/// ParallelFor2D is the model).
///
///     renderImage(context, image, options)
///       threads = min(options.threads, tiles); the calling thread is one of them
///       each thread, until no tile is left (or stop, or another thread failed):
///         i = nextTile++                          one atomic add per tile
///         for each row of tile(i):                the stop flag is checked between rows
///           counts += renderBlock(row)            this thread's own counts, no atomics
///         donePixels += the tile's pixels         one atomic add per tile
///       join; rethrow the first exception; add the threads' counts
///
/// The image is the same bits for any number of threads and any tile size: every random number
/// is a function of (seed, pixel, sample, dimension), never of a thread or of the order of the
/// pixels, and a pixel's colour does not depend on which tile holds it (see the README).

#include <atomic>
#include <cstdint>

#include "camera/Image.h"
#include "camera/RayTracer.h"
#include "camera/RenderBlock.h"
#include "camera/SampleContext.h"

namespace rt {

class Camera;

struct RenderOptions {
  /// The default tile side, in pixels: 1024 pixels make the per-tile costs (an atomic add, a
  /// few checks, the counts' merge) vanish, and a 400 × 400 image still has 169 tiles, enough
  /// for a thread that draws slow tiles (the galaxy's core) to be balanced by the others.
  static constexpr int DEFAULT_TILE_SIZE = 32;
  /// The most threads accepted.
  static constexpr int MAX_THREADS = 1024;

  /// Threads that render, the calling thread included: 1 renders on the calling thread and
  /// creates none; 0 means std::thread::hardware_concurrency() (1 if it is unknown). Never more
  /// threads than tiles are used.
  int threads = 0;
  /// The tiles' side in pixels (the last column and row are cut to the image).
  int tileSize = DEFAULT_TILE_SIZE;
  /// When given and raised (Ctrl-C), the threads stop before their next tile row: the tiles in
  /// flight stop within one row, no new tile is started, the result says interrupted.
  const std::atomic<bool>* stop = nullptr;
  /// When given, each tile's pixels are added to it once the tile is done (once per tile, not
  /// per pixel), for a progress display reading it from another thread.
  std::atomic<std::uint64_t>* donePixels = nullptr;
  /// When given, each tile's rays (primary, secondary and shadow) are added to it once the tile
  /// is done, for the progress display's rays per second.
  std::atomic<std::uint64_t>* doneRays = nullptr;
};

struct RenderResult {
  RayCounts counts;          ///< the rays of every pixel rendered, all threads added up
  std::uint64_t pixels = 0;  ///< pixels rendered: all of them unless interrupted
  bool interrupted = false;  ///< stopped by options.stop before every pixel was rendered
  double seconds = 0;        ///< wall time of the render, threads started and joined included
  int threads = 1;           ///< threads that rendered, the calling thread included
};

/// Renders every pixel of image with context's sampler and tracer through its camera, on
/// options.threads threads.
///
/// - Stop: an interrupted render returns with interrupted = true and the pixels it rendered
///   (the others keep their old values); nothing else is done.
/// - Exceptions: the renderer never throws per ray, but a tracer or sampler may; the first
///   exception thrown by any thread is rethrown here, after the other threads have stopped at
///   their next tile row and every thread has been joined. A failure to start a thread is
///   handled the same way. A render that throws returns nothing.
/// - The camera, tracer and sampler are shared by the threads: they must be safe to call from
///   several threads at once (RayTracer's and PixelSampler's contract). Each thread writes only
///   its tiles' pixels of image.
///
/// @throws std::invalid_argument, naming the value, for threads outside 0..MAX_THREADS,
///         tileSize < 1, or an image that is not the camera's nX × nY; whatever the tracer or
///         the sampler throws; std::system_error when a thread cannot be started.
RenderResult renderImage(const RenderContext& context, Image& image,
                         const RenderOptions& options = {});

}  // namespace rt
