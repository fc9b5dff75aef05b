#include "camera/Camera.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "primitives/Checks.h"
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

/// A view-plane size or distance: a positive finite number, and not the course's zero (below
/// 2^-40 the view plane's points would be indistinguishable from each other).
void requireViewPlaneLength(double v, const char* operation, const char* argument) {
  requirePositive(v, operation, argument);
  if (isZero(v)) {
    throw std::invalid_argument(std::string(operation) + ": " + argument +
                                " must be above the course's zero 2^-40, got " + formatNumber(v));
  }
}

/// The look-at frame: vTo = normalize(target - p0), vRight = normalize(vTo x up),
/// vUp = vRight x vTo. up only has to be non-parallel to vTo; the resulting vUp is the
/// component of up orthogonal to vTo, normalised.
Frame aimedFrame(const Point& p0, const Point& target, const Vector& up, const char* operation,
                 const char* upName) {
  // BEGIN SOLUTION: hint: aimedFrame, the look-at frame; target == p0 or a parallel up throw
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
  // END SOLUTION
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

Ray Camera::viewPlaneRay(double xRight, double yUp, const Sample2& lens) const noexcept {
  // BEGIN SOLUTION: hint: viewPlaneRay, Pij = pC + x*vRight + y*vUp; a lens aims at focus
  // Pij = pC + xJ·vRight + yI·vUp with pC = p0 + d·vTo. The sum is taken on plain triples, so a
  // zero xJ or yI needs no special case. Pij − p0 is never zero: build() checked that the view
  // plane's centre differs from p0, and Pij − p0 has the component d along vTo.
  const Double3& p0 = spec_.location.xyz();
  const Double3 pIJ =
      p0 + vTo_.xyz() * spec_.vpDistance + vRight_.xyz() * xRight + vUp_.xyz() * yUp;
  if (spec_.aperture == 0) return Ray(spec_.location, Vector::unchecked(pIJ - p0));
  // A thin lens: every ray through the lens that aims at the point where the pinhole ray meets
  // the focal plane (at focal along vTo; the pinhole ray's vTo component is d, so it gets
  // there at (focal / d) of Pij − p0) converges there: that plane is sharp, the rest is blurred
  // by the aperture.
  const Double3 focus = p0 + (pIJ - p0) * (focal_ / spec_.vpDistance);
  const Double3 origin =
      p0 + vRight_.xyz() * (spec_.aperture * lens.u) + vUp_.xyz() * (spec_.aperture * lens.v);
  return Ray(Point(origin), Vector::unchecked(focus - origin));
  // END SOLUTION
}

Ray Camera::constructRay(int nX, int nY, int j, int i) const {
  // BEGIN SOLUTION: hint: constructRay, the ray through the centre of pixel (j, i)
  if (nX < 1 || nY < 1) {
    throw std::invalid_argument("Camera::constructRay: the resolution must be at least 1x1, got " +
                                std::to_string(nX) + "x" + std::to_string(nY));
  }
  // xJ = (j - (nX-1)/2)·rx and yI = -(i - (nY-1)/2)·ry (rows grow downwards, vUp upwards).
  return viewPlaneRay((j - (nX - 1) / 2.0) * (spec_.vpWidth / nX),
                      -(i - (nY - 1) / 2.0) * (spec_.vpHeight / nY), Sample2{});
  // END SOLUTION
}

Ray Camera::ray(double px, double py, const Sample2& lens) const noexcept {
  // BEGIN SOLUTION: hint: Camera::ray, constructRay's formula in continuous pixel units
  // The same formula in continuous pixel units: for px = j + 0.5, px − nX/2 = j − (nX−1)/2
  // exactly (both are small multiples of 1/2), so a pixel's centre gives constructRay's ray.
  return viewPlaneRay((px - spec_.nX / 2.0) * pixelWidth_, -(py - spec_.nY / 2.0) * pixelHeight_,
                      lens);
  // END SOLUTION
}

Camera& Camera::renderImage(const std::atomic<bool>* stop) {
  // BEGIN SOLUTION: hint: renderImage, every row through renderBlock; mind the stop flag
  if (!rayTracer_) throwMissing("Camera::renderImage", "rayTracer");
  counts_ = {};
  const RenderContext context{*this, *rayTracer_, *pixelSampler_};
  for (int i = 0; i < spec_.nY; ++i) {
    if (stop != nullptr && stop->load(std::memory_order_relaxed)) throw RenderInterrupted();
    counts_ += renderBlock(context, {0, i, spec_.nX, i + 1}, image_);
  }
  return *this;
  // END SOLUTION
}

Camera& Camera::printGrid(int interval, const Color& color) {
  // BEGIN SOLUTION: hint: printGrid, a line every interval pixels; interval < 1 throws
  if (interval < 1) {
    throw std::invalid_argument("Camera::printGrid: interval must be at least 1, got " +
                                std::to_string(interval));
  }
  for (int y = 0; y < image_.nY(); ++y)
    for (int x = 0; x < image_.nX(); ++x)
      if (x % interval == 0 || y % interval == 0) image_.setPixel(x, y, color);
  return *this;
  // END SOLUTION
}

Camera& Camera::writeToImage(const std::string& path) {
  // BEGIN SOLUTION: hint: writeToImage, through the image writer (missing: throw)
  if (!imageWriter_) throwMissing("Camera::writeToImage", "imageWriter");
  imageWriter_->write(image_, path);
  return *this;
  // END SOLUTION
}

void Camera::setFrame(const Vector& vTo, const Vector& vUp, const Vector& vRight) {
  vTo_ = vTo;
  vUp_ = vUp;
  vRight_ = vRight;
  spec_.target.reset();
  spec_.to = vTo;
  spec_.up = vUp;
}

Camera& Camera::move(const Vector& offset) {
  requireFinite(offset.xyz(), "Camera::move", "offset");
  spec_.location = spec_.location + offset;
  return *this;
}

Camera& Camera::rotate(double angleDegrees) {
  // BEGIN SOLUTION: hint: rotate vUp and vRight around vTo (Rodrigues' formula)
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
  setFrame(vTo_, Vector(up).normalized(), Vector(right).normalized());
  return *this;
  // END SOLUTION
}

Camera& Camera::lookAt(const Point& target) {
  // BEGIN SOLUTION: hint: lookAt, the look-at frame from the location and the current vUp
  requireFinite(target.xyz(), "Camera::lookAt", "target");
  const Frame f = aimedFrame(spec_.location, target, vUp_, "Camera::lookAt", "the camera's vUp");
  setFrame(f.vTo, f.vUp, f.vRight);
  return *this;
  // END SOLUTION
}

// ----------------------------------------------------------------------------------------------
// Camera::Builder

CameraBuilder::CameraBuilder(const CameraSpec& spec) {
  setLocation(spec.location);
  // With neither a target nor a vTo the direction stays unset, and build() reports it missing.
  if (spec.target) {
    setDirection(*spec.target, spec.up);
  } else if (spec.to) {
    setDirection(*spec.to, spec.up);
  }
  setVpSize(spec.vpWidth, spec.vpHeight).setVpDistance(spec.vpDistance);
  setResolution(spec.nX, spec.nY).setAperture(spec.aperture).setFocalDistance(spec.focalDistance);
}

CameraBuilder CameraSpec::builder() const { return CameraBuilder(*this); }

CameraBuilder& CameraBuilder::setLocation(const Point& p0) {
  requireFinite(p0.xyz(), "Camera::Builder::setLocation", "location");
  spec_.location = p0;
  hasLocation_ = true;
  return *this;
}

CameraBuilder& CameraBuilder::setDirection(const Vector& vTo, const Vector& vUp) {
  // BEGIN SOLUTION: hint: setDirection(vTo, vUp); they must be orthogonal (isZero of the dot)
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
  spec_.to = to;
  spec_.up = up;
  spec_.target.reset();
  return *this;
  // END SOLUTION
}

CameraBuilder& CameraBuilder::setDirection(const Point& target, const Vector& up) {
  constexpr const char* OP = "Camera::Builder::setDirection";
  requireFinite(target.xyz(), OP, "target");
  requireFinite(up.xyz(), OP, "up");
  spec_.target = target;
  spec_.up = up;
  spec_.to.reset();
  return *this;
}

CameraBuilder& CameraBuilder::setVpSize(double width, double height) {
  requireViewPlaneLength(width, "Camera::Builder::setVpSize", "width");
  requireViewPlaneLength(height, "Camera::Builder::setVpSize", "height");
  spec_.vpWidth = width;
  spec_.vpHeight = height;
  return *this;
}

CameraBuilder& CameraBuilder::setVpDistance(double distance) {
  requireViewPlaneLength(distance, "Camera::Builder::setVpDistance", "distance");
  spec_.vpDistance = distance;
  return *this;
}

CameraBuilder& CameraBuilder::setResolution(int nX, int nY) {
  Image::checkSize(nX, nY, "Camera::Builder::setResolution");
  spec_.nX = nX;
  spec_.nY = nY;
  return *this;
}

CameraBuilder& CameraBuilder::setAperture(double radius) {
  requireNonNegative(radius, "Camera::Builder::setAperture", "radius");
  spec_.aperture = radius;
  return *this;
}

CameraBuilder& CameraBuilder::setFocalDistance(double distance) {
  requireNonNegative(distance, "Camera::Builder::setFocalDistance", "distance");
  spec_.focalDistance = distance;
  return *this;
}

CameraBuilder& CameraBuilder::setRayTracer(std::shared_ptr<const RayTracer> tracer) {
  rayTracer_ = std::move(tracer);
  return *this;
}

CameraBuilder& CameraBuilder::setImageWriter(std::shared_ptr<const ImageWriter> writer) {
  imageWriter_ = std::move(writer);
  return *this;
}

CameraBuilder& CameraBuilder::setPixelSampler(std::shared_ptr<const PixelSampler> sampler) {
  pixelSampler_ = std::move(sampler);
  return *this;
}

Camera CameraBuilder::build() const {
  // BEGIN SOLUTION: hint: build(), check the data (missing: throw), then the frame and image
  constexpr const char* OP = "Camera::Builder";
  if (!hasLocation_) throwMissing(OP, "location");
  if (!spec_.to && !spec_.target) throwMissing(OP, "direction");
  if (spec_.vpWidth == 0) throwMissing(OP, "vpSize");
  if (spec_.vpDistance == 0) throwMissing(OP, "vpDistance");
  if (spec_.nX == 0) throwMissing(OP, "resolution");

  Camera c;
  c.spec_ = spec_;
  if (spec_.target) {
    const Frame f =
        aimedFrame(spec_.location, *spec_.target, spec_.up, "Camera::Builder::setDirection", "up");
    c.vTo_ = f.vTo;
    c.vUp_ = f.vUp;
    c.vRight_ = f.vRight;
  } else {
    c.vTo_ = *spec_.to;
    c.vUp_ = spec_.up;
    // Unit and orthogonal (checked in setDirection), so the product is unit up to rounding.
    c.vRight_ = spec_.to->cross(spec_.up).normalized();
  }
  // Rays go from p0 through the view plane: its centre must be a different point than p0 in
  // floating point, or every ray's direction would be zero (a location of 1e20 with a view
  // plane at distance 1, say). Checked here so that making a ray never has to.
  // The same holds for a lens's focal plane, where every lens ray aims.
  const auto requireDistinct = [&](double distance, const char* plane) {
    const Double3 centre = spec_.location.xyz() + c.vTo_.xyz() * distance;
    if ((centre - spec_.location.xyz()).isZero()) {
      throw std::invalid_argument(std::string(OP) + ": the " + plane + " at distance " +
                                  formatNumber(distance) + " from the location " +
                                  spec_.location.xyz().str() +
                                  " rounds to the location itself (the distance is too small for "
                                  "coordinates this large)");
    }
  };
  requireDistinct(spec_.vpDistance, "view plane");
  if (spec_.aperture > 0 && spec_.focalDistance > 0)
    requireDistinct(spec_.focalDistance, "focal plane");
  c.pixelWidth_ = spec_.vpWidth / spec_.nX;
  c.pixelHeight_ = spec_.vpHeight / spec_.nY;
  c.focal_ = spec_.focalDistance > 0 ? spec_.focalDistance : spec_.vpDistance;
  c.rayTracer_ = rayTracer_;
  c.imageWriter_ = imageWriter_;
  c.pixelSampler_ = pixelSampler_ ? pixelSampler_ : std::make_shared<CenterSampler>();
  c.image_ = Image(spec_.nX, spec_.nY);
  return c;
  // END SOLUTION
}

}  // namespace rt
