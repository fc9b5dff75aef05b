#include "parallel/TilePool.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "camera/Camera.h"
#include "parallel/TileGrid.h"

namespace rt {

namespace {

/// What the threads of one render share. The counter and the failure flag are touched once per
/// tile (or row) by every thread: each gets a cache line of its own, so the line that holds the
/// read-only references is not invalidated by every tile taken.
struct Shared {
  const RenderContext& context;
  Image& image;
  const TileGrid& grid;
  const std::atomic<bool>* stop;
  std::atomic<std::uint64_t>* donePixels;
  std::atomic<std::uint64_t>* doneRays;

  alignas(64) std::atomic<std::uint64_t> nextTile{0};
  alignas(64) std::atomic<bool> failed{false};
  std::mutex errorMutex{};
  std::exception_ptr error{};  ///< the first exception thrown by a thread (guarded by errorMutex)

  /// Relaxed loads: a raised flag needs no other data to travel with it, and it is seen within
  /// a row or so (the threads are joined before anything they wrote is read).
  bool shouldStop() const noexcept {
    return failed.load(std::memory_order_relaxed) ||
           (stop != nullptr && stop->load(std::memory_order_relaxed));
  }
};

/// One thread's share of the work, handed over once, when it ends.
struct WorkerResult {
  RayCounts counts;
  std::uint64_t pixels = 0;
};

/// The loop every thread runs, the calling thread included. Catches everything: an exception
/// that left a std::thread's function would call std::terminate.
void renderTiles(Shared& s, WorkerResult& result) noexcept {
  RayCounts counts;  // this thread's own: nothing is shared or atomic per ray
  std::uint64_t pixels = 0;
  try {
    // BEGIN SOLUTION: hint: renderTiles, take the next tile until none is left or a stop
    const std::uint64_t tiles = s.grid.size();
    while (!s.shouldStop()) {
      const std::uint64_t index = s.nextTile.fetch_add(1, std::memory_order_relaxed);
      if (index >= tiles) break;
      const PixelBlock tile = s.grid.tile(index);
      // Row by row, so that a stop (or another thread's failure) is seen within one row of the
      // tile instead of a whole tile; a row is tileSize pixels, so the check costs nothing.
      std::uint64_t tilePixels = 0;
      const std::uint64_t raysBefore = counts.total();
      for (int y = tile.y0; y < tile.y1; ++y) {
        if (y > tile.y0 && s.shouldStop()) break;
        const PixelBlock row{tile.x0, y, tile.x1, y + 1};
        counts += renderBlock(s.context, row, s.image);
        tilePixels += row.pixels();
      }
      pixels += tilePixels;
      if (s.donePixels != nullptr) s.donePixels->fetch_add(tilePixels, std::memory_order_relaxed);
      if (s.doneRays != nullptr)
        s.doneRays->fetch_add(counts.total() - raysBefore, std::memory_order_relaxed);
    }
    // END SOLUTION
  } catch (...) {
    {
      const std::lock_guard lock(s.errorMutex);
      if (!s.error) s.error = std::current_exception();
    }
    s.failed.store(true, std::memory_order_relaxed);
  }
  result = WorkerResult{counts, pixels};
}

/// The number of threads options ask for, checked.
int requestedThreads(int threads) {
  if (threads < 0 || threads > RenderOptions::MAX_THREADS)
    throw std::invalid_argument("renderImage: threads is " + std::to_string(threads) +
                                ", expected 0 (one per core) to " +
                                std::to_string(RenderOptions::MAX_THREADS));
  if (threads > 0) return threads;
  const unsigned cores = std::thread::hardware_concurrency();  // 0 when unknown
  return static_cast<int>(std::clamp(cores, 1u, unsigned{RenderOptions::MAX_THREADS}));
}

}  // namespace

RenderResult renderImage(const RenderContext& context, Image& image, const RenderOptions& options) {
  const Camera& camera = context.camera;
  // Everything is checked on the calling thread, before a thread is started.
  int threads = requestedThreads(options.threads);
  if (options.tileSize < 1)
    throw std::invalid_argument("renderImage: tileSize is " + std::to_string(options.tileSize) +
                                ", expected 1 or more");
  if (image.nX() != camera.nX() || image.nY() != camera.nY())
    throw std::invalid_argument("renderImage: image is " + std::to_string(image.nX()) + "x" +
                                std::to_string(image.nY()) + ", camera is " +
                                std::to_string(camera.nX()) + "x" + std::to_string(camera.nY()) +
                                ": they must match");
  const TileGrid grid(camera.nX(), camera.nY(), options.tileSize);
  // A thread without a tile would only be started and joined.
  threads =
      static_cast<int>(std::min<std::uint64_t>(static_cast<std::uint64_t>(threads), grid.size()));

  const auto start = std::chrono::steady_clock::now();
  Shared shared{context, image, grid, options.stop, options.donePixels, options.doneRays};
  std::vector<WorkerResult> results(static_cast<std::size_t>(threads));
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads - 1));
  try {
    for (int i = 1; i < threads; ++i)
      pool.emplace_back(renderTiles, std::ref(shared),
                        std::ref(results[static_cast<std::size_t>(i)]));
  } catch (...) {
    // Not started: the threads already running stop at their next row and are joined (a
    // joinable std::thread destroyed would call std::terminate); nothing is returned.
    shared.failed.store(true, std::memory_order_relaxed);
    for (std::thread& t : pool) t.join();
    throw;
  }
  renderTiles(shared, results[0]);  // the calling thread is one of the pool
  for (std::thread& t : pool) t.join();
  if (shared.error) std::rethrow_exception(shared.error);

  RenderResult result;
  for (const WorkerResult& r : results) {
    result.counts += r.counts;
    result.pixels += r.pixels;
  }
  result.interrupted = result.pixels < static_cast<std::uint64_t>(camera.nX()) * camera.nY();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.threads = threads;
  return result;
}

}  // namespace rt
