#pragma once
/// @file SceneDocument.h
/// Everything a scene file (or a built-in scene) describes: the scene, its cameras, the render
/// settings, and the names the file gave to things.
///
/// The document is the same in every course cut; what it holds depends on the stages present.
/// Its scene is the model of the highest stage that has one: a stage-4 Scene in a cut after
/// stage 4, a LitScene (lights, appearances) from stage 5 on (scenefile/LitDocument.h gives
/// typed access to it, and to the named materials). The render settings are plain data whose
/// meaning the stage that reads them supplies (render.samples is mini project 1's, say).

#include <any>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <typeindex>
#include <vector>

#include "camera/CameraSpec.h"
#include "camera/Scene.h"

namespace rt {

/// The `render` object of a scene file.
struct RenderSettings {
  std::string tracer;               ///< which stage's tracer renders it; "": the build's highest
  std::uint64_t seed = 0;           ///< the random numbers' seed: changes the noise, nothing else
  int gridLines = 0;                ///< stage 4: a line every N pixels on the image; 0: none
  Color gridColor{255, 255, 0};     ///< stage 4: the lines' colour (the course's yellow)
  int maxLevel = 10;                ///< stage 7: the recursion's depth
  double minK = 0.001;              ///< stage 7: the path weight's cut-off
  int samples = 1;                  ///< mini 1: N x N jittered samples per pixel
  int lensSamples = 1;              ///< mini 1: rays through the lens per sample (camera key)
  bool adaptive = false;            ///< mini 1: adaptive super-sampling instead
  double adaptiveThreshold = 16;    ///< mini 1: the colour difference that splits a square
  int adaptiveDepth = 2;            ///< mini 1: the adaptive sampler's depth limit
  std::string beamDepth = "first";  ///< mini 1: beams at the "first" bounce or at "every" one
  std::string accel = "bvh4";       ///< mini 2: "none", "cbr", "bvh", "bvh4" or "grid"
  bool lightBuffers = true;         ///< mini 2: a light buffer per point light for shadow rays
  int threads = 0;                  ///< mini 2: render threads; 0: every core

  bool operator==(const RenderSettings&) const = default;
};

struct SceneDocument {
  /// The scene; its dynamic type is the highest stage's model (see above). A copy of the
  /// document shares it.
  std::shared_ptr<Scene> scene;
  CameraSpec camera;
  /// Other points of view, by name, in the file's order (`rt render SCENE --view NAME`).
  std::vector<NamedView> views;
  RenderSettings render;
  /// The names the file gave to shapes, by geometry index: only the named ones (a generated
  /// scene of a million unnamed stars keeps none).
  std::map<std::uint32_t, std::string> geometryNames;
  /// What the reader found questionable but not wrong, one message per problem, each naming the
  /// file, line and column and the JSON path like an error ("x.json:9:5: geometries[4]: ...";
  /// stage 7: glass faces wound both ways). Empty for a built-in scene; never written.
  std::vector<std::string> warnings;

  /// Geometry i's name, or nullptr when it has none.
  const std::string* geometryName(std::uint32_t i) const {
    const auto it = geometryNames.find(i);
    return it == geometryNames.end() ? nullptr : &it->second;
  }

  /// What a stage's part of the format keeps about the file beyond the scene (stage 5: the named
  /// materials and which rows of the appearance table use them), one value per type.
  template <typename T>
  T& part() {
    std::any& slot = parts_[std::type_index(typeid(T))];
    if (!slot.has_value()) slot = T{};
    return std::any_cast<T&>(slot);
  }
  /// The part of type T, or nullptr when the document has none.
  template <typename T>
  const T* findPart() const {
    const auto it = parts_.find(std::type_index(typeid(T)));
    return it == parts_.end() ? nullptr : std::any_cast<T>(&it->second);
  }

 private:
  std::map<std::type_index, std::any> parts_;
};

}  // namespace rt
