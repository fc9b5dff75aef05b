// The scene format's mini-project-2 part: the acceleration structure and the threads.
#include "../Format.h"
#include "bvh/Acceleration.h"
#include "parallel/TilePool.h"

namespace rt::scenefile {

void registerFormat_mini2_bvh(SceneFormat& format) {
  using R = RenderSettings;
  format.attach<R>("render", "accel", [](const Node& n, R& r) {
    r.accel = readChoice(n, "an acceleration", ACCELERATION_NAMES);
  });
  format.attach<R>("render", "threads", [](const Node& n, R& r) {
    r.threads = readInteger(n, 0, RenderOptions::MAX_THREADS);
  });
  format.writeDocument.push_back([](const SceneDocument& doc, Json& j) {
    const RenderSettings d;
    Json& render = j["render"];
    if (doc.render.accel != d.accel) render["accel"] = doc.render.accel;
    if (doc.render.threads != d.threads) render["threads"] = doc.render.threads;
  });
}

}  // namespace rt::scenefile
