#pragma once
/// @file TraceStats.h

#include <atomic>
#include <cstdint>

namespace rt {

/// Ray counts of a Whitted render, for tests and for explaining timings. A tracer counts into
/// it only when one is set (WhittedTracer::setStats); with none set, counting costs one
/// predictable branch per ray. Safe to share between render threads (relaxed atomics).
struct TraceStats {
  /// traceRay calls.
  std::atomic<std::uint64_t> primaryRays{0};
  /// Reflected and refracted rays cast (one per WhittedTracer::secondaryColor call: a beam that
  /// calls it once per ray counts every ray of the beam).
  std::atomic<std::uint64_t> secondaryRays{0};

  void reset() {
    primaryRays.store(0, std::memory_order_relaxed);
    secondaryRays.store(0, std::memory_order_relaxed);
  }
};

}  // namespace rt
