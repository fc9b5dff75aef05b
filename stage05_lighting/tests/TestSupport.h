#pragma once
// Helpers shared by stage 5's tests: colour comparison to a tolerance, the message of an
// expected exception, and rendering a scene.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "camera/Camera.h"
#include "camera/CameraSpec.h"
#include "camera/Image.h"
#include "camera/SampleContext.h"
#include "lighting/LitScene.h"
#include "lighting/PhongTracer.h"
#include "primitives/Color.h"
#include "primitives/Double3.h"

namespace rt::test {

inline constexpr double EPS = 1e-9;

/// Every channel of `actual` within EPS of (r, g, b).
inline ::testing::AssertionResult colorNear(const Color& actual, double r, double g, double b,
                                            double eps = EPS) {
  if (std::abs(actual.r() - r) <= eps && std::abs(actual.g() - g) <= eps &&
      std::abs(actual.b() - b) <= eps)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got " << actual.rgb().str() << ", expected "
                                       << Double3(r, g, b).str() << " (tolerance " << eps << ")";
}
inline ::testing::AssertionResult colorNear(const Color& actual, const Double3& expected,
                                            double eps = EPS) {
  return colorNear(actual, expected.x, expected.y, expected.z, eps);
}

/// Same check for a Double3 (directions, coefficients).
inline ::testing::AssertionResult tripleNear(const Double3& actual, const Double3& expected,
                                             double eps = EPS) {
  if (std::abs(actual.x - expected.x) <= eps && std::abs(actual.y - expected.y) <= eps &&
      std::abs(actual.z - expected.z) <= eps)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got " << actual.str() << ", expected " << expected.str()
                                       << " (tolerance " << eps << ")";
}

/// The message of the exception of type E that f throws ("" when it throws nothing; any other
/// exception propagates and fails the test).
template <typename E, typename F>
std::string thrownMessage(F&& f) {
  try {
    std::forward<F>(f)();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

/// The message of the std::invalid_argument that f throws ("" when it throws nothing).
template <typename F>
std::string invalidArgumentMessage(F&& f) {
  return thrownMessage<std::invalid_argument>(std::forward<F>(f));
}

/// A sample context for calling a tracer's protected steps directly: pixel (0, 0), sample 0,
/// seed 0, with its own counts.
struct TestSample {
  RayCounts counts;
  SampleContext ctx{0, 0, 0, 0, counts};
};

/// A camera for spec (its resolution replaced by nX x nY when given), rendering with tracer.
inline Camera makeCamera(const CameraSpec& spec, std::shared_ptr<const RayTracer> tracer,
                         int nX = 0, int nY = 0) {
  CameraSpec s = spec;
  if (nX > 0) s.nX = nX;
  if (nY > 0) s.nY = nY;
  return s.builder().setRayTracer(std::move(tracer)).build();
}

/// Renders the scene with the Phong tracer through the spec's camera at nX x nY pixels.
inline Camera renderPhong(const LitScene& scene, const CameraSpec& spec, int nX = 0, int nY = 0) {
  Camera camera = makeCamera(spec, std::make_shared<PhongTracer>(scene), nX, nY);
  camera.renderImage();
  return camera;
}

}  // namespace rt::test
