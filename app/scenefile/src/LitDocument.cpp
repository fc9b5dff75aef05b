// The typed access to a document's stage-5 part (scenefile/LitDocument.h).
#include "scenefile/LitDocument.h"

#include <memory>
#include <stdexcept>
#include <utility>

namespace rt {

LitScene& litScene(SceneDocument& doc) {
  auto* lit = dynamic_cast<LitScene*>(doc.scene.get());
  if (!lit) throw std::logic_error("litScene: the document's scene is not a LitScene");
  return *lit;
}

const LitScene& litScene(const SceneDocument& doc) {
  const auto* lit = dynamic_cast<const LitScene*>(doc.scene.get());
  if (!lit) throw std::logic_error("litScene: the document's scene is not a LitScene");
  return *lit;
}

NamedMaterials& namedMaterials(SceneDocument& doc) { return doc.part<NamedMaterials>(); }

const NamedMaterials& namedMaterials(const SceneDocument& doc) {
  static const NamedMaterials none;
  const NamedMaterials* m = doc.findPart<NamedMaterials>();
  return m ? *m : none;
}

const std::string* materialNameOf(const SceneDocument& doc, std::uint32_t i) {
  return materialNameOfRow(doc, litScene(doc).appearanceIndex[i]);
}

const std::string* materialNameOfRow(const SceneDocument& doc, std::uint32_t row) {
  const NamedMaterials* m = doc.findPart<NamedMaterials>();
  if (!m || row >= m->rowNames.size() || !m->rowNames[row]) return nullptr;
  return &*m->rowNames[row];
}

SceneDocument litDocument(LitScene scene, const CameraSpec& camera) {
  SceneDocument doc;
  doc.scene = std::make_shared<LitScene>(std::move(scene));
  doc.camera = camera;
  return doc;
}

}  // namespace rt
