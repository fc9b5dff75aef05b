#pragma once
/// @file GlossyScene.h
/// A lit scene whose materials may blur and whose lights may have a size: the data of the first
/// mini project, added beside stage 5's appearance table and light list (a lower stage never
/// learns about it).

#include <cstdint>
#include <vector>

#include "glossy/RayBeam.h"
#include "lighting/LitScene.h"

namespace rt {

/// How a material blurs: a glossy surface spreads its reflected ray into a beam, diffused glass
/// its refracted ray.
struct Blur {
  BeamSettings reflected;  ///< glossy reflection
  BeamSettings refracted;  ///< diffused (frosted) glass

  bool operator==(const Blur&) const = default;
};

/// The size of a point or spot light: a disk of this radius facing the shaded point, sampled by
/// `samples` shadow rays (soft shadows). Radius 0 is the course's point light (one shadow ray).
struct LightSize {
  /// The most shadow rays one light may cast per shaded point.
  static constexpr int MAX_SAMPLES = 4096;

  double radius = 0;  ///< >= 0
  int samples = 1;    ///< 1..MAX_SAMPLES

  /// True when the light has an area to sample (radius > 0 and more than one sample).
  bool isArea() const noexcept { return radius > 0 && samples > 1; }

  bool operator==(const LightSize&) const = default;
};

struct GlossyScene : LitScene {
  /// blur[row] belongs to row `row` of the appearance table; rows beyond the end do not blur.
  std::vector<Blur> blur;
  /// lightSizes[i] belongs to lights[i]; lights beyond the end are points.
  std::vector<LightSize> lightSizes;

  GlossyScene() = default;
  /// A lit scene as a glossy one: nothing blurs, every light is a point.
  explicit GlossyScene(const LitScene& base) : LitScene(base) {}

  /// Adds a row to the appearance table with its blur and returns its index.
  /// @throws std::invalid_argument for an invalid material or blur.
  std::uint32_t addAppearance(const Color& emission, const Material& material = {},
                              const Blur& rowBlur = {});
  using LitScene::add;
  /// Adds a light with its size. @throws std::invalid_argument for an invalid light or size.
  GlossyScene& addLight(LightSource light, const LightSize& size = {});

  /// The blur of shape `geometry`'s row. Not checked (per-ray code; see validate()).
  const Blur& blurOfRow(std::uint32_t row) const noexcept {
    static const Blur none{};
    return row < blur.size() ? blur[row] : none;
  }
  /// The size of light i (a point when none was given).
  const LightSize& sizeOfLight(std::uint32_t i) const noexcept {
    static const LightSize point{};
    return i < lightSizes.size() ? lightSizes[i] : point;
  }

  /// LitScene::validate, then: no more blurs than rows and no more sizes than lights, every blur
  /// and size valid, and no size on a directional light (it has no position).
  /// @throws std::logic_error or std::invalid_argument naming the entry and the field.
  void validate() const;
};

/// @throws std::invalid_argument "<what>: radius must be ..." / "samples must be ...".
void validate(const LightSize& size, const char* what);

}  // namespace rt
