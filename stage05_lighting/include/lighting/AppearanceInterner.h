#pragma once
/// @file AppearanceInterner.h

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

#include "lighting/LitScene.h"

namespace rt {

/// Gives shapes that look the same one shared row of a LitScene's appearance table.
///
/// Two looks are the same when their bits are: the emission's three channels and every field of
/// the material (mini 1's beams included), compared as bytes. So 0.0 and -0.0 make two rows (the
/// bits differ although the numbers compare equal; no tracer tells such rows apart); a NaN cannot
/// occur, as Color and Material::validate reject it. Bitwise equality is exact and cheap to hash.
/// A label keeps looks apart that are the same bits but must stay distinct rows: a scene file
/// gives its named material's name, so that an export writes each geometry's material as the
/// file gave it (by name or inline). Looks with different labels never share a row.
///
/// Only rows this interner added are shared: rows already in the table when it is made, and rows
/// added to the scene by other means, are never handed out. The interner keeps a pointer to the
/// scene: use it only while the scene lives where it was when the interner was made.
class AppearanceInterner {
 public:
  explicit AppearanceInterner(LitScene& scene) : scene_(&scene) {}

  /// The row for `look` labelled `label`: the row an earlier call added for the same bits and
  /// label, else a new row of the scene's table (LitScene::addAppearance).
  /// @throws std::invalid_argument for an invalid material (see Material::validate); no row is
  ///         added and the interner is unchanged then.
  std::uint32_t row(const Appearance& look, std::string_view label = {});

  /// Adds a shape that looks like `look` (the row of row(look, label)) and returns its index.
  /// @throws std::invalid_argument for an invalid material; nothing is added then.
  std::uint32_t add(Geometry shape, const Appearance& look, std::string_view label = {});

  /// The scene whose table this interner fills.
  LitScene& scene() const noexcept { return *scene_; }

 private:
  LitScene* scene_;
  std::unordered_map<std::string, std::uint32_t> rows_;  ///< bits and label -> row
};

}  // namespace rt
