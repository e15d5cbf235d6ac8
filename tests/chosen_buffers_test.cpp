// A front end that writes only some auxiliary buffers (`rise render --aov`)
// names them in the settings, and the algorithms make only those: every
// algorithm, with one sample and with several, gives the same image and the
// same values in the buffers it was asked for as when it makes them all. The
// depth buffer's picture is the same for every algorithm, and of many grey
// levels, whatever the floor's far reaches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/image_io.hpp"
#include "io/scene_file.hpp"
#include "render/buffer_images.hpp"

namespace rise {
namespace {

std::vector<std::string> namesOf(const RenderResult& result) {
  std::vector<std::string> names;
  for (const auto& [name, buffer] : result.buffers) names.push_back(name);
  return names;
}

TEST(ChosenBuffers, OnlyThoseNamedAreMadeAndTheImageIsTheSame) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml");
  for (const int samples : {1, 3}) {
    RenderRequest request;
    request.image.width = 41;
    request.image.height = 23;
    request.image.samples = samples;
    request.settings.threads = 2;
    const RenderSettings all = settingsFor(scene, request);
    for (const Renderer* renderer : allRenderers()) {
      RenderObserver observer;
      const RenderResult everything = renderer->render(scene, all, observer);
      for (const std::vector<std::string>& chosen :
           {std::vector<std::string>{}, {"normal"}, {"face", "depth"}, {"cost"}}) {
        RenderSettings some = all;
        some.buffers = chosen;
        const RenderResult result = renderer->render(scene, some, observer);
        EXPECT_EQ(result.image.pixels(), everything.image.pixels()) << renderer->name();
        std::vector<std::string> expected;
        for (const std::string& name : chosen)
          if (renderer->description().writes(name)) expected.push_back(name);
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(namesOf(result), expected) << renderer->name() << ", " << samples << " samples";
        for (const auto& [name, buffer] : result.buffers)
          EXPECT_EQ(buffer.pixels(), everything.buffers.at(name).pixels())
              << renderer->name() << ": " << name;
      }
    }
  }
}

// Flat and Gouraud shading find no point of the surface where no texture
// and no buffer needs one: every shading gives the same image whether the
// depth and normal are wanted or not, on plain and on textured materials.
TEST(ChosenBuffers, EveryShadingGivesTheSameImageWithoutTheDepthAndNormal) {
  for (const char* file : {"classic.yaml", "textures.yaml"}) {
    const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + file);
    RenderRequest request;
    request.image.width = 37;
    request.image.height = 29;
    request.settings.threads = 2;
    for (const Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
      RenderSettings all = settingsFor(scene, request);
      all.shading = shading;
      RenderSettings imageAlone = all;
      imageAlone.buffers = std::vector<std::string>{};
      for (const Renderer* renderer : allRenderers()) {
        if (!renderer->description().reads(Option::Shading)) continue;
        RenderObserver observer;
        EXPECT_EQ(renderer->render(scene, imageAlone, observer).image.pixels(),
                  renderer->render(scene, all, observer).image.pixels())
            << renderer->name() << ", " << file << ", " << shadingName(shading);
      }
    }
  }
}

// The README's `--aov depth` of the spheres example: the ray tracer's
// infinite floor and the z-buffer's floor of 100,000 units give the same
// picture, of a hundred grey levels and more, not a score of them.
TEST(ChosenBuffers, TheDepthPictureHasManyLevelsAndIsAlikeForEveryAlgorithm) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/spheres.yaml");
  RenderRequest request;
  request.image.width = 160;
  request.image.height = 120;
  RenderSettings settings = settingsFor(scene, request);
  settings.buffers = {"depth"};
  const auto picture = [&](std::string_view algorithm) {
    RenderObserver observer;
    return visualizeBuffer(
        "depth", findRenderer(algorithm)->render(scene, settings, observer).buffers.at("depth"));
  };
  const Image traced = picture("ray-tracing"), drawn = picture("z-buffer");
  std::set<long> levels;
  int apart = 0;
  for (int y = 0; y < traced.height(); ++y)
    for (int x = 0; x < traced.width(); ++x) {
      const long level = std::lround(255.0f * srgbFromLinear(traced.at(x, y).r));
      levels.insert(level);
      apart += std::abs(level - std::lround(255.0f * srgbFromLinear(drawn.at(x, y).r))) > 3;
    }
  EXPECT_GE(levels.size(), 100u);
  EXPECT_LE(apart, traced.width() * traced.height() / 50);
}

}  // namespace
}  // namespace rise
