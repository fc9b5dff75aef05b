#include "camera/CameraSpec.h"

namespace rt {

namespace {

/// The square view plane and image shared by both forms of squareView.
CameraSpec squareAt(const Point& location, double vpSize, double vpDistance, int pixels) {
  CameraSpec c;
  c.location = location;
  c.vpWidth = c.vpHeight = vpSize;
  c.vpDistance = vpDistance;
  c.nX = c.nY = pixels;
  return c;
}

}  // namespace

CameraSpec CameraSpec::squareView(const Point& location, const Vector& to, double vpSize,
                                  double vpDistance, int pixels) {
  CameraSpec c = squareAt(location, vpSize, vpDistance, pixels);
  c.to = to;
  return c;
}

CameraSpec CameraSpec::squareView(const Point& location, const Point& target, double vpSize,
                                  double vpDistance, int pixels) {
  CameraSpec c = squareAt(location, vpSize, vpDistance, pixels);
  c.target = target;
  return c;
}

}  // namespace rt
