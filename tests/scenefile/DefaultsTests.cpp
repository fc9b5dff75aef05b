// Defaults: what a key left out of a file means, and that it agrees with the model's own
// defaults (the tables' default JSON is read through the same readers as the file).
#include <gtest/gtest.h>

#include <string>

#include "SceneCompare.h"
#include "scenefile/LitDocument.h"
#include "scenefile/SceneFile.h"

namespace rt {
namespace {

using testing::sameBits;

const std::string CAMERA =
    "\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], \"vpDistance\": 10, "
    "\"vpSize\": [2, 2], \"resolution\": [4, 4]}";

SceneDocument parse(const std::string& rest) {
  return parseScene("{" + CAMERA + (rest.empty() ? "" : ", " + rest) + "}", "defaults.json");
}

bool same(const Double3& a, const Double3& b) {
  return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

bool same(const Material& a, const Material& b) {
  return same(a.kD, b.kD) && same(a.kS, b.kS) && same(a.kT, b.kT) && same(a.kR, b.kR) &&
         a.shininess == b.shininess && sameBits(a.ior, b.ior);
}

TEST(DefaultsTest, Document) {
  // EP01: only a camera: no name, black background, no ambient light, nothing in the scene,
  // the model's render settings.
  const SceneDocument doc = parse("");
  EXPECT_EQ(litScene(doc).name, "");
  EXPECT_TRUE(same(litScene(doc).background.rgb(), Color::BLACK.rgb()));
  EXPECT_TRUE(same(litScene(doc).ambientLight.ia().rgb(), AmbientLight::NONE.ia().rgb()));
  EXPECT_TRUE(same(litScene(doc).ambientLight.kA(), AmbientLight::NONE.kA()));
  EXPECT_TRUE(litScene(doc).lights.empty());
  EXPECT_TRUE(litScene(doc).geometries.empty());
  EXPECT_TRUE(namedMaterials(doc).materials.empty());
  const RenderSettings model;
  EXPECT_EQ(doc.render.tracer, model.tracer);
  EXPECT_EQ(doc.render.maxLevel, model.maxLevel);
  EXPECT_TRUE(sameBits(doc.render.minK, model.minK));
  // EP02: no grid lines, and yellow ones when asked for (the course's printGrid colour)
  EXPECT_EQ(doc.render.gridLines, 0);
  EXPECT_EQ(doc.render.gridColor, Color(255, 255, 0));
}

TEST(DefaultsTest, Camera) {
  // EP01: up defaults to +Y with a target; the given values are kept as written.
  const SceneDocument doc = parse("");
  EXPECT_TRUE(same(doc.camera.up.xyz(), Double3(0, 1, 0)));
  ASSERT_TRUE(doc.camera.target.has_value());
  EXPECT_FALSE(doc.camera.to.has_value());
  EXPECT_TRUE(sameBits(doc.camera.vpDistance, 10));
  EXPECT_EQ(doc.camera.nX, 4);
}

TEST(DefaultsTest, ResolutionBoundaries) {
  // BV01: 1x1 and 2^15 x 2^15 are accepted (nothing is allocated at load).
  for (const char* resolution : {"[1, 1]", "[32768, 32768]"}) {
    const SceneDocument doc = parseScene(
        std::string("{\"camera\": {\"location\": [0, 0, 10], \"target\": [0, 0, 0], ") +
            "\"vpDistance\": 10, \"vpSize\": [2, 2], \"resolution\": " + resolution + "}}",
        "r.json");
    EXPECT_EQ(doc.camera.nX, doc.camera.nY);
  }
}

TEST(DefaultsTest, AmbientAndMaterial) {
  // EP01: an empty ambient object is no ambient light; an empty material is the model's
  // Material.
  const SceneDocument doc = parse("\"ambient\": {}, \"materials\": {\"plain\": {}}");
  EXPECT_TRUE(same(litScene(doc).ambientLight.kA(), Double3(1)));
  EXPECT_TRUE(same(namedMaterials(doc).materials.at("plain"), Material{}));
  // EP02: a single number is the same coefficient for r, g and b.
  const SceneDocument kA = parse("\"ambient\": {\"color\": [255, 255, 255], \"kA\": 0.25}");
  EXPECT_TRUE(same(litScene(kA).ambientLight.kA(), Double3(0.25)));
  // EP03: an integral number is accepted where an integer is expected (shininess 1e2).
  EXPECT_EQ(namedMaterials(parse("\"materials\": {\"m\": {\"shininess\": 1e2}}"))
                .materials.at("m")
                .shininess,
            100);
}

TEST(DefaultsTest, Geometry) {
  // EP01: a geometry with no emission, material or name: black, the model's Material, no name
  // and no named material.
  const SceneDocument doc =
      parse("\"geometries\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]");
  ASSERT_EQ(litScene(doc).geometries.size(), 1u);
  EXPECT_TRUE(same(litScene(doc).appearanceOf(0).emission.rgb(), Color::BLACK.rgb()));
  EXPECT_TRUE(same(litScene(doc).appearanceOf(0).material, Material{}));
  EXPECT_TRUE(doc.geometryNames.empty());
  EXPECT_EQ(materialNameOf(doc, 0), nullptr);
}

TEST(DefaultsTest, Lights) {
  // EP01: a point light's attenuation defaults to 1, 0, 0; a spot light's narrowBeam to 1.
  const SceneDocument doc = parse(
      "\"lights\": [{\"type\": \"point\", \"intensity\": [1, 2, 3], \"position\": [0, 0, 0]},"
      "{\"type\": \"spot\", \"intensity\": [1, 2, 3], \"position\": [0, 0, 0], "
      "\"direction\": [0, 0, -2]}]");
  ASSERT_EQ(litScene(doc).lights.size(), 2u);
  const auto& point = std::get<PointLight>(litScene(doc).lights[0]);
  EXPECT_TRUE(sameBits(point.kC, 1) && sameBits(point.kL, 0) && sameBits(point.kQ, 0));
  const auto& spot = std::get<SpotLight>(litScene(doc).lights[1]);
  EXPECT_TRUE(sameBits(spot.narrowBeam, 1));
  EXPECT_TRUE(same(spot.direction.xyz(), Double3(0, 0, -1)));  // stored normalised
}

TEST(DefaultsTest, LightBuffers) {
  // EP01: left out: light buffers on, the model's default
  EXPECT_TRUE(parse("").render.lightBuffers);
  EXPECT_TRUE(RenderSettings{}.lightBuffers);
  // EP02: true and false are read as written
  EXPECT_TRUE(parse("\"render\": {\"lightBuffers\": true}").render.lightBuffers);
  EXPECT_FALSE(parse("\"render\": {\"lightBuffers\": false}").render.lightBuffers);
  // EP03: the catalogue's documented default, read by the loader, is the model's
  bool listed = false;
  for (const SceneKeyInfo& k : sceneFormatKeys())
    if (k.object == "render" && k.key == "lightBuffers") {
      listed = true;
      EXPECT_EQ(k.defaultText, "true");
      EXPECT_EQ(k.stage, "mini2_bvh");
      EXPECT_EQ(parse("\"render\": {\"lightBuffers\": " + k.defaultText + "}").render.lightBuffers,
                RenderSettings{}.lightBuffers);
    }
  EXPECT_TRUE(listed);
}

TEST(DefaultsTest, TablesAgreeWithTheModel) {
  // EP01: every defaulted key's documented default, read by the loader, gives the model's
  // default: a material object with every default spelt out equals Material{}.
  const SceneDocument doc = parse(
      "\"materials\": {\"m\": {\"kD\": 0, \"kS\": 0, \"shininess\": 0, \"kT\": 0, \"kR\": 0, "
      "\"ior\": 1}}, \"render\": {\"tracer\": \"whitted\", \"maxLevel\": 10, \"minK\": 0.001}");
  EXPECT_TRUE(same(namedMaterials(doc).materials.at("m"), Material{}));
  // EP02: each key is either required, or has a default (JSON text, or "none" for the optional
  // ones whose absence means something of its own).
  for (const SceneKeyInfo& k : sceneFormatKeys()) {
    SCOPED_TRACE(k.object + "." + k.key);
    EXPECT_NE(k.required, !k.defaultText.empty());
  }
}

}  // namespace
}  // namespace rt
