#include "camera/Camera.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "primitives/Util.h"

namespace rt {

namespace {

/// An orthonormal camera frame: vRight = vTo x vUp.
struct Frame {
  Vector vTo, vUp, vRight;
};

[[noreturn]] void throwMissing(const char* operation, const char* field) {
  throw std::logic_error(std::string(operation) + ": missing rendering data '" + field + "'");
}

void requireFinite(const Double3& v, const char* operation, const char* argument) {
  if (!v.isFinite()) {
    throw std::invalid_argument(std::string(operation) + ": " + argument + " must be finite, got " +
                                v.str());
  }
}

/// A view-plane size or distance: positive after alignZero, and finite.
void requirePositive(double v, const char* operation, const char* argument) {
  if (!(std::isfinite(v) && alignZero(v) > 0)) {
    throw std::invalid_argument(std::string(operation) + ": " + argument +
                                " must be a positive number, got " + formatNumber(v));
  }
}

/// The look-at frame: vTo = normalize(target - p0), vRight = normalize(vTo x up),
/// vUp = vRight x vTo. up only has to be non-parallel to vTo; the resulting vUp is the
/// component of up orthogonal to vTo, normalised.
Frame aimedFrame(const Point& p0, const Point& target, const Vector& up, const char* operation,
                 const char* upName) {
  if (target == p0) {
    throw std::invalid_argument(std::string(operation) + ": target " + target.xyz().str() +
                                " is the camera location, so there is no direction to it");
  }
  const Vector vTo = (target - p0).normalized();
  const Double3 right = vTo.xyz().cross(up.normalized().xyz());
  if (right.isZero()) {
    throw std::invalid_argument(std::string(operation) + ": " + upName + " " + up.xyz().str() +
                                " is parallel to the direction " + vTo.xyz().str() +
                                " towards target " + target.xyz().str());
  }
  const Vector vRight = Vector(right).normalized();
  return {vTo, vRight.cross(vTo).normalized(), vRight};
}

/// cos and sin of an angle in degrees, exact for multiples of 90 degrees so that quarter turns
/// keep an axis-aligned frame exactly axis-aligned.
void cosSinDegrees(double degrees, double& c, double& s) {
  const double reduced = std::fmod(degrees, 360.0);  // in (-360, 360), exact
  if (std::fmod(reduced, 90.0) == 0.0) {
    const int quarter = (static_cast<int>(reduced / 90.0) + 4) % 4;
    constexpr double COS[4] = {1, 0, -1, 0};
    constexpr double SIN[4] = {0, 1, 0, -1};
    c = COS[quarter];
    s = SIN[quarter];
    return;
  }
  const double radians = reduced * std::numbers::pi / 180.0;
  c = std::cos(radians);
  s = std::sin(radians);
}

}  // namespace

// ----------------------------------------------------------------------------------------------
// Camera

Camera::Builder Camera::builder() { return Builder{}; }

Ray Camera::pixelRay(int nX, int nY, int j, int i, double rx, double ry) const {
  // Pij = pC + xJ·vRight + yI·vUp with pC = p0 + d·vTo,
  // xJ = (j - (nX-1)/2)·rx and yI = -(i - (nY-1)/2)·ry (rows grow downwards, vUp upwards).
  // The sum is taken on plain triples, so a zero xJ or yI needs no special case.
  const double xJ = (j - (nX - 1) / 2.0) * rx;
  const double yI = -(i - (nY - 1) / 2.0) * ry;
  const Double3 pIJ = p0_.xyz() + vTo_.xyz() * vpDistance_ + vRight_.xyz() * xJ + vUp_.xyz() * yI;
  return Ray(p0_, Point(pIJ) - p0_);
}

Ray Camera::constructRay(int nX, int nY, int j, int i) const {
  if (nX < 1 || nY < 1) {
    throw std::invalid_argument("Camera::constructRay: the resolution must be at least 1x1, got " +
                                std::to_string(nX) + "x" + std::to_string(nY));
  }
  return pixelRay(nX, nY, j, i, vpWidth_ / nX, vpHeight_ / nY);
}

void Camera::requireRayTracer(const char* operation) const {
  if (!rayTracer_) throwMissing(operation, "rayTracer");
}

void Camera::renderBlock(const PixelBlock& b) {
  requireRayTracer("Camera::renderBlock");
  if (b.x0 < 0 || b.y0 < 0 || b.x1 > nX_ || b.y1 > nY_ || b.x0 >= b.x1 || b.y0 >= b.y1) {
    throw std::invalid_argument("Camera::renderBlock: block columns [" + std::to_string(b.x0) +
                                "," + std::to_string(b.x1) + ") rows [" + std::to_string(b.y0) +
                                "," + std::to_string(b.y1) + ") is empty or not inside the " +
                                std::to_string(nX_) + "x" + std::to_string(nY_) + " image");
  }
  const RayTracer& tracer = *rayTracer_;
  const double rx = vpWidth_ / nX_;
  const double ry = vpHeight_ / nY_;
  for (int i = b.y0; i < b.y1; ++i)
    for (int j = b.x0; j < b.x1; ++j)
      image_.setPixel(j, i, tracer.traceRay(pixelRay(nX_, nY_, j, i, rx, ry)));
}

Camera& Camera::renderImage(const std::atomic<bool>* stop) {
  requireRayTracer("Camera::renderImage");
  for (int i = 0; i < nY_; ++i) {
    if (stop != nullptr && stop->load(std::memory_order_relaxed)) throw RenderInterrupted();
    renderBlock({0, i, nX_, i + 1});
  }
  return *this;
}

Camera& Camera::printGrid(int interval, const Color& color) {
  if (interval < 1) {
    throw std::invalid_argument("Camera::printGrid: interval must be at least 1, got " +
                                std::to_string(interval));
  }
  for (int y = 0; y < image_.nY(); ++y)
    for (int x = 0; x < image_.nX(); ++x)
      if (x % interval == 0 || y % interval == 0) image_.setPixel(x, y, color);
  return *this;
}

Camera& Camera::writeToImage(const std::string& path) {
  if (!imageWriter_) throwMissing("Camera::writeToImage", "imageWriter");
  imageWriter_->write(image_, path);
  return *this;
}

Camera& Camera::move(const Vector& offset) {
  requireFinite(offset.xyz(), "Camera::move", "offset");
  p0_ = p0_ + offset;
  return *this;
}

Camera& Camera::rotate(double angleDegrees) {
  if (!std::isfinite(angleDegrees)) {
    throw std::invalid_argument("Camera::rotate: angleDegrees must be finite, got " +
                                formatNumber(angleDegrees));
  }
  // Rodrigues' formula around the unit axis k = -vTo (pointing back at a viewer behind the
  // camera, so that a positive angle turns counter-clockwise for that viewer):
  //   v' = v·cos + (k x v)·sin + k·(k·v)·(1 - cos).
  // vUp and vRight are orthogonal to k, so the last term vanishes; k x vUp = -vRight and
  // k x vRight = vUp give
  //   vUp' = vUp·cos - vRight·sin,   vRight' = vRight·cos + vUp·sin.
  double c = 1, s = 0;
  cosSinDegrees(angleDegrees, c, s);
  const Double3 up = vUp_.xyz() * c - vRight_.xyz() * s;
  const Double3 right = vRight_.xyz() * c + vUp_.xyz() * s;
  vUp_ = Vector(up).normalized();
  vRight_ = Vector(right).normalized();
  return *this;
}

Camera& Camera::lookAt(const Point& target) {
  requireFinite(target.xyz(), "Camera::lookAt", "target");
  const Frame f = aimedFrame(p0_, target, vUp_, "Camera::lookAt", "the camera's vUp");
  vTo_ = f.vTo;
  vUp_ = f.vUp;
  vRight_ = f.vRight;
  return *this;
}

// ----------------------------------------------------------------------------------------------
// Camera::Builder

Camera::Builder& Camera::Builder::setLocation(const Point& p0) {
  requireFinite(p0.xyz(), "Camera::Builder::setLocation", "location");
  p0_ = p0;
  return *this;
}

Camera::Builder& Camera::Builder::setDirection(const Vector& vTo, const Vector& vUp) {
  constexpr const char* OP = "Camera::Builder::setDirection";
  requireFinite(vTo.xyz(), OP, "vTo");
  requireFinite(vUp.xyz(), OP, "vUp");
  const Vector to = vTo.normalized();
  const Vector up = vUp.normalized();
  if (!isZero(to.dot(up))) {
    throw std::invalid_argument(std::string(OP) + ": vTo " + vTo.xyz().str() + " and vUp " +
                                vUp.xyz().str() + " must be orthogonal, their unit vectors' " +
                                "dot product is " + formatNumber(to.dot(up)));
  }
  vTo_ = to;
  vUp_ = up;
  target_.reset();
  return *this;
}

Camera::Builder& Camera::Builder::setDirection(const Point& target, const Vector& up) {
  constexpr const char* OP = "Camera::Builder::setDirection";
  requireFinite(target.xyz(), OP, "target");
  requireFinite(up.xyz(), OP, "up");
  target_ = target;
  targetUp_ = up;
  vTo_.reset();
  vUp_.reset();
  return *this;
}

Camera::Builder& Camera::Builder::setVpSize(double width, double height) {
  requirePositive(width, "Camera::Builder::setVpSize", "width");
  requirePositive(height, "Camera::Builder::setVpSize", "height");
  vpWidth_ = width;
  vpHeight_ = height;
  return *this;
}

Camera::Builder& Camera::Builder::setVpDistance(double distance) {
  requirePositive(distance, "Camera::Builder::setVpDistance", "distance");
  vpDistance_ = distance;
  return *this;
}

Camera::Builder& Camera::Builder::setResolution(int nX, int nY) {
  Image::checkSize(nX, nY, "Camera::Builder::setResolution");
  nX_ = nX;
  nY_ = nY;
  return *this;
}

Camera::Builder& Camera::Builder::setRayTracer(std::shared_ptr<const RayTracer> tracer) {
  rayTracer_ = std::move(tracer);
  return *this;
}

Camera::Builder& Camera::Builder::setImageWriter(std::shared_ptr<const ImageWriter> writer) {
  imageWriter_ = std::move(writer);
  return *this;
}

Camera Camera::Builder::build() const {
  constexpr const char* OP = "Camera::Builder";
  if (!p0_) throwMissing(OP, "location");
  if (!vTo_ && !target_) throwMissing(OP, "direction");
  if (!vpWidth_) throwMissing(OP, "vpSize");
  if (!vpDistance_) throwMissing(OP, "vpDistance");
  if (!nX_) throwMissing(OP, "resolution");

  Camera c;
  c.p0_ = *p0_;
  if (target_) {
    const Frame f = aimedFrame(*p0_, *target_, targetUp_, "Camera::Builder::setDirection", "up");
    c.vTo_ = f.vTo;
    c.vUp_ = f.vUp;
    c.vRight_ = f.vRight;
  } else {
    c.vTo_ = *vTo_;
    c.vUp_ = *vUp_;
    // Unit and orthogonal (checked in setDirection), so the product is unit up to rounding.
    c.vRight_ = vTo_->cross(*vUp_).normalized();
  }
  c.vpWidth_ = *vpWidth_;
  c.vpHeight_ = *vpHeight_;
  c.vpDistance_ = *vpDistance_;
  c.nX_ = *nX_;
  c.nY_ = *nY_;
  c.rayTracer_ = rayTracer_;
  c.imageWriter_ = imageWriter_;
  c.image_ = Image(*nX_, *nY_);
  return c;
}

}  // namespace rt
