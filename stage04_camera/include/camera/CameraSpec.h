#pragma once
/// @file CameraSpec.h
/// A camera as plain data: the one list of the camera's properties. Camera::Builder keeps one
/// while it collects the data (its setters validate each field as it is set), a built Camera
/// keeps the one that describes it, and built-in scenes and scene files describe their cameras
/// with it. A new camera property is a field here, a setter in Camera::Builder and its use.

#include <optional>
#include <string>

#include "primitives/Point.h"
#include "primitives/Vector.h"

namespace rt {

class CameraBuilder;

struct CameraSpec {
  Point location = Point::ZERO;
  /// Either a look-at target (with up, default +Y) ...
  std::optional<Point> target;
  /// ... or vTo with up (orthogonal to it).
  std::optional<Vector> to;
  Vector up = Vector::AXIS_Y;
  /// The view plane: width x height at distance vpDistance along vTo (0: not given).
  double vpWidth = 0, vpHeight = 0, vpDistance = 0;
  /// The image: nX columns, nY rows (0: not given).
  int nX = 0, nY = 0;
  /// The lens: a thin lens of this radius (0: a pinhole, the course's camera) ...
  double aperture = 0;
  /// ... focused at this distance along vTo (0: on the view plane, at vpDistance).
  double focalDistance = 0;

  /// The shape of every built-in camera: at `location` looking along `to` (or, in the second
  /// form, at `target`), up +Y, a vpSize x vpSize view plane at vpDistance and an image of
  /// pixels x pixels. Values are checked when a builder is made from the spec.
  static CameraSpec squareView(const Point& location, const Vector& to, double vpSize,
                               double vpDistance, int pixels);
  static CameraSpec squareView(const Point& location, const Point& target, double vpSize,
                               double vpDistance, int pixels);

  /// A builder with every field of this spec set through its setters (so validated by them);
  /// include camera/Camera.h to use it.
  /// @throws std::invalid_argument for a field its setter refuses (a zero view plane, say).
  CameraBuilder builder() const;
};

/// A named point of view of a scene (a scene file's "views", the galaxy's "above").
struct NamedView {
  std::string name;
  CameraSpec camera;
};

/// A ready-to-render scene and the camera that frames it: what a built-in scene of `rt` is, and
/// what the render tests use, so every scene is written once.
template <typename SceneT>
struct SceneSetup {
  SceneT scene;
  CameraSpec camera;
};

}  // namespace rt
