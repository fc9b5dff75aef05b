#pragma once
/// @file Concurrently.h
/// The BVH build's one way of using more than one thread: a few jobs at once, each on a thread
/// of its own, joined before the caller goes on. (Builds are rare and short: a thread started
/// per job costs tens of microseconds, nothing beside a pass over a million primitives.)

#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace rt::build {

/// Calls job(k) for k = 0 .. jobs − 1 at once: job 0 on the calling thread, every other job on a
/// thread of its own. A job whose thread cannot be started (std::system_error: no more threads
/// to be had) runs on the calling thread after job 0. Returns when every job has returned; the
/// first exception a job threw (std::bad_alloc on a huge scene) is then thrown again. A job that
/// must stop the others early when one fails says so itself (see Builder::runTasks).
template <typename Job>
void concurrently(int jobs, const Job& job) {
  std::mutex failure;
  std::exception_ptr error;
  auto run = [&](int k) noexcept {
    try {
      job(k);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  helpers.reserve(jobs > 1 ? static_cast<std::size_t>(jobs - 1) : 0);
  int started = 1;
  try {
    for (; started < jobs; ++started) helpers.emplace_back(run, started);
  } catch (const std::system_error&) {
    // The jobs not started run below, on this thread.
  }
  run(0);
  for (int k = started; k < jobs; ++k) run(k);
  for (std::thread& h : helpers) h.join();
  if (error) std::rethrow_exception(error);
}

/// The fewest items a chunk of its own is worth: below that, a thread's start costs more than
/// the chunk's work (a box or a sphere copied per item).
inline constexpr std::size_t MIN_CHUNK = 16384;

/// How many chunks `count` items are cut into on up to `threads` threads: one per MIN_CHUNK
/// items, at least one, at most `threads`.
constexpr int chunkCount(std::size_t count, int threads) noexcept {
  const std::size_t most = threads > 1 ? static_cast<std::size_t>(threads) : 1;
  const std::size_t chunks = count / MIN_CHUNK;
  return static_cast<int>(chunks < 1 ? 1 : chunks > most ? most : chunks);
}

/// Where chunk k of `chunks` consecutive chunks of [0, count) begins (chunk k ends where chunk
/// k + 1 begins; chunk `chunks` begins at count): the chunks' sizes differ by at most one.
constexpr std::size_t chunkBegin(std::size_t count, int chunks, int k) noexcept {
  return count / static_cast<std::size_t>(chunks) * static_cast<std::size_t>(k) +
         count % static_cast<std::size_t>(chunks) * static_cast<std::size_t>(k) /
             static_cast<std::size_t>(chunks);
}

}  // namespace rt::build
