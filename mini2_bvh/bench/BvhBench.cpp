// mini2_bench: how fast the three Intersectables answer closest-hit queries, side by side.
//
//   build/release/bin/mini2_bench [--sizes 1000,10000,100000,1000000] [--no-galaxy]
//                                 [--galaxy-stars N]
//
// 1. Random scenes of n spheres (uniform in a cube of side 100, radius 1.5·√(1000/n), so that a
//    ray meets about the same number of spheres whatever n), seen by a fan of 256 × 256 rays from
//    a camera in front of the cube: the build time and memory of the BVH, then for the linear
//    Geometries, the CBR and the BVH the rays per second, the boxes tested (BVH nodes, or the
//    CBR's one box per shape) and the shapes tested per ray. The linear scan and the CBR get a
//    subset of the fan (about 5·10^7 shape tests), and their answers are compared with the BVH's on
//    that subset.
// 2. The course's "glassed galaxy" (mini1's galaxy(): about 1000 stars, or N with
//    --galaxy-stars; the whole scene, then its spheres alone), with the camera and resolution of
//    the report: the 1280 × 720 primary rays.
// 3. Memory for the largest random scene, measured first: the scene, the BVH, and the build's
//    peak (the process's peak resident size, reset before the build; Linux only).
// Single-threaded; query rates are from the fastest of several passes, in the thread's CPU time.
// A timing is never a test: this prints figures, it asserts nothing.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "benchmark/Measure.h"
#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "camera/Camera.h"
#include "glossy/Galaxy.h"

#include "RandomScenes.h"

namespace rt {
namespace {

/// A field of /proc/self/status in kB ("VmRSS:", "VmHWM:"), or -1.
long statusKb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field, 0) == 0) return std::stol(line.substr(std::strlen(field)));
  return -1;
}

/// Resets the peak resident size (VmHWM) to the current one (Linux >= 4.0).
void resetPeakMemory() { std::ofstream("/proc/self/clear_refs") << "5"; }

struct Timing {
  double raysPerSecond = 0;
  double nodesPerRay = 0;
  double testsPerRay = 0;
  std::vector<std::optional<Hit>> answers;
};

/// Runs closestHit over the rays, pass after pass for at least 0.3 s and 3 passes; reports the
/// fastest pass, in thread CPU time (the machine is shared: the others measure the neighbours
/// too).
Timing timeClosestHit(const Intersectable& shapes, const std::vector<Ray>& rays) {
  Timing timing;
  timing.answers.resize(rays.size());
  QueryCounts counts;
  double best = INFINITE_DISTANCE, total = 0;
  for (int pass = 0; pass < 3 || total < 0.3; ++pass) {
    const double start = threadCpuSeconds();
    for (std::size_t i = 0; i < rays.size(); ++i)
      timing.answers[i] =
          shapes.closestHit(rays[i], INFINITE_DISTANCE, pass == 0 ? &counts : nullptr);
    const double seconds = threadCpuSeconds() - start;
    best = std::min(best, seconds);
    total += seconds;
  }
  const double n = static_cast<double>(rays.size());
  timing.raysPerSecond = n / best;
  timing.nodesPerRay = static_cast<double>(counts.nodesVisited) / n;
  timing.testsPerRay = static_cast<double>(counts.shapeTests) / n;
  return timing;
}

/// How many answers differ from the reference (which answered every k-th ray of `all`).
long mismatches(const std::vector<std::optional<Hit>>& subset,
                const std::vector<std::optional<Hit>>& all, std::size_t k) {
  long wrong = 0;
  for (std::size_t i = 0; i < subset.size(); ++i) {
    const std::optional<Hit>& a = subset[i];
    const std::optional<Hit>& b = all[i * k];
    if (a.has_value() != b.has_value() || (a && (a->t != b->t || a->geometry != b->geometry)))
      ++wrong;
  }
  return wrong;
}

/// Every k-th ray.
std::vector<Ray> everyKth(const std::vector<Ray>& rays, std::size_t k) {
  std::vector<Ray> subset;
  for (std::size_t i = 0; i < rays.size(); i += k) subset.push_back(rays[i]);
  return subset;
}

void printRow(const char* scene, const char* method, std::size_t rays, const Timing& t,
              long wrong) {
  std::printf("%-12s %-8s %9zu %12.0f %10.1f %10.1f   %s\n", scene, method, rays, t.raysPerSecond,
              t.nodesPerRay, t.testsPerRay,
              wrong < 0 ? "" : (wrong == 0 ? "same answers" : "DIFFERENT ANSWERS"));
}

/// The three methods on one scene: the BVH on every ray, the others on every k-th.
void compareMethods(const char* name, const Geometries& scene, const Bvh& bvh,
                    const std::vector<Ray>& rays, std::size_t k) {
  const Timing fast = timeClosestHit(bvh, rays);
  const std::vector<Ray> subset = everyKth(rays, k);
  const Timing linear = timeClosestHit(scene, subset);
  printRow(name, "linear", subset.size(), linear, mismatches(linear.answers, fast.answers, k));
  const Cbr cbr(scene);
  const Timing boxed = timeClosestHit(cbr, subset);
  printRow(name, "CBR", subset.size(), boxed, mismatches(boxed.answers, fast.answers, k));
  printRow(name, "BVH", rays.size(), fast, -1);
}

/// 256 × 256 rays from (0,0,-150) through the square x, y in [-50, 50] of the plane z = -50.
std::vector<Ray> cameraFan() {
  constexpr int side = 256;
  std::vector<Ray> rays;
  rays.reserve(side * side);
  const Point eye(0, 0, -150);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const Point target(-50 + 100.0 * (j + 0.5) / side, 50 - 100.0 * (i + 0.5) / side, -50);
      rays.emplace_back(eye, target - eye);
    }
  return rays;
}

Geometries randomSpheres(std::uint32_t n) {
  test::Random random(n);
  Geometries scene;
  scene.reserve(n);
  const double r = 1.5 * std::sqrt(1000.0 / n);
  test::addSpheres(scene, random, n, Aabb(Double3(-50), Double3(50)), r, r);
  return scene;
}

void randomScenes(const std::vector<std::uint32_t>& sizes) {
  std::printf("Random spheres: build\n%10s %10s %8s %8s %10s %8s\n", "spheres", "build ms", "nodes",
              "depth", "BVH MB", "B/sphere");
  for (std::uint32_t n : sizes) {
    const Geometries scene = randomSpheres(n);
    const double start = threadCpuSeconds();
    const Bvh bvh(scene);
    const double ms = 1e3 * (threadCpuSeconds() - start);
    std::printf("%10u %10.1f %8zu %8d %10.1f %8.1f\n", n, ms, bvh.nodes().size(), bvh.depth(),
                static_cast<double>(bvh.memoryBytes()) / 1e6,
                static_cast<double>(bvh.memoryBytes()) / n);
  }
  std::printf("\nRandom spheres: closest hit, 256 x 256 camera rays (one thread)\n");
  std::printf("%-12s %-8s %9s %12s %10s %10s\n", "scene", "method", "rays", "rays/s", "boxes/ray",
              "tests/ray");
  const std::vector<Ray> rays = cameraFan();
  for (std::uint32_t n : sizes) {
    const Geometries scene = randomSpheres(n);
    const Bvh bvh(scene);
    const std::size_t k = std::max<std::size_t>(1, rays.size() * n / 50'000'000);
    const std::string name = std::to_string(n);
    compareMethods(name.c_str(), scene, bvh, rays, k);
  }
}

// ---- The course's "glassed galaxy" (mini1's galaxy(), course-catalogue.md §6) ----

/// The galaxy's shapes, of about `stars` stars (0: the reference report's 50 per arm): the whole
/// scene (the floor, the pedestal, the glass box and its frame, the stars), or its spheres alone,
/// where every ray that meets no star crosses the whole galaxy.
Geometries galaxyShapes(const GalaxySetup& g, bool whole) {
  if (whole) return g.scene.geometries;
  Geometries spheres;
  for (const Geometry& shape : g.scene.geometries.shapes())
    if (std::holds_alternative<Sphere>(shape)) spheres.add(shape);
  return spheres;
}

void galaxyScene(long stars, bool whole) {
  const GalaxySetup g = galaxy(GalaxyParams{.stars = stars, .diffusion = false});
  const Geometries scene = galaxyShapes(g, whole);
  const char* name = whole ? "galaxy" : "stars";
  std::uint32_t spheres = 0;
  for (const Geometry& shape : scene.shapes()) spheres += std::holds_alternative<Sphere>(shape);
  const double buildStart = threadCpuSeconds();
  const Bvh bvh(scene);
  std::printf("\n%s: %u shapes, %u spheres; BVH built in %.2f ms, %zu nodes\n",
              whole ? "Galaxy, the whole scene" : "Galaxy, its spheres alone", scene.size(),
              spheres, 1e3 * (threadCpuSeconds() - buildStart), bvh.nodes().size());
  // The reference report's camera: from (100,27,22) at (4,8,4), 1280 x 720.
  const Camera camera = g.camera.builder().build();
  const int nX = camera.nX(), nY = camera.nY();
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(nX) * nY);
  for (int i = 0; i < nY; ++i)
    for (int j = 0; j < nX; ++j) rays.push_back(camera.constructRay(nX, nY, j, i));
  std::printf("%-12s %-8s %9s %12s %10s %10s\n", "scene", "method", "rays", "rays/s", "boxes/ray",
              "tests/ray");
  // The linear scan and the CBR on every k-th ray: about 5·10^7 shape tests.
  const std::size_t k = std::max<std::size_t>(16, rays.size() * scene.size() / 50'000'000);
  compareMethods(name, scene, bvh, rays, k);

  // The renderer's loop with a trivial shader: make the camera ray, find the closest hit, keep
  // the shape index as the "colour".
  std::uint64_t sink = 0;
  double seconds = INFINITE_DISTANCE;
  for (int pass = 0; pass < 3; ++pass) {
    const double start = threadCpuSeconds();
    for (int i = 0; i < nY; ++i)
      for (int j = 0; j < nX; ++j)
        if (const auto hit = bvh.closestHit(camera.constructRay(nX, nY, j, i)))
          sink += hit->geometry;
    seconds = std::min(seconds, threadCpuSeconds() - start);
  }
  std::printf("%s, BVH, camera ray + closest hit + trivial shader: %.0f rays/s (sink %llu)\n", name,
              nX * nY / seconds, static_cast<unsigned long long>(sink));
}

void memory(std::uint32_t n) {
  const long before = statusKb("VmRSS:");
  const Geometries scene = randomSpheres(n);
  const long withScene = statusKb("VmRSS:");
  resetPeakMemory();
  const Bvh bvh(scene);
  const long peak = statusKb("VmHWM:");
  const long after = statusKb("VmRSS:");
  if (before < 0 || peak < 0) return;
  auto perSphere = [n](long kb) { return 1024.0 * static_cast<double>(kb) / n; };
  std::printf("Memory, %u spheres (resident kB, from /proc/self/status):\n", n);
  std::printf("  scene (Geometries)   %8ld kB  %6.1f B/sphere\n", withScene - before,
              perSphere(withScene - before));
  std::printf("  BVH after the build  %8ld kB  %6.1f B/sphere (memoryBytes: %.1f B/sphere)\n",
              after - withScene, perSphere(after - withScene),
              static_cast<double>(bvh.memoryBytes()) / n);
  std::printf("  build peak           %8ld kB  %6.1f B/sphere (temporaries included)\n",
              peak - withScene, perSphere(peak - withScene));
  std::printf("  scene + BVH peak     %8ld kB\n\n", peak - before);
}

/// "1000,10000" → {1000, 10000}.
std::vector<std::uint32_t> parseSizes(const std::string& list) {
  std::vector<std::uint32_t> sizes;
  std::size_t start = 0;
  while (start < list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    sizes.push_back(static_cast<std::uint32_t>(std::stoul(list.substr(start, comma - start))));
    start = comma + 1;
  }
  return sizes;
}

}  // namespace
}  // namespace rt

int main(int argc, char** argv) {
  std::vector<std::uint32_t> sizes{1000, 10000, 100000, 1000000};
  bool galaxy = true;
  long galaxyStars = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--sizes") == 0 && i + 1 < argc) {
      sizes = rt::parseSizes(argv[++i]);
    } else if (std::strcmp(argv[i], "--no-galaxy") == 0) {
      galaxy = false;
    } else if (std::strcmp(argv[i], "--galaxy-stars") == 0 && i + 1 < argc) {
      galaxyStars = std::stol(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--sizes 1000,10000,...] [--no-galaxy] [--galaxy-stars N]\n",
                   argv[0]);
      return 2;
    }
  }
  // Memory first, while the process has freed nothing that malloc could reuse.
  if (!sizes.empty()) rt::memory(*std::max_element(sizes.begin(), sizes.end()));
  if (!sizes.empty()) rt::randomScenes(sizes);
  if (galaxy) {
    rt::galaxyScene(galaxyStars, true);
    rt::galaxyScene(galaxyStars, false);
  }
  return 0;
}
