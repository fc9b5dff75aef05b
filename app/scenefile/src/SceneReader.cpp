// Reading a scene file: the document's keys as this build's parts of the format assemble them
// (Format.h, parts/), read with the one mechanism of KeyTable.h.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "Format.h"
#include "KeyTable.h"
#include "Node.h"
#include "SourceMap.h"
#include "scenefile/SceneFile.h"

namespace rt {

// ---------------------------------------------------------------------------------------------
// The public API

SceneDocument parseScene(std::string_view text, const std::string& sourceName,
                         const ModelFileSource& models) {
  using namespace scenefile;
  SourceMap map;
  if (const std::optional<SyntaxProblem> problem = scanSource(text, map)) {
    const LineColumn lc = lineColumnOf(text, problem->offset);
    throw SceneError(sourceName, lc.line, lc.column, problem->path, problem->detail);
  }
  // The text is valid JSON (the first pass checked it with the same parser).
  const Json root = Json::parse(text.begin(), text.end());
  Context ctx(text, sourceName, map);
  ctx.models = models;
  const SceneFormat& format = sceneFormat();
  ctx.doc.scene = format.liftScene(Scene{});
  static const KeyTable<SceneDocument> documentKeys = format.table<SceneDocument>("document");
  const Node document(ctx, root);
  readObject(document, documentKeys, ctx.doc, "a scene object");
  for (const auto& check : format.checkRead) check(document);
  return std::move(ctx.doc);
}

SceneDocument loadScene(const std::string& path) { return parseScene(readSceneText(path), path); }

std::string readSceneText(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError("cannot read " + path + ": it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("cannot read " + path + ": " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > MAX_SCENE_FILE_BYTES)
      throw SceneError("cannot read " + path + ": larger than " +
                       std::to_string(MAX_SCENE_FILE_BYTES >> 20) + " MiB");
  }
  if (in.bad()) throw SceneError("cannot read " + path + ": " + std::strerror(errno));
  return text;
}

std::vector<std::string_view> knownTracers() { return scenefile::sceneFormat().tracers(); }

std::string_view missingTracerStage(std::string_view name) {
  const std::vector<std::string_view> present = knownTracers();
  if (std::find(present.begin(), present.end(), name) != present.end()) return {};
  for (const scenefile::CatalogueTracer& t : scenefile::tracerCatalogue())
    if (t.name == name) return t.stage;
  return {};
}

std::shared_ptr<Scene> sceneModelOf(const Scene& scene) {
  return scenefile::sceneFormat().liftScene(scene);
}

std::vector<SceneKeyInfo> sceneFormatKeys() {
  std::vector<SceneKeyInfo> out;
  for (const scenefile::CatalogueKey& k : scenefile::keyCatalogue())
    out.push_back({std::string(k.object), std::string(k.key), std::string(k.stage),
                   k.presence == scenefile::Presence::Required, std::string(k.defaultText)});
  return out;
}

}  // namespace rt
