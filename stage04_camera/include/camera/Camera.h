#pragma once
/// @file Camera.h

#include <atomic>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "camera/Image.h"
#include "camera/ImageWriter.h"
#include "camera/RayTracer.h"
#include "primitives/Color.h"
#include "primitives/Point.h"
#include "primitives/Ray.h"
#include "primitives/Vector.h"

namespace rt {

/// Thrown by Camera::renderImage when its stop flag is raised.
struct RenderInterrupted : std::runtime_error {
  RenderInterrupted() : std::runtime_error("render interrupted") {}
};

/// A rectangle of pixels, half-open: columns [x0, x1), rows [y0, y1). One row, one square tile
/// or the whole image: the unit of work of Camera::renderBlock.
struct PixelBlock {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// A pinhole camera with a view plane, built by Camera::Builder.
///
/// Frame: vTo (towards the scene), vUp, vRight = vTo x vUp, all unit and orthogonal. The view
/// plane is w x h at distance d along vTo; pixel (j = column, i = row) of an nX x nY image has its
/// centre at pC + (j - (nX-1)/2)·(w/nX)·vRight - (i - (nY-1)/2)·(h/nY)·vUp, pC = p0 + d·vTo.
class Camera {
 public:
  class Builder;
  static Builder builder();

  /// The ray from the camera's location through the centre of pixel (j, i) of an nX x nY grid.
  /// j and i may lie outside the grid (the formula extends the view plane).
  /// @throws std::invalid_argument unless nX, nY >= 1.
  Ray constructRay(int nX, int nY, int j, int i) const;

  const Point& location() const { return p0_; }
  const Vector& vTo() const { return vTo_; }
  const Vector& vUp() const { return vUp_; }
  const Vector& vRight() const { return vRight_; }
  double vpWidth() const { return vpWidth_; }
  double vpHeight() const { return vpHeight_; }
  double vpDistance() const { return vpDistance_; }
  int nX() const { return nX_; }
  int nY() const { return nY_; }

  /// Casts one ray through every pixel's centre into the camera's image.
  /// @param stop when given and set (from a signal handler, say), the render stops within one
  ///        row and throws RenderInterrupted; the image is then incomplete.
  /// @throws std::logic_error naming "rayTracer" when no tracer was set.
  Camera& renderImage(const std::atomic<bool>* stop = nullptr);
  /// Casts one ray through the centre of every pixel of block and stores the colours in the
  /// image. renderImage calls it row by row; a parallel renderer can hand disjoint blocks to
  /// different threads (they write disjoint pixels and share only const state).
  /// @throws std::logic_error naming "rayTracer" when no tracer was set;
  ///         std::invalid_argument when block is empty or not inside the image.
  void renderBlock(const PixelBlock& block);
  /// Paints every pixel whose column or row is a multiple of interval.
  /// @throws std::invalid_argument for interval < 1.
  Camera& printGrid(int interval, const Color& color);
  /// Writes the image through the image writer.
  /// @throws std::logic_error naming "imageWriter" when no writer was set; std::runtime_error
  ///         when the file cannot be written.
  Camera& writeToImage(const std::string& path);

  const Image& image() const { return image_; }
  Image& image() { return image_; }

  // Transformations (the seed's stage-4 bonus). Each keeps the frame orthonormal.
  /// Moves the location by offset; the orientation is unchanged.
  Camera& move(const Vector& offset);
  /// Rotates vUp and vRight around vTo by angleDegrees (counter-clockwise as seen from behind
  /// the camera, Rodrigues' formula): rotate(90) turns vUp into the old -vRight and vRight
  /// into the old vUp. @throws std::invalid_argument for a non-finite angle.
  Camera& rotate(double angleDegrees);
  /// Turns the camera to look at target, keeping its up as close to the old vUp as possible.
  /// @throws std::invalid_argument when target is the location or lies along the old vUp.
  Camera& lookAt(const Point& target);

 private:
  Camera() = default;
  /// The course's pixel-centre formula with the pixel sizes rx = w/nX, ry = h/nY given: the
  /// ray from p0 through the centre of pixel (j, i). Arguments are not checked (hot path).
  Ray pixelRay(int nX, int nY, int j, int i, double rx, double ry) const;
  void requireRayTracer(const char* operation) const;

  Point p0_ = Point::ZERO;
  Vector vTo_ = Vector(0, 0, -1);
  Vector vUp_ = Vector::AXIS_Y;
  Vector vRight_ = Vector::AXIS_X;
  double vpWidth_ = 0, vpHeight_ = 0, vpDistance_ = 0;
  int nX_ = 0, nY_ = 0;
  std::shared_ptr<const RayTracer> rayTracer_;
  std::shared_ptr<const ImageWriter> imageWriter_;
  Image image_;
};

/// Collects the camera's data; build() checks that nothing is missing.
class Camera::Builder {
 public:
  Builder& setLocation(const Point& p0);
  /// vTo and vUp given directly; @throws std::invalid_argument unless they are orthogonal.
  Builder& setDirection(const Vector& vTo, const Vector& vUp);
  /// Look at target: vTo = normalize(target - p0), vRight = normalize(vTo x up),
  /// vUp = vRight x vTo (up need not be orthogonal to vTo). Resolved at build(), after the
  /// location is known. @throws std::invalid_argument (at build) when up is parallel to vTo
  /// or target is the location.
  Builder& setDirection(const Point& target, const Vector& up = Vector::AXIS_Y);
  /// @throws std::invalid_argument unless both are positive.
  Builder& setVpSize(double width, double height);
  /// @throws std::invalid_argument unless positive.
  Builder& setVpDistance(double distance);
  /// @throws std::invalid_argument unless both are at least 1.
  Builder& setResolution(int nX, int nY);
  Builder& setRayTracer(std::shared_ptr<const RayTracer> tracer);
  Builder& setImageWriter(std::shared_ptr<const ImageWriter> writer);

  /// @throws std::logic_error "Camera::Builder: missing rendering data 'FIELD'" naming the first
  ///         missing field among location, direction, vpSize, vpDistance, resolution.
  Camera build() const;

 private:
  std::optional<Point> p0_;
  std::optional<Vector> vTo_, vUp_;
  std::optional<Point> target_;
  Vector targetUp_ = Vector::AXIS_Y;
  std::optional<double> vpWidth_, vpHeight_, vpDistance_;
  std::optional<int> nX_, nY_;
  std::shared_ptr<const RayTracer> rayTracer_;
  std::shared_ptr<const ImageWriter> imageWriter_;
};

}  // namespace rt
