// A render split into regions, as processes split it among themselves: every
// algorithm, each region holding the very values the whole image has there,
// with filters whose samples reach past a tile, adaptive refinement, and
// regions that do not fall on the ray tracers' own tiles.
#include <gtest/gtest.h>

#include <string>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"

namespace rise {
namespace {

struct Case {
  std::string scene;
  SamplePattern pattern;
  FilterKind filter;
  int samples;
};

class RegionRender : public testing::TestWithParam<Case> {};

TEST_P(RegionRender, EqualsTheWholeImageThere) {
  const Case& sampled = GetParam();
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + sampled.scene);
  RenderRequest request;
  request.image = {37, 29, sampled.samples, sampled.pattern, sampled.filter, std::nullopt};
  request.settings.threads = 2;
  const RenderSettings whole = settingsFor(scene, request);
  const PixelRect regions[] = {{0, 0, 37, 29}, {3, 5, 20, 23}, {17, 16, 37, 29}, {36, 0, 37, 1}};
  for (const Renderer* renderer : allRenderers()) {
    RenderObserver observer;
    const RenderResult expected = renderer->render(scene, whole, observer);
    for (const PixelRect& region : regions) {
      RenderSettings part = whole;
      part.region = region;
      const RenderResult result = renderer->render(scene, part, observer);
      ASSERT_EQ(result.image.width(), region.width());
      ASSERT_EQ(result.image.height(), region.height());
      for (const auto& [name, buffer] : result.buffers)
        EXPECT_EQ(buffer.width(), region.width()) << name;
      int differing = 0;
      for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x)
          differing += result.image.at(x - region.x0, y - region.y0) != expected.image.at(x, y);
      EXPECT_EQ(differing, 0) << renderer->name() << " in " << region.x0 << "," << region.y0;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Sampling, RegionRender,
    testing::Values(Case{"classic.yaml", SamplePattern::None, FilterKind::Box, 1},
                    Case{"soft-shadows.yaml", SamplePattern::Jittered, FilterKind::Gaussian, 4},
                    Case{"spheres.yaml", SamplePattern::Adaptive, FilterKind::Box, 16},
                    Case{"motion-blur.yaml", SamplePattern::Random, FilterKind::Tent, 3}),
    [](const testing::TestParamInfo<Case>& info) {
      std::string name = info.param.scene.substr(0, info.param.scene.find('.'));
      for (char& c : name)
        if (c == '-') c = '_';
      return name;
    });

TEST(RegionSettings, ARegionOutsideTheImageIsRefusedWithItsSize) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  RenderRequest request;
  request.image.width = 40;
  request.image.height = 30;
  request.settings.region = PixelRect{30, 0, 41, 10};
  try {
    settingsFor(scene, request);
    FAIL() << "a region beyond the image was accepted";
  } catch (const SettingsError& error) {
    EXPECT_NE(std::string(error.what()).find("30,0,11,10"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("40x30"), std::string::npos) << error.what();
  }
}

// The shadow map is the light's view, not the image's: a region takes it whole.
TEST(RegionRender, KeepsTheShadowMapWhole) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  RenderRequest request;
  request.image.width = 41;
  request.image.height = 23;
  request.settings.shadows = ShadowMethod::Map;
  request.settings.shadowMapSize = 64;
  const RenderSettings whole = settingsFor(scene, request);
  RenderSettings part = whole;
  part.region = PixelRect{5, 3, 30, 20};
  RenderObserver observer;
  const Renderer& zBuffer = *findRenderer("z-buffer");
  const RenderResult expected = zBuffer.render(scene, whole, observer);
  const RenderResult result = zBuffer.render(scene, part, observer);
  const Image& map = result.buffers.at("shadow-map");
  const Image& wholeMap = expected.buffers.at("shadow-map");
  ASSERT_EQ(map.width(), wholeMap.width());
  ASSERT_EQ(map.height(), wholeMap.height());
  EXPECT_GT(map.width(), part.region->width());
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) ASSERT_EQ(map.at(x, y), wholeMap.at(x, y));
  EXPECT_EQ(result.buffers.at("depth").width(), part.region->width());
}

}  // namespace
}  // namespace rise
