// mini2_packet_bench: the beams of mini project 1 traced one ray at a time and as packets,
// through the wide BVH, side by side.
//
//   build/release/bin/mini2_packet_bench [STARS]      (default 1000: the report's galaxy)
//
// The rays: for every 8th pixel of the report's 1280 x 720 view of the glassed galaxy that hits
// a shape, the beam of the glass's settings (mini1's forEachBeamRay) from that hit, as the beams
// tracer casts them: rays that share an origin and spread in a narrow cone. Each set is traced
// three ways: closestHit ray by ray; closestHits with the SSE2 lanes (two halves of four); and
// with the AVX2 lanes (eight at once, where the processor has them). The three must agree (the
// sums of the hit indices are printed); the figures are nanoseconds per ray on this thread, the
// nodes and exact tests per ray.
//
// Then the same packets inside the beams tracer: the galaxy rendered at 320 x 180 on this thread
// through the wide BVH with each beam's rays traced one by one (BeamTracerSettings::together
// false) and together (true), in turn (each first in every other pass), ten times each: the medians
// of this thread's CPU times, their ratio, and whether the two images are the same bits. A timing
// is never a test: this prints figures only.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

#include "benchmark/Measure.h"
#include "bvh/WideBvh.h"
#include "camera/Camera.h"
#include "camera/Image.h"
#include "camera/RenderBlock.h"
#include "glossy/BeamTracer.h"
#include "glossy/Galaxy.h"
#include "glossy/RayBeam.h"
#include "parallel/TilePool.h"
#include "primitives/Random.h"

namespace rt {
namespace {

bool sameBits(const Image& a, const Image& b) {
  for (int y = 0; y < a.nY(); ++y)
    for (int x = 0; x < a.nX(); ++x) {
      const Double3 p = a.pixel(x, y).rgb(), q = b.pixel(x, y).rgb();
      if (std::memcmp(&p, &q, sizeof p) != 0) return false;
    }
  return true;
}

/// The galaxy rendered by the beams tracer with its beams traced one by one and together.
int renderBothWays(const GalaxySetup& g, const WideBvh& wide) {
  const Camera camera = middleView(g.camera, 320, 180);
  const CenterSampler sampler;
  const BeamTracer oneByOne(g.scene, &wide, {}, {.together = false});
  const BeamTracer together(g.scene, &wide, {}, {.together = true});
  const BeamTracer* tracers[] = {&oneByOne, &together};
  Image images[] = {Image(camera.nX(), camera.nY()), Image(camera.nX(), camera.nY())};
  std::vector<double> seconds[2];
  for (int pass = 0; pass < 10; ++pass)  // in turn, each first in every other pass
    for (int i = 0; i < 2; ++i) {
      const int k = (pass + i) % 2;
      const double start = threadCpuSeconds();
      renderImage({camera, *tracers[k], sampler}, images[k], {.threads = 1});
      seconds[k].push_back(threadCpuSeconds() - start);
    }
  const double a = median(seconds[0]), b = median(seconds[1]);
  std::printf("\nthe beams tracer, the galaxy at 320x180 on one thread, median of 10 each:\n");
  std::printf("%-12s %10s\n%-12s %10.3f\n%-12s %10.3f\ntogether / one by one: %.3f; images: %s\n",
              "beam rays", "CPU s", "one by one", a, "together", b, b / a,
              sameBits(images[0], images[1]) ? "the same bits" : "DIFFERENT");
  return sameBits(images[0], images[1]) ? 0 : 1;
}

int run(long stars) {
  const GalaxySetup g = galaxy(GalaxyParams{.stars = stars});
  const Geometries& scene = g.scene.geometries;
  const WideBvh wide(scene);
  const Camera camera = g.camera.builder().build();
  BeamSettings beam;
  for (const Appearance& a : g.scene.appearances)
    if (a.material.refractedBeam.isBeam()) {
      beam = a.material.refractedBeam;
      break;
    }
  RandomStream random(7, 1, 2, 3);
  std::vector<std::vector<Ray>> beams;
  std::size_t total = 0;
  for (int i = 0; i < camera.nY(); i += 8)
    for (int j = 0; j < camera.nX(); j += 8) {
      const Ray ray = camera.constructRay(camera.nX(), camera.nY(), j, i);
      const std::optional<Hit> hit = wide.closestHit(ray);
      if (!hit) continue;
      const Point p = ray.point(hit->t);
      const Point start(p.xyz() + ray.direction().xyz() * 1e-6);
      std::vector<Ray>& b = beams.emplace_back();
      forEachBeamRay(ray.direction(), scene.normalAt(hit->geometry, p), beam, random,
                     [&](const Vector& d) { b.push_back(Ray::withUnitDirection(start, d)); });
      total += b.size();
    }
  std::printf("galaxy of %ld stars: %zu beams of up to %d rays (%zu rays); AVX2 %s\n", stars,
              beams.size(), beam.grid * beam.grid, total,
              WideBvh::bestSimd() == WideBvh::Simd::Avx2 ? "present" : "absent (SSE2 twice)");
  std::printf("%-10s %10s %10s %10s %14s\n", "method", "ns/ray", "nodes/ray", "tests/ray",
              "hit sum");
  std::vector<std::optional<Hit>> out;
  for (const auto& b : beams) out.resize(std::max(out.size(), b.size()));
  for (int pass = 0; pass < 3; ++pass)
    for (int method = 0; method < 3; ++method) {
      QueryCounts counts;
      unsigned long sum = 0;
      const auto start = std::chrono::steady_clock::now();
      for (const std::vector<Ray>& b : beams) {
        if (method == 0) {
          for (const Ray& r : b)
            if (const auto h = wide.closestHit(r, INFINITE_DISTANCE, &counts)) sum += h->geometry;
          continue;
        }
        const std::span<std::optional<Hit>> hits = std::span(out).first(b.size());
        wide.closestHits(b, INFINITE_DISTANCE, hits, &counts,
                         method == 1 ? WideBvh::Simd::Sse2 : WideBvh::Simd::Avx2);
        for (const auto& h : hits) sum += h ? h->geometry : 0;
      }
      const double ns =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e9 /
          static_cast<double>(total);
      const char* names[] = {"one by one", "SSE2 x8", "AVX2 x8"};
      std::printf("%-10s %10.1f %10.2f %10.2f %14lu\n", names[method], ns,
                  static_cast<double>(counts.nodesVisited) / static_cast<double>(total),
                  static_cast<double>(counts.shapeTests) / static_cast<double>(total), sum);
    }
  return renderBothWays(g, wide);
}

}  // namespace
}  // namespace rt

int main(int argc, char** argv) { return rt::run(argc > 1 ? std::atol(argv[1]) : 1000); }
