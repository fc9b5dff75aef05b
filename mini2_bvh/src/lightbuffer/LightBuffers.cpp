#include "lightbuffer/LightBuffers.h"

#include <stdexcept>
#include <utility>
#include <variant>

namespace rt {

namespace {

/// The light's position when it is a point (a point light, or a spot light, without a size).
std::optional<Point> pointOf(const LightSource& light) {
  if (const auto* p = std::get_if<PointLight>(&light))
    if (!(p->radius > 0 && p->shadowSamples > 1)) return p->position;
  if (const auto* s = std::get_if<SpotLight>(&light))
    if (!(s->radius > 0 && s->shadowSamples > 1)) return s->position;
  return std::nullopt;
}

}  // namespace

LightBuffers::LightBuffers(const Intersectable& walk, Primitives primitives,
                           std::span<const LightSource> lights, const LightBuffersOptions& options)
    : walk_(walk) {
  buffers_.resize(lights.size());
  if (primitives.size() > options.maxPrimitives) return;
  std::vector<std::uint32_t> flat;
  flatOf_.assign(primitives.shapeCount(), 0);
  for (std::uint32_t i = 0; i < primitives.shapeCount(); ++i)
    if (FlatShapes::isFlat(primitives.shapes()[i])) {
      flatOf_[i] = static_cast<std::uint32_t>(flat.size());
      flat.push_back(i);
    }
  flats_ = FlatShapes(primitives, flat);
  for (std::size_t k = 0; k < lights.size(); ++k)
    if (const std::optional<Point> at = pointOf(lights[k]))
      buffers_[k] = LightBuffer::build(primitives, *at, flats_, flatOf_, options.buffer);
}

LightBuffers::LightBuffers(std::unique_ptr<Intersectable> walk, Primitives primitives,
                           std::span<const LightSource> lights, const LightBuffersOptions& options)
    : LightBuffers(*walk, primitives, lights, options) {
  owned_ = std::move(walk);
}

bool LightBuffers::crossingsTowards(std::uint32_t light, const Ray& ray, double tMin, double tMax,
                                    ShadowCrossings& crossings, QueryCounts* counts) const {
  const auto add = [&crossings](const Hit& hit) { return crossings.add(hit); };
  if (light < buffers_.size() && buffers_[light]) {
    std::uint64_t tests = 0, certified = 0;
    const std::optional<bool> done =
        buffers_[light]->forEachHit(ray, tMin, tMax, add, tests, certified);
    if (done) {
      if (counts != nullptr) counts->shapeTests += tests;
      return *done;
    }
  }
  return walk_.forEachHit(ray, tMax, add, counts);
}

std::size_t LightBuffers::memoryBytes() const noexcept {
  std::size_t bytes = buffers_.capacity() * sizeof(buffers_[0]) + flats_.memoryBytes() +
                      flatOf_.capacity() * sizeof(std::uint32_t);
  for (const std::optional<LightBuffer>& b : buffers_)
    if (b) bytes += b->memoryBytes();
  return bytes;
}

}  // namespace rt
