#include "io/scene_document.hpp"

#include <gtest/gtest.h>

#include "io/scene_error.hpp"

namespace rise {
namespace {

const std::string kScene = R"(# a comment that edits of values keep
camera: {position: [0, 1, -5], look_at: [0, 1, 0], up: [0, 1, 0], fov: 50}
materials:
  red: {color: [0.9, 0.1, 0.1]}   # red
objects:
  - sphere: {center: [0, 1, 0], radius: 1, material: red}
  - sphere: {center: [2, 1, 0], radius: 0.5, material: red}
)";

SceneDocument document() { return SceneDocument(kScene, "scene.yaml"); }

TEST(SceneDocument, FindsEntriesByPath) {
  const SceneDocument scene = document();
  EXPECT_EQ(scene.keys(""), (std::vector<std::string>{"camera", "materials", "objects"}));
  EXPECT_EQ(scene.kind("objects"), SceneDocument::Kind::List);
  EXPECT_EQ(scene.kind("objects/1/sphere"), SceneDocument::Kind::Map);
  EXPECT_EQ(scene.kind("objects/1/sphere/radius"), SceneDocument::Kind::Value);
  EXPECT_EQ(scene.kind("objects/2"), SceneDocument::Kind::Missing);
  EXPECT_EQ(scene.kind("objects/x/sphere"), SceneDocument::Kind::Missing);
  EXPECT_EQ(scene.size("objects"), 2);
  EXPECT_EQ(scene.value("objects/1/sphere/radius"), "0.5");
  EXPECT_EQ(scene.line("objects/1"), 7);
}

TEST(SceneDocument, ReplacesValuesInTheTextKeepingEverythingElse) {
  const SceneDocument edited = document()
                                   .withValue("objects/1/sphere/radius", "0.75")
                                   .withValue("materials/red/color", "[0.2, 0.8, 0.3]");
  std::string expected = kScene;
  expected.replace(expected.find("radius: 0.5"), 11, "radius: 0.75");
  expected.replace(expected.find("[0.9, 0.1, 0.1]"), 15, "[0.2, 0.8, 0.3]");
  EXPECT_EQ(edited.text(), expected);
  EXPECT_FLOAT_EQ(edited.load().materials[0].color.g, 0.8f);
}

TEST(SceneDocument, AddsKeysAndItemsAndRemovesThem) {
  const SceneDocument added =
      document()
          .withValue("materials/red/reflection", "0.5")
          .withItem("lights", "point: {position: [0, 5, 0], color: [1, 1, 1]}");
  EXPECT_EQ(added.value("materials/red/reflection"), "0.5");
  EXPECT_EQ(added.load().lights.size(), 1u);
  const SceneDocument removed = added.without("lights/0").without("materials/red/reflection");
  EXPECT_EQ(removed.size("lights"), 0);
  EXPECT_EQ(removed.kind("materials/red/reflection"), SceneDocument::Kind::Missing);
  EXPECT_EQ(removed.load().shapes.size(), 2u);
}

TEST(SceneDocument, CopiesAnItemRightAfterIt) {
  const SceneDocument copied = document().withCopy("objects/0");
  ASSERT_EQ(copied.size("objects"), 3);
  EXPECT_EQ(copied.value("objects/1/sphere/radius"), "1");
  EXPECT_EQ(copied.value("objects/2/sphere/radius"), "0.5");
  EXPECT_EQ(copied.load().shapes.size(), 3u);
}

TEST(SceneDocument, ValuesThatNeedQuotingAreNotSplicedRaw) {
  // Spliced raw, "1, radius: 2" would add a second key to the sphere.
  const SceneDocument edited = document().withValue("objects/0/sphere/material", "'a, b: c'");
  EXPECT_EQ(edited.value("objects/0/sphere/material"), "a, b: c");
  EXPECT_EQ(edited.keys("objects/0/sphere"),
            (std::vector<std::string>{"center", "radius", "material"}));
}

TEST(SceneDocument, LeavesValidationToTheLoader) {
  const SceneDocument negative = document().withValue("objects/0/sphere/radius", "-1");
  try {
    negative.load();
    FAIL() << "a negative radius loaded";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.line(), 6);
    EXPECT_NE(error.message().find("radius"), std::string::npos) << error.what();
  }
}

TEST(SceneDocument, RefusesWhatIsNotYamlOrLeadsNowhere) {
  EXPECT_THROW(document().withValue("objects/0/sphere/radius", "[1, 2"), DocumentError);
  EXPECT_THROW(document().without("objects/5"), DocumentError);
  EXPECT_THROW(document().withCopy("camera"), DocumentError);
  EXPECT_THROW(document().withItem("camera", "1"), DocumentError);
  try {
    SceneDocument("objects: [1, 2\n", "broken.yaml");
    FAIL() << "broken YAML parsed";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), "broken.yaml");
    EXPECT_GT(error.line(), 0);
    EXPECT_NE(error.message().find("not closed"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace rise
