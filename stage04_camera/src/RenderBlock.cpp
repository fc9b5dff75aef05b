#include "camera/RenderBlock.h"

#include <stdexcept>
#include <string>

#include "camera/Camera.h"

namespace rt {

Color PixelSampler::traceSample(const Camera& camera, const RayTracer& tracer, SampleContext& ctx,
                                double px, double py) const {
  // The lens point takes the sample's next two numbers, only when there is a lens, so a pinhole
  // camera leaves them to the tracer.
  const Sample2 lens = camera.aperture() > 0 ? squareToDisk(ctx.random.next2D()) : Sample2{};
  return traceSample(camera, tracer, ctx, px, py, lens);
}

Color PixelSampler::traceSample(const Camera& camera, const RayTracer& tracer, SampleContext& ctx,
                                double px, double py, const Sample2& lens) const {
  ++ctx.counts.primary;
  return tracer.traceRay(camera.ray(px, py, lens), ctx);
}

Color CenterSampler::pixelColor(const Camera& camera, const RayTracer& tracer, int x, int y,
                                RayCounts& counts) const {
  SampleContext ctx = context(x, y, 0, counts);
  return traceSample(camera, tracer, ctx, x + 0.5, y + 0.5);
}

RayCounts renderBlock(const RenderContext& context, const PixelBlock& b, Image& image) {
  const Camera& camera = context.camera;
  const RayTracer& tracer = context.tracer;
  const PixelSampler& sampler = context.sampler;
  const int nX = camera.nX(), nY = camera.nY();
  if (image.nX() != nX || image.nY() != nY) {
    throw std::invalid_argument("renderBlock: the image is " + std::to_string(image.nX()) + "x" +
                                std::to_string(image.nY()) + " but the camera's is " +
                                std::to_string(nX) + "x" + std::to_string(nY));
  }
  if (b.x0 < 0 || b.y0 < 0 || b.x1 > nX || b.y1 > nY || b.x0 >= b.x1 || b.y0 >= b.y1) {
    throw std::invalid_argument("renderBlock: block columns [" + std::to_string(b.x0) + "," +
                                std::to_string(b.x1) + ") rows [" + std::to_string(b.y0) + "," +
                                std::to_string(b.y1) + ") is empty or not inside the " +
                                std::to_string(nX) + "x" + std::to_string(nY) + " image");
  }
  RayCounts counts;
  for (int y = b.y0; y < b.y1; ++y)
    for (int x = b.x0; x < b.x1; ++x)
      image.setPixel(x, y, sampler.pixelColor(camera, tracer, x, y, counts));
  return counts;
}

}  // namespace rt
