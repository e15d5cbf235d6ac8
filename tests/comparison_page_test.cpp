// What the comparison page says is true and complete: every counter any
// algorithm reports is a number, told in words beside it; the page is titled by the
// scene's file; each picture's caption says which shadows it has, and what
// the shadow maps took; and where the hybrid is slower than the ray tracer
// whose image it draws, the page says why, from their counters.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"
#include "reports/comparison_report.hpp"
#include "reports/counter_glossary.hpp"
#include "support/example_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

using example_testing::exampleScenes;

Scene load(const std::string& name) {
  return loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
}

RenderSettings smallSettings(const Scene& scene) {
  RenderRequest request;
  request.image.width = 40;
  request.image.height = 30;
  request.settings.shadows = kComparedShadows;
  request.settings.shadowMapSize = 64;
  request.image.samples = 1;
  return settingsFor(scene, request);
}

std::vector<ComparedRender> compared(const Scene& scene, const RenderSettings& settings) {
  std::vector<ComparedRender> renders;
  for (const Renderer* renderer : allRenderers()) {
    RenderObserver observer;
    renders.push_back(
        {&renderer->description(), renderTimed(*renderer, scene, settings, observer)});
  }
  addSameImageCounters(renders, Encoding::Srgb);
  return renders;
}

TEST(ComparisonPage, EveryCounterIsANumberToldInWords) {
  std::set<std::string> untold;
  for (const std::string& name : exampleScenes()) {
    const Scene scene = load(name);
    RenderSettings settings = smallSettings(scene);
    for (const ShadowMethod shadows : {ShadowMethod::Map, ShadowMethod::Volume}) {
      settings.shadows = shadows;
      settings.transparency =
          shadows == ShadowMethod::Volume ? Transparency::ABuffer : Transparency::Sorted;
      const std::vector<ComparedRender> renders = compared(scene, settings);
      for (const std::string& counter : statisticNames(renders))
        if (!counterMeaning(counter)) untold.insert(counter);
      for (const ComparedRender& render : renders)
        for (const auto& [counter, value] : render.result.stats.entries())
          EXPECT_TRUE(std::isfinite(value))
              << name << ", " << render.algorithm->name << ": " << counter << " = " << value;
    }
  }
  EXPECT_TRUE(untold.empty()) << "counters with no line in reports/counter_glossary.cpp: " << [&] {
    std::string all;
    for (const std::string& name : untold) all += name + " ";
    return all;
  }();
}

class ComparisonPageFiles : public TemporaryFolderTest {
 protected:
  std::string page(const std::vector<ComparedRender>& renders, const std::string& scene) {
    writeComparison(directory_, scene, renders, Encoding::Srgb);
    std::ifstream file(directory_ / "index.html");
    return {std::istreambuf_iterator<char>(file), {}};
  }
};

TEST_F(ComparisonPageFiles, IsTitledByTheSceneAndSaysEachPicturesShadows) {
  const std::string path = std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml";
  const Scene scene = load("classic.yaml");
  const std::string html = page(compared(scene, smallSettings(scene)), path);
  EXPECT_NE(html.find("<title>RISE: classic.yaml</title>"), std::string::npos);
  EXPECT_EQ(html.find(std::string(RISE_SOURCE_DIR)), std::string::npos);
  const auto count = [&](const std::string& text) {
    std::size_t found = 0;
    for (std::size_t at = html.find(text); at != std::string::npos; at = html.find(text, at + 1))
      ++found;
    return found;
  };
  const std::size_t maps = count("shadows by shadow maps"), rays = count("shadows by shadow rays");
  // Each part in seconds, or, on a machine busy elsewhere, "under 0.5% of it".
  EXPECT_EQ(count(" drawing the shadow maps, "), 4u);
  EXPECT_EQ(count(" finding the visible surfaces, "), 4u);
  EXPECT_EQ(count(" shading, "), 4u);
  EXPECT_EQ(maps, 4u);
  // The ray tracers', and radiosity's, which finds its direct light by them.
  EXPECT_EQ(rays, 5u);
  EXPECT_NE(html.find("<td class=\"meaning\">rays traced, of every kind</td>"), std::string::npos);
  EXPECT_EQ(html.find("<td class=\"meaning\"></td>"), std::string::npos);
}

TEST_F(ComparisonPageFiles, SaysWhyTheHybridIsSlowerWhereItIs) {
  const auto stats = [](std::initializer_list<std::pair<const char*, double>> values) {
    Stats result;
    for (const auto& [name, value] : values) result.add(name, value);
    return result;
  };
  std::vector<ComparedRender> renders = {{&findRenderer("ray-tracing")->description(),
                                          {Image(2, 2),
                                           {},
                                           stats({{"render_seconds", 0.1},
                                                  {"rays", 1000},
                                                  {"intersection_tests", 6700},
                                                  {"intersection_tests_per_ray", 6.7}})}},
                                         {&findRenderer("hybrid")->description(),
                                          {Image(2, 2),
                                           {},
                                           stats({{"render_seconds", 0.125},
                                                  {"intersection_tests", 3000},
                                                  {"primary_rays_from_item_buffer", 500},
                                                  {"item_buffer_seconds", 0.06}})}}};
  addSameImageCounters(renders, Encoding::Srgb);
  const std::string html = page(renders, "s.yaml");
  EXPECT_NE(html.find("Slower than ray-tracing here (0.8 times its speed): its item buffer took "
                      "0.06 s, and the 500 primary rays it spared would have taken ray-tracing "
                      "about 0.05 s"),
            std::string::npos)
      << html;
  renders[1].result.stats = stats({{"render_seconds", 0.05}});
  addSameImageCounters(renders, Encoding::Srgb);
  EXPECT_EQ(page(renders, "s.yaml").find("Slower than"), std::string::npos);
}

// The split's parts are estimates: one too small to tell from zero is said
// to be so, not printed as no time at all.
TEST_F(ComparisonPageFiles, SaysAPartOfTheTimeTooSmallToMeasureIsSo) {
  Stats stats;
  stats.add("render_seconds", 0.1);
  stats.add("shadow_map_texels", 6.0 * 1024 * 1024);
  stats.add("shadow_map_seconds", 0.03);
  stats.add("visible_surface_seconds", 0.0);
  stats.add("shading_seconds", 0.05);
  const std::vector<ComparedRender> renders = {
      {&findRenderer("scanline")->description(), {Image(2, 2), {}, stats}}};
  const std::string html = page(renders, "s.yaml");
  EXPECT_NE(html.find("Of its 0.1 s: 0.03 s drawing the shadow maps, under 0.5% of it finding the "
                      "visible surfaces, 0.05 s shading, 0.02 s preparing"),
            std::string::npos)
      << html;
}

// A scene lit by emitting surfaces alone has no light that casts shadows
// by maps or shadow rays: the captions say so.
TEST_F(ComparisonPageFiles, SaysWhenNoLightCastsShadows) {
  Stats mapped;
  mapped.add("render_seconds", 0.1);
  mapped.add("shadow_map_texels", 0.0);
  mapped.add("shadow_map_seconds", 0.0);
  mapped.add("visible_surface_seconds", 0.04);
  mapped.add("shading_seconds", 0.05);
  Stats traced;
  traced.add("render_seconds", 0.1);
  traced.add("shadow_rays", 0.0);
  const std::vector<ComparedRender> renders = {
      {&findRenderer("z-buffer")->description(), {Image(2, 2), {}, mapped}},
      {&findRenderer("ray-tracing")->description(), {Image(2, 2), {}, traced}}};
  const std::string html = page(renders, "s.yaml");
  std::size_t said = 0;
  for (std::size_t at = html.find("no shadows: no light casts them"); at != std::string::npos;
       at = html.find("no shadows: no light casts them", at + 1))
    ++said;
  EXPECT_EQ(said, 2u) << html;
  EXPECT_EQ(html.find(" s drawing the shadow maps"), std::string::npos) << html;
  EXPECT_EQ(html.find("of it drawing the shadow maps"), std::string::npos) << html;
}

}  // namespace
}  // namespace rise
