#include "benchmark/Scaling.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>

#include "benchmark/Measure.h"
#include "camera/Camera.h"

namespace rt {

TimedRenders timeRenders(const RenderContext& context, const TimingOptions& options) {
  const int n = static_cast<int>(options.threads.size());
  if (n < 1 || n > TimedRenders::MAX_COUNTS)
    throw std::invalid_argument("timeRenders: " + std::to_string(n) +
                                " thread counts, expected 1 or 2");
  if (options.repeat < 1)
    throw std::invalid_argument("timeRenders: repeat is " + std::to_string(options.repeat) +
                                ", expected 1 or more");
  const Camera& camera = context.camera;
  std::vector<Image> images(static_cast<std::size_t>(n), Image(camera.nX(), camera.nY()));
  std::vector<std::vector<double>> wall(static_cast<std::size_t>(n)), cpu(wall);
  TimedRenders t;
  t.counts = n;
  for (int r = 0; r < options.repeat; ++r)
    for (int k = 0; k < n; ++k) {
      if (options.stop != nullptr && options.stop->load()) {
        t.interrupted = true;
        return t;
      }
      const double cpuStart = processCpuSeconds();
      const RenderResult result =
          renderImage(context, images[static_cast<std::size_t>(k)],
                      {.threads = options.threads[static_cast<std::size_t>(k)],
                       .tileSize = options.tileSize,
                       .stop = options.stop});
      if (result.interrupted) {
        t.interrupted = true;
        return t;
      }
      cpu[static_cast<std::size_t>(k)].push_back(processCpuSeconds() - cpuStart);
      wall[static_cast<std::size_t>(k)].push_back(result.seconds);
      t.rays[k] = result.counts;
      t.threads[k] = result.threads;
    }
  for (int k = 0; k < n; ++k) {
    const auto& w = wall[static_cast<std::size_t>(k)];
    t.wall[k] = median(w);
    t.cpu[k] = median(cpu[static_cast<std::size_t>(k)]);
    t.fastest[k] = *std::min_element(w.begin(), w.end());
  }
  for (int k = 1; k < n; ++k) {
    t.sameImage = t.sameImage && t.rays[k] == t.rays[0];
    for (int y = 0; y < camera.nY(); ++y)
      for (int x = 0; x < camera.nX(); ++x)
        t.sameImage = t.sameImage && std::memcmp(&images[0].pixel(x, y),
                                                 &images[static_cast<std::size_t>(k)].pixel(x, y),
                                                 sizeof(Color)) == 0;
  }
  return t;
}

namespace {

/// What one scene of a scaling cost: its renders through its structure (in the child process).
ScalingMeasurement measureRenders(const LitScene& scene, double generateSeconds,
                                  const TimedStructure& structure, const RayTracer& tracer,
                                  const Camera& camera, const TimingOptions& options) {
  std::uint64_t meshBytes = 0;
  for (const PlacedMesh& m : scene.geometries.meshes()) meshBytes += m.mesh->memoryBytes();
  const CenterSampler sampler;
  return {.shapes = scene.geometries.size(),
          .triangles = scene.geometries.triangleCount(),
          .generateSeconds = generateSeconds,
          .buildSeconds = structure.buildSeconds,
          .structureBytes = structure.memoryBytes(),
          .meshBytes = meshBytes,
          .renders = timeRenders({camera, tracer, sampler}, options)};
}

/// Runs work in a child process of its own; its measurement with the child's peak, or nothing
/// when stopped.
std::optional<ScalingMeasurement> measureInChild(const std::function<ScalingMeasurement()>& work,
                                                 const std::atomic<bool>* stop) {
  const auto measured = measureInChildProcess<ScalingMeasurement>(work, stop);
  if (!measured || measured->value.renders.interrupted) return std::nullopt;
  ScalingMeasurement m = measured->value;
  m.peakBytes = measured->peakBytes;
  return m;
}

}  // namespace

std::optional<ScalingMeasurement> measureGalaxy(long stars, int nX, int nY,
                                                const TimingOptions& options, ScalingAccel accel) {
  return measureInChild(
      [stars, nX, nY, &options, accel] {
        const GalaxyRender g(GalaxyParams{.stars = stars, .diffusion = false}, accel);
        return measureRenders(g.setup.scene, g.generateSeconds, g.structure, *g.tracer,
                              referenceView(g.setup, nX, nY), options);
      },
      options.stop);
}

std::optional<ScalingMeasurement> measureTeapot(int detail, int nX, int nY,
                                                const TimingOptions& options, ScalingAccel accel) {
  return measureInChild(
      [detail, nX, nY, &options, accel] {
        const TeapotRender t(detail, accel);
        return measureRenders(t.setup.scene, t.generateSeconds, t.structure, *t.tracer,
                              middleView(t.setup.camera, nX, nY), options);
      },
      options.stop);
}

}  // namespace rt
