#include "Distributed.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <thread>

#include "camera/Camera.h"
#include "camera/Image.h"
#include "cli/RenderCommand.h"
#include "parallel/TileGrid.h"
#include "parallel/TilePool.h"

namespace rt::mpi {

namespace {

constexpr int TAG_WORK = 1;     ///< a rank's result and request for the next unit
constexpr int TAG_REPLY = 100;  ///< + the asking thread's number: the next unit
constexpr std::int64_t NO_MORE = -1, STOP = -2;

enum Status : std::int32_t { RESULT = 0, FAILED = 1, STOPPED = 2 };

/// The fixed part of a rank's message; after it come the unit's pixels (3 doubles each, row by
/// row) or, for FAILED, the error's message.
struct WorkHeader {
  std::int32_t thread = 0;       ///< the asking thread: the reply's tag is TAG_REPLY + thread
  std::int32_t status = RESULT;  ///< RESULT (unit -1: the first request), FAILED, STOPPED
  std::int64_t unit = -1;        ///< the unit whose pixels follow
  std::uint64_t primary = 0, secondary = 0, shadow = 0;
};

/// The job's units: tiles of every frame in TileGrid's order, frame after frame; or whole
/// frames (a grid of one tile).
class Units {
 public:
  explicit Units(const JobSpec& spec)
      : grid_(spec.cameras.front().nX, spec.cameras.front().nY,
              spec.wholeFrames ? std::max(spec.cameras.front().nX, spec.cameras.front().nY)
                               : spec.tileSize),
        perFrame_(grid_.size()),
        frames_(spec.cameras.size()) {}
  std::uint64_t count() const noexcept { return perFrame_ * frames_; }
  int frameOf(std::uint64_t unit) const noexcept { return static_cast<int>(unit / perFrame_); }
  PixelBlock blockOf(std::uint64_t unit) const noexcept { return grid_.tile(unit % perFrame_); }
  /// The most pixels a unit has.
  std::uint64_t maxPixels() const noexcept { return grid_.tile(0).pixels(); }

 private:
  TileGrid grid_;
  std::uint64_t perFrame_, frames_;
};

void copyOut(const Image& image, const PixelBlock& b, double* out) noexcept {
  for (int y = b.y0; y < b.y1; ++y)
    for (int x = b.x0; x < b.x1; ++x) {
      const Double3& c = image.pixel(x, y).rgb();
      *out++ = c.x;
      *out++ = c.y;
      *out++ = c.z;
    }
}

void copyIn(Image& image, const PixelBlock& b, const double* in) {
  for (int y = b.y0; y < b.y1; ++y)
    for (int x = b.x0; x < b.x1; ++x, in += 3)
      image.setPixel(x, y, Color(Double3(in[0], in[1], in[2])));
}

std::string messageOf(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory while rendering";
  return e.what();
}

/// The frames' cameras (each with its image) a worker rank renders into, made when first asked
/// and dropped, oldest first, beyond `keep` (units come in increasing order, so an old frame is
/// not asked again; if it were, it would be made again).
class CameraCache {
 public:
  CameraCache(const JobSpec& spec, std::size_t keep) : spec_(spec), keep_(keep) {}
  std::shared_ptr<Camera> get(int frame) {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto it = cameras_.find(frame);
    if (it == cameras_.end()) {
      it =
          cameras_
              .emplace(frame, std::make_shared<Camera>(
                                  spec_.cameras[static_cast<std::size_t>(frame)].builder().build()))
              .first;
      while (cameras_.size() > keep_) cameras_.erase(cameras_.begin());
      it = cameras_.find(frame);
    }
    return it->second;
  }

 private:
  const JobSpec& spec_;
  std::size_t keep_;
  std::mutex mutex_;
  std::map<int, std::shared_ptr<Camera>> cameras_;
};

/// Rank 0's frames being assembled: each frame's camera and image, made when its first pixels
/// come, finished (grid lines) and written atomically when its last pixels have come, then freed.
class FrameSink {
 public:
  explicit FrameSink(const JobSpec& spec) : spec_(spec) {}
  Camera& camera(int frame) {
    const std::lock_guard<std::mutex> lock(mutex_);
    return *entry(frame).camera;
  }
  /// pixels more of frame are in its image; writes it when they were the last (unless stop).
  void delivered(int frame, std::uint64_t pixels, bool stop) {
    const std::lock_guard<std::mutex> lock(mutex_);
    Entry& e = entry(frame);
    e.left -= pixels;
    if (e.left > 0 || stop) return;
    const std::size_t i = static_cast<std::size_t>(frame);
    cli::finishImage(*e.camera, spec_.doc, spec_.gridLines, spec_.outputs[i]);
    frames_.erase(frame);
    ++written_;
  }
  int written() const noexcept { return written_; }

 private:
  struct Entry {
    std::unique_ptr<Camera> camera;
    std::uint64_t left = 0;
  };
  Entry& entry(int frame) {
    auto it = frames_.find(frame);
    if (it != frames_.end()) return it->second;
    const CameraSpec& c = spec_.cameras[static_cast<std::size_t>(frame)];
    Entry e{std::make_unique<Camera>(c.builder().build()),
            static_cast<std::uint64_t>(c.nX) * static_cast<std::uint64_t>(c.nY)};
    return frames_.emplace(frame, std::move(e)).first->second;
  }
  const JobSpec& spec_;
  std::mutex mutex_;
  std::map<int, Entry> frames_;
  int written_ = 0;
};

/// Renders block row by row into image, adding its rays to counts, so that a raised stop is seen
/// within a row (as the tile pool does) instead of a whole tile. Whether every row was rendered.
bool renderRows(const RenderContext& context, const PixelBlock& block, Image& image,
                const std::atomic<bool>& stop, RayCounts& counts) {
  for (int y = block.y0; y < block.y1; ++y) {
    if (y > block.y0 && stop.load(std::memory_order_relaxed)) return false;
    counts += renderBlock(context, PixelBlock{block.x0, y, block.x1, y + 1}, image);
  }
  return true;
}

void addCounts(WorkHeader& h, const RayCounts& c) {
  h.primary = c.primary;
  h.secondary = c.secondary;
  h.shadow = c.shadow;
}

/// A worker rank's thread: sends its last result (the first time: nothing) as the request for
/// the next unit, and renders what it is given, until rank 0 answers "no more" or "stop".
void workerLoop(const JobSpec& spec, const Units& units, CameraCache& cache, int thread,
                MPI_Comm comm) {
  std::vector<char> message(sizeof(WorkHeader) + units.maxPixels() * 3 * sizeof(double));
  WorkHeader h;
  h.thread = thread;
  std::size_t length = sizeof h;
  while (true) {
    std::memcpy(message.data(), &h, sizeof h);
    MPI_Send(message.data(), static_cast<int>(length), MPI_BYTE, 0, TAG_WORK, comm);
    std::int64_t next = STOP;
    MPI_Recv(&next, 1, MPI_INT64_T, 0, TAG_REPLY + thread, comm, MPI_STATUS_IGNORE);
    if (next < 0) return;
    h = WorkHeader{};
    h.thread = thread;
    h.unit = next;
    length = sizeof h;
    try {
      const std::uint64_t unit = static_cast<std::uint64_t>(next);
      const std::shared_ptr<Camera> camera = cache.get(units.frameOf(unit));
      const PixelBlock block = units.blockOf(unit);
      const RenderContext context{*camera, spec.tracer, spec.sampler};
      if (spec.wholeFrames) {
        RenderOptions options;
        options.threads = spec.threads;
        options.stop = &stopFlag();
        const RenderResult r = renderImage(context, camera->image(), options);
        if (r.interrupted) h.status = STOPPED;
        addCounts(h, r.counts);
      } else {
        RayCounts c;
        if (!renderRows(context, block, camera->image(), stopFlag(), c) || stopFlag().load())
          h.status = STOPPED;
        addCounts(h, c);
      }
      if (h.status == RESULT) {
        copyOut(camera->image(), block, reinterpret_cast<double*>(message.data() + sizeof h));
        length += block.pixels() * 3 * sizeof(double);
      }
    } catch (const std::exception& e) {
      h.status = FAILED;
      const std::string text = messageOf(e).substr(0, message.size() - sizeof h);
      std::memcpy(message.data() + sizeof h, text.data(), text.size());
      length = sizeof h + text.size();
    }
  }
}

}  // namespace

std::atomic<bool>& stopFlag() {
  static std::atomic<bool> flag{false};
  return flag;
}

void runWorker(const JobSpec& spec, MPI_Comm comm) {
  const Units units(spec);
  if (spec.wholeFrames || spec.threads == 1) {
    CameraCache cache(spec, 1);
    workerLoop(spec, units, cache, 0, comm);
    return;
  }
  CameraCache cache(spec, static_cast<std::size_t>(spec.threads) + 1);
  std::vector<std::thread> threads;
  for (int t = 0; t < spec.threads; ++t)
    threads.emplace_back([&, t] { workerLoop(spec, units, cache, t, comm); });
  for (std::thread& t : threads) t.join();
}

JobOutcome runDealer(const JobSpec& spec, const std::vector<std::string>& hosts,
                     const std::vector<int>& threads, std::atomic<std::uint64_t>& donePixels,
                     std::atomic<std::uint64_t>& doneRays, MPI_Comm comm) {
  const Units units(spec);
  const std::uint64_t total = units.count();
  JobOutcome outcome;
  outcome.unitsByRank.assign(threads.size(), 0);
  std::mutex mutex;  // outcome's counts, unitsByRank and failure
  std::atomic<std::uint64_t> next{0};
  std::atomic<bool> abort{false};
  const auto take = [&]() -> std::int64_t {
    if (abort.load()) return STOP;
    const std::uint64_t u = next.fetch_add(1);
    return u < total ? static_cast<std::int64_t>(u) : NO_MORE;
  };
  const auto fail = [&](int rank, const std::string& message) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!outcome.failure)
      outcome.failure = RankFailure{rank, hosts[static_cast<std::size_t>(rank)], message};
    abort.store(true);
  };
  FrameSink sink(spec);

  // Rank 0's own render threads: tiles, one per thread; or frames, each with every thread.
  const int localThreads = spec.wholeFrames ? 1 : spec.threads;
  std::atomic<int> localDone{0};
  const auto local = [&] {
    RayCounts counts;
    std::uint64_t rendered = 0;
    try {
      for (std::int64_t u; (u = take()) >= 0;) {
        const int frame = units.frameOf(static_cast<std::uint64_t>(u));
        Camera& camera = sink.camera(frame);
        const RenderContext context{camera, spec.tracer, spec.sampler};
        if (spec.wholeFrames) {
          RenderOptions options;
          options.threads = spec.threads;
          options.stop = &abort;
          options.donePixels = &donePixels;
          options.doneRays = &doneRays;
          const RenderResult r = renderImage(context, camera.image(), options);
          counts += r.counts;
          if (r.interrupted) break;
          ++rendered;
          sink.delivered(frame, r.pixels, abort.load());
        } else {
          const PixelBlock block = units.blockOf(static_cast<std::uint64_t>(u));
          RayCounts c;
          const bool whole = renderRows(context, block, camera.image(), abort, c);
          counts += c;
          if (!whole) break;
          donePixels += block.pixels();
          doneRays += c.total();
          ++rendered;
          sink.delivered(frame, block.pixels(), abort.load());
        }
      }
    } catch (const std::exception& e) {
      fail(0, messageOf(e));
    }
    {
      const std::lock_guard<std::mutex> lock(mutex);
      outcome.counts += counts;
      outcome.unitsByRank[0] += rendered;
    }
    ++localDone;
  };
  std::vector<std::thread> pool;
  try {
    for (int t = 0; t < localThreads; ++t) pool.emplace_back(local);
  } catch (const std::system_error& e) {
    fail(0, std::string("cannot start a render thread: ") + e.what());
    localDone += localThreads - static_cast<int>(pool.size());
  }

  // The other ranks' threads, each answered until it is told "no more" or "stop".
  int remote = 0;
  for (std::size_t r = 1; r < threads.size(); ++r) remote += spec.wholeFrames ? 1 : threads[r];
  std::vector<char> buffer(sizeof(WorkHeader) + units.maxPixels() * 3 * sizeof(double));
  int answered = 0;
  std::chrono::microseconds idle{50};
  while (answered < remote || localDone.load() < localThreads) {
    if (stopFlag().load() && !abort.load()) {
      const std::lock_guard<std::mutex> lock(mutex);
      outcome.interrupted = true;
      abort.store(true);
    }
    int flag = 0;
    MPI_Status status;
    if (answered < remote) MPI_Iprobe(MPI_ANY_SOURCE, TAG_WORK, comm, &flag, &status);
    if (!flag) {
      // Nothing came: sleep, longer the longer nothing comes (50 µs doubled up to 1 ms), so that
      // a busy job is answered at once and a quiet one does not wake this thread 10,000 times a
      // second beside the render threads; when only rank 0's own threads are left, 5 ms (it
      // only passes a Ctrl-C on to them).
      std::this_thread::sleep_for(answered < remote ? idle : std::chrono::microseconds(5000));
      idle = std::min(idle * 2, std::chrono::microseconds(1000));
      continue;
    }
    idle = std::chrono::microseconds(50);
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    const int source = status.MPI_SOURCE;
    MPI_Recv(buffer.data(), count, MPI_BYTE, source, TAG_WORK, comm, MPI_STATUS_IGNORE);
    WorkHeader h;
    std::memcpy(&h, buffer.data(), sizeof h);
    ++outcome.messages;
    outcome.bytes += static_cast<std::uint64_t>(count);
    if (h.status == FAILED) {
      fail(source,
           std::string(buffer.data() + sizeof h, static_cast<std::size_t>(count) - sizeof h));
    } else if (h.status == STOPPED) {
      const std::lock_guard<std::mutex> lock(mutex);
      outcome.interrupted = true;
      abort.store(true);
    } else if (h.unit >= 0) {
      const std::uint64_t unit = static_cast<std::uint64_t>(h.unit);
      const int frame = units.frameOf(unit);
      const PixelBlock block = units.blockOf(unit);
      RayCounts c;
      c.primary = h.primary;
      c.secondary = h.secondary;
      c.shadow = h.shadow;
      try {
        copyIn(sink.camera(frame).image(), block,
               reinterpret_cast<const double*>(buffer.data() + sizeof h));
        {
          const std::lock_guard<std::mutex> lock(mutex);
          outcome.counts += c;
          ++outcome.unitsByRank[static_cast<std::size_t>(source)];
        }
        donePixels += block.pixels();
        doneRays += c.total();
        sink.delivered(frame, block.pixels(), abort.load());
      } catch (const std::exception& e) {
        fail(0, messageOf(e));
      }
    }
    const std::int64_t reply = take();
    if (reply < 0) ++answered;
    MPI_Send(&reply, 1, MPI_INT64_T, source, TAG_REPLY + h.thread, comm);
    ++outcome.messages;
    outcome.bytes += sizeof reply;
  }
  for (std::thread& t : pool) t.join();
  outcome.units = std::min(next.load(), total);
  outcome.framesWritten = sink.written();
  return outcome;
}

}  // namespace rt::mpi
