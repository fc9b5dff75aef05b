#include "camera/CameraSpec.h"

namespace rt {

Camera::Builder CameraSpec::builder() const {
  Camera::Builder b;
  b.setLocation(location);
  // With neither a target nor a vTo the direction stays unset, and build() reports it missing.
  if (target) {
    b.setDirection(*target, up);
  } else if (to) {
    b.setDirection(*to, up);
  }
  b.setVpSize(vpWidth, vpHeight).setVpDistance(vpDistance).setResolution(nX, nY);
  return b;
}

}  // namespace rt
