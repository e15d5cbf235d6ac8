// A ks texture (a specular map): its value multiplies ks, channel by
// channel, in the one Phong model that every algorithm shades with, so that
// black leaves no highlight, white the material's own, and a colour tints it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/image_io.hpp"
#include "io/scene_file.hpp"
#include "scene/scene.hpp"
#include "shading/bump_mapping.hpp"
#include "shading/material_at_point.hpp"
#include "shading/phong.hpp"
#include "support/raster_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

TEST(SpecularMap, KsScalesTheHighlightChannelByChannel) {
  Material material;
  material.kd = 0.5f;
  material.n = 4.0f;
  // Light and viewer both along the normal: the highlight is at its peak.
  const LightSample light{Vec3(0, 0, 1), 1.0f, Color(1.0f)};
  const auto direct = [&](const Color& ks) {
    return phongDirect(material, {Color(0.2f), ks}, Vec3(0, 0, 1), Vec3(0, 0, 1), light);
  };
  const auto expectNear = [](const Color& actual, const Color& expected) {
    EXPECT_LT(glm::length(actual - expected), 1e-6f)
        << actual.r << " " << actual.g << " " << actual.b;
  };
  expectNear(direct(Color(0.0f)), Color(0.1f));
  expectNear(direct(Color(0.7f)), Color(0.8f));
  expectNear(direct(Color(1.0f, 0.0f, 0.5f)), Color(1.1f, 0.1f, 0.6f));
}

// A shiny sphere whose only light is its highlight (no ambient, no
// diffuse), with `ksTexture` when given.
Scene highlightScene(const std::string& ksTexture) {
  return loadScene(
      "image: {width: 48, height: 36}\n"
      "camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 40}\n"
      "lights:\n  - point: {position: [-3, 3, -6], color: [1, 1, 1]}\n"
      "materials:\n  shiny: {color: [0.5, 0.5, 0.5], ka: 0, kd: 0, ks: 0.8, n: 20" +
          (ksTexture.empty() ? "" : ", ks_texture: " + ksTexture) +
          "}\n"
          "objects:\n  - sphere: {center: [0, 0, 0], radius: 1, material: shiny}\n",
      "highlight.yaml");
}

float brightest(const Image& image, int channel) {
  float most = 0.0f;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) most = std::max(most, image.at(x, y)[channel]);
  return most;
}

TEST(SpecularMap, BlackKillsTheHighlightAndWhiteKeepsItInEveryAlgorithm) {
  const Scene plain = highlightScene("");
  const Scene black = highlightScene("{checker: {colors: [[0, 0, 0], [0, 0, 0]]}}");
  const Scene white = highlightScene("{checker: {colors: [[1, 1, 1], [1, 1, 1]]}}");
  const Scene red = highlightScene("{checker: {colors: [[1, 0, 0], [1, 0, 0]]}}");
  for (const std::string_view algorithm : {"ray-tracing", "z-buffer", "scanline"}) {
    for (const Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
      RenderSettings settings = settingsFor(plain);
      settings.shading = shading;
      const Image highlight = raster_testing::render(algorithm, plain, settings).image;
      ASSERT_GT(brightest(highlight, 0), 0.3f) << algorithm;
      const Image none = raster_testing::render(algorithm, black, settings).image;
      const Image kept = raster_testing::render(algorithm, white, settings).image;
      const Image tinted = raster_testing::render(algorithm, red, settings).image;
      for (int y = 0; y < highlight.height(); ++y) {
        for (int x = 0; x < highlight.width(); ++x) {
          const bool onTheSphere = highlight.at(x, y) != plain.image.background;
          if (!onTheSphere) continue;
          EXPECT_EQ(none.at(x, y), Color(0.0f)) << algorithm << " " << x << " " << y;
          EXPECT_EQ(kept.at(x, y), highlight.at(x, y)) << algorithm << " " << x << " " << y;
          EXPECT_EQ(tinted.at(x, y), Color(highlight.at(x, y).r, 0.0f, 0.0f))
              << algorithm << " " << x << " " << y;
        }
      }
    }
  }
}

using SpecularMapFile = TemporaryFolderTest;

TEST_F(SpecularMapFile, ReadsAnImageLinearly) {
  // Stored as 128 of 255: linearly about a half, where sRGB would decode it
  // to 0.2159.
  Image grey(2, 2, Color(128.0f / 255.0f));
  writeImage(grey, directory_ / "grey.png", Encoding::Linear);
  std::ofstream(directory_ / "scene.yaml")
      << "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n"
         "materials:\n  half: {ks: 0.6, ks_texture: {image: grey.png}}\n"
         "objects:\n  - sphere: {center: [0, 0, 0], radius: 1, material: half}\n";
  const Scene scene = loadSceneFile(directory_ / "scene.yaml");
  const SurfacePoint point(Vec3(0, 0, -1), Vec3(0, 0, -1), Vec2(0.3f, 0.6f));
  const Color ks = surfaceColors(scene.materials[0], point).ks;
  EXPECT_NEAR(ks.r, 0.6f * 128.0f / 255.0f, 1e-5f);
  EXPECT_NEAR(ks.b, 0.6f * 128.0f / 255.0f, 1e-5f);
}

}  // namespace
}  // namespace rise
