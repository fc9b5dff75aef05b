#include "lighting/AppearanceInterner.h"

#include <utility>

namespace rt {

namespace {

/// Appends the bytes of a value: equal keys mean identical bits.
template <typename T>
void appendBits(std::string& key, const T& value) {
  key.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// The key of a look: its bits, then the label (after the fixed-size bits, so that no two
/// different (look, label) pairs make the same key).
std::string keyOf(const Appearance& look, std::string_view label) {
  std::string key;
  appendBits(key, look.emission.rgb());
  const Material& m = look.material;
  for (const Double3* k : {&m.kD, &m.kS, &m.kT, &m.kR}) appendBits(key, *k);
  appendBits(key, m.shininess);
  appendBits(key, m.ior);
  for (const BeamSettings* b : {&m.reflectedBeam, &m.refractedBeam}) {
    appendBits(key, b->distance);
    appendBits(key, b->radius);
    appendBits(key, b->grid);
  }
  key += label;
  return key;
}

}  // namespace

std::uint32_t AppearanceInterner::row(const Appearance& look, std::string_view label) {
  std::string key = keyOf(look, label);
  if (const auto it = rows_.find(key); it != rows_.end()) return it->second;
  const std::uint32_t added = scene_->addAppearance(look.emission, look.material);
  rows_.emplace(std::move(key), added);
  return added;
}

std::uint32_t AppearanceInterner::add(Geometry shape, const Appearance& look,
                                      std::string_view label) {
  return scene_->add(std::move(shape), row(look, label));
}

}  // namespace rt
