#pragma once
/// @file CameraSpec.h
/// A camera as plain data, for built-in scenes and scene files: turned into a Camera::Builder
/// (where everything is validated) once the renderer knows the tracer and the output.

#include <optional>

#include "camera/Camera.h"
#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

struct CameraSpec {
  Point location = Point::ZERO;
  /// Either a look-at target (with up, default +Y) ...
  std::optional<Point> target;
  /// ... or vTo with up (orthogonal to it).
  std::optional<Vector> to;
  Vector up = Vector::AXIS_Y;
  double vpWidth = 0, vpHeight = 0, vpDistance = 0;
  int nX = 0, nY = 0;

  /// A builder with location, direction, view plane and resolution set from this spec.
  Camera::Builder builder() const;

  /// The shape of every built-in camera: at `location` looking along `to` (or, in the second
  /// form, at `target`), up +Y, a vpSize x vpSize view plane at vpDistance and an image of
  /// pixels x pixels. Values are checked by builder(), as for any spec.
  static CameraSpec squareView(const Point& location, const Vector& to, double vpSize,
                               double vpDistance, int pixels);
  static CameraSpec squareView(const Point& location, const Point& target, double vpSize,
                               double vpDistance, int pixels);
};

/// A ready-to-render scene and the camera that frames it: what a built-in scene of `rt` is, and
/// what the render tests use, so every scene is written once.
template <typename SceneT>
struct SceneSetup {
  SceneT scene;
  CameraSpec camera;
};

}  // namespace rt
