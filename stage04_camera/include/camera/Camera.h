#pragma once
/// @file Camera.h

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>

#include "camera/CameraSpec.h"
#include "camera/Image.h"
#include "camera/ImageWriter.h"
#include "camera/RayTracer.h"
#include "camera/RenderBlock.h"
#include "primitives/Color.h"
#include "primitives/Point.h"
#include "primitives/Random.h"
#include "primitives/Ray.h"
#include "primitives/Vector.h"

namespace rt {

/// Thrown by Camera::renderImage when its stop flag is raised.
struct RenderInterrupted : std::runtime_error {
  RenderInterrupted() : std::runtime_error("render interrupted") {}
};

class CameraBuilder;

/// A camera with a view plane, built by Camera::Builder: it makes rays. (Rendering is
/// renderBlock's job, camera/RenderBlock.h; renderImage is the course's API on top of it.)
///
/// Frame: vTo (towards the scene), vUp, vRight = vTo x vUp, all unit and orthogonal. The view
/// plane is w x h at distance d along vTo; pixel (j = column, i = row) of an nX x nY image has its
/// centre at pC + (j - (nX-1)/2)·(w/nX)·vRight - (i - (nY-1)/2)·(h/nY)·vUp, pC = p0 + d·vTo.
class Camera {
 public:
  using Builder = CameraBuilder;
  static Builder builder();

  /// The ray from the camera's location through the centre of pixel (j, i) of an nX x nY grid.
  /// j and i may lie outside the grid (the formula extends the view plane). The course's API.
  /// @throws std::invalid_argument unless nX, nY >= 1.
  Ray constructRay(int nX, int nY, int j, int i) const;

  /// The ray through any point of the image, in pixel units of the camera's nX x nY image:
  /// pixel (j, i) covers [j, j+1) x [i, i+1), so (j + 0.5, i + 0.5) is its centre and gives
  /// exactly constructRay(nX, nY, j, i). A jittered sample or an adaptive corner asks for its
  /// own point. lens is a point of the unit disk: with an aperture (a thin lens) the ray leaves
  /// the lens at location + aperture·(lens.u·vRight + lens.v·vUp) and passes through the point
  /// the pinhole ray meets at the focal distance; with no aperture (the course's pinhole) lens
  /// is ignored. Never throws (per-sample code).
  Ray ray(double px, double py, const Sample2& lens = {}) const noexcept;

  const Point& location() const { return spec_.location; }
  const Vector& vTo() const { return vTo_; }
  const Vector& vUp() const { return vUp_; }
  const Vector& vRight() const { return vRight_; }
  double vpWidth() const { return spec_.vpWidth; }
  double vpHeight() const { return spec_.vpHeight; }
  double vpDistance() const { return spec_.vpDistance; }
  int nX() const { return spec_.nX; }
  int nY() const { return spec_.nY; }
  /// The lens radius; 0 for the course's pinhole.
  double aperture() const { return spec_.aperture; }
  /// The distance along vTo where the lens focuses (vpDistance unless set).
  double focalDistance() const { return focal_; }
  /// This camera as data (after any move, rotate or lookAt: location, vTo and vUp as they are
  /// now).
  const CameraSpec& spec() const { return spec_; }

  /// Renders every pixel into the camera's image, row by row, with the builder's pixel sampler
  /// (by default one ray through each pixel's centre, the course's).
  /// @param stop when given and set (from a signal handler, say), the render stops within one
  ///        row and throws RenderInterrupted; the image is then incomplete.
  /// The rays it cast are then rayCounts().
  /// @throws std::logic_error naming "rayTracer" when no tracer was set.
  Camera& renderImage(const std::atomic<bool>* stop = nullptr);
  /// The rays the last renderImage cast (the rows it finished, when it was stopped).
  const RayCounts& rayCounts() const { return counts_; }
  /// Paints every pixel whose column or row is a multiple of interval.
  /// @throws std::invalid_argument for interval < 1.
  Camera& printGrid(int interval, const Color& color);
  /// Writes the image through the image writer.
  /// @throws std::logic_error naming "imageWriter" when no writer was set; std::runtime_error
  ///         when the file cannot be written.
  Camera& writeToImage(const std::string& path);

  /// The camera's own image (the course's renderImage and writeToImage use it; renderBlock can
  /// render into it too), nX x nY black pixels until rendered.
  const Image& image() const { return image_; }
  Image& image() { return image_; }

  // Transformations (a bonus of the Java course's camera stage). Each keeps the frame orthonormal.
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
  friend class CameraBuilder;
  Camera() = default;
  /// The ray through the view-plane point at xRight·vRight + yUp·vUp from its centre.
  Ray viewPlaneRay(double xRight, double yUp, const Sample2& lens) const noexcept;
  /// Sets the frame and writes it into spec_ (as to and up, no target).
  void setFrame(const Vector& vTo, const Vector& vUp, const Vector& vRight);

  CameraSpec spec_;
  Vector vTo_ = Vector(0, 0, -1);
  Vector vUp_ = Vector::AXIS_Y;
  Vector vRight_ = Vector::AXIS_X;
  double pixelWidth_ = 0, pixelHeight_ = 0;  ///< w/nX, h/nY
  double focal_ = 0;                         ///< focalDistance, or vpDistance when not set
  std::shared_ptr<const RayTracer> rayTracer_;
  std::shared_ptr<const ImageWriter> imageWriter_;
  std::shared_ptr<const PixelSampler> pixelSampler_;
  Image image_;
  RayCounts counts_;
};

/// Collects the camera's data into a CameraSpec; each setter validates its field, build()
/// checks that nothing is missing.
class CameraBuilder {
 public:
  CameraBuilder() = default;
  /// Every field of spec, through the setters below.
  /// @throws std::invalid_argument for a field a setter refuses.
  explicit CameraBuilder(const CameraSpec& spec);

  /// @throws std::invalid_argument unless finite.
  CameraBuilder& setLocation(const Point& p0);
  /// vTo and vUp given directly; @throws std::invalid_argument unless they are orthogonal.
  CameraBuilder& setDirection(const Vector& vTo, const Vector& vUp);
  /// Look at target: vTo = normalize(target - p0), vRight = normalize(vTo x up),
  /// vUp = vRight x vTo (up need not be orthogonal to vTo). Resolved at build(), after the
  /// location is known. @throws std::invalid_argument (at build) when up is parallel to vTo
  /// or target is the location.
  CameraBuilder& setDirection(const Point& target, const Vector& up = Vector::AXIS_Y);
  /// @throws std::invalid_argument unless both are positive (above the course's zero).
  CameraBuilder& setVpSize(double width, double height);
  /// @throws std::invalid_argument unless positive (above the course's zero).
  CameraBuilder& setVpDistance(double distance);
  /// @throws std::invalid_argument unless both are at least 1.
  CameraBuilder& setResolution(int nX, int nY);
  /// The lens radius: 0 (the default) is a pinhole.
  /// @throws std::invalid_argument unless finite and >= 0.
  CameraBuilder& setAperture(double radius);
  /// Where a lens focuses, along vTo: 0 (the default) means at the view plane.
  /// @throws std::invalid_argument unless finite and >= 0.
  CameraBuilder& setFocalDistance(double distance);
  CameraBuilder& setRayTracer(std::shared_ptr<const RayTracer> tracer);
  CameraBuilder& setImageWriter(std::shared_ptr<const ImageWriter> writer);
  /// How renderImage estimates a pixel (default: one ray through its centre).
  CameraBuilder& setPixelSampler(std::shared_ptr<const PixelSampler> sampler);

  /// @throws std::logic_error "Camera::Builder: missing rendering data 'FIELD'" naming the first
  ///         missing field among location, direction, vpSize, vpDistance, resolution;
  ///         std::invalid_argument when the look-at direction is undefined, or the view plane is
  ///         so close to a far-away location that its points round to the location itself.
  Camera build() const;

 private:
  CameraSpec spec_;
  bool hasLocation_ = false;
  std::shared_ptr<const RayTracer> rayTracer_;
  std::shared_ptr<const ImageWriter> imageWriter_;
  std::shared_ptr<const PixelSampler> pixelSampler_;
};

}  // namespace rt
