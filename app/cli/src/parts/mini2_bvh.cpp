// What rt knows of mini project 2: the acceleration structure a render asks for
// (render.accel: none, cbr or bvh; --accel), built once over the scene's shapes before any ray.
#include "bvh/Bvh.h"
#include "bvh/Cbr.h"
#include "cli/Registry.h"

namespace rt::cli {

void registerCli_mini2_bvh(CliRegistry& registry) {
  registry.makeAccelerator = [](const SceneDocument& doc) -> std::unique_ptr<Intersectable> {
    const Geometries& shapes = doc.scene->geometries;
    if (doc.render.accel == "bvh") return std::make_unique<Bvh>(shapes);
    if (doc.render.accel == "cbr") return std::make_unique<Cbr>(shapes);
    return nullptr;  // "none": the course's list
  };
}

}  // namespace rt::cli
