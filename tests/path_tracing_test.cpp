// What path tracing must do (Kajiya 1986), each held to an answer known
// without it: the furnace's closed form, the distributed ray tracer's soft
// shadows for the light that reaches a surface directly, one mean whichever
// way the light is found, and an error that falls as one over the square
// root of the samples.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "core/image_error.hpp"
#include "io/scene_file.hpp"

namespace rise {
namespace {

RenderResult render(const std::string& sceneText, const std::string& algorithm,
                    const std::function<void(RenderSettings&)>& choose = {}) {
  const Scene scene = loadScene(sceneText, "test.yaml");
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.threads = 2;
  if (choose) choose(settings);
  RenderObserver observer;
  return findRenderer(algorithm)->render(scene, settings, observer);
}

double meanOf(const Image& image) {
  double sum = 0.0;
  for (const Color& pixel : image.pixels()) sum += (pixel.r + pixel.g + pixel.b) / 3.0;
  return sum / static_cast<double>(image.pixels().size());
}

// The inside of a sphere whose walls of albedo a emit Le: the light bounces
// for ever, Le (1 + a + a^2 + ...) = Le / (1 - a) everywhere.
std::string furnace(float albedo, float emitted) {
  return "image: {width: 16, height: 16, background: [0, 0, 0]}\n"
         "camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 60}\n"
         "materials:\n"
         "  wall: {color: [1, 1, 1], ka: 0, kd: " +
         std::to_string(albedo) + ", emission: [" + std::to_string(emitted) + ", " +
         std::to_string(emitted) + ", " + std::to_string(emitted) +
         "]}\n"
         "objects:\n"
         "  - sphere: {center: [0, 0, 0], radius: 5, material: wall}\n";
}

TEST(PathTracing, TheFurnaceGlowsAsTheSeriesOfItsBouncesSums) {
  for (const float albedo : {0.5f, 0.9f})
    for (const bool roulette : {true, false}) {
      const RenderResult result = render(furnace(albedo, 0.5f), "path-tracing", [&](auto& s) {
        s.maxDepth = 64;
        s.russianRoulette = roulette;
        s.progression.samples = albedo > 0.6f ? 256 : 64;
      });
      const double expected = 0.5 / (1.0 - albedo);
      EXPECT_NEAR(meanOf(result.image), expected, 0.01 * expected)
          << "albedo " << albedo << (roulette ? ", roulette" : ", no roulette");
    }
}

// A lossless mirror or glass ball in the furnace takes nothing from its
// light and adds nothing: Fresnel's split between reflection and refraction
// only shares the light out.
TEST(PathTracing, AMirrorOrAGlassBallInTheFurnaceDisappears) {
  for (const std::string ball : {"{color: [1, 1, 1], ka: 0, kd: 0, reflection: 1}",
                                 "{color: [1, 1, 1], ka: 0, kd: 0, transmission: 1, ior: 1.5}"}) {
    std::string scene = furnace(0.5f, 0.5f);
    scene.insert(scene.find("objects:"), "  ball: " + ball + "\n");
    scene += "  - sphere: {center: [0, 0, 3], radius: 1.5, material: ball}\n";
    const RenderResult result = render(scene, "path-tracing", [](auto& s) {
      s.maxDepth = 64;
      s.progression.samples = 64;
    });
    EXPECT_NEAR(meanOf(result.image), 1.0, 0.01) << ball;
  }
}

// The depth cuts the series: d surfaces give Le (1 + ... + a^(d-1)).
TEST(PathTracing, AShorterPathSumsFewerBounces) {
  const RenderResult result = render(furnace(0.5f, 0.5f), "path-tracing", [](auto& s) {
    s.maxDepth = 2;
    s.russianRoulette = false;
  });
  EXPECT_NEAR(meanOf(result.image), 0.75, 0.0075);
}

// In the closed furnace no path escapes: without the roulette each meets
// exactly its depth's surfaces; with it, the lengths spread out, and the
// histogram's bins still count every path and every vertex.
TEST(PathTracing, CountsThePathsOfEachLength) {
  const RenderResult fixed = render(furnace(0.5f, 0.5f), "path-tracing", [](auto& s) {
    s.maxDepth = 3;
    s.russianRoulette = false;
  });
  const double paths = fixed.stats.value("paths");
  EXPECT_EQ(fixed.stats.value("paths_of_3_vertices"), paths);
  EXPECT_EQ(fixed.stats.value("paths_of_1_vertex"), 0.0);

  const RenderResult rouletted = render(furnace(0.5f, 0.5f), "path-tracing", [](auto& s) {
    s.maxDepth = 64;
    s.russianRoulette = true;
  });
  double counted = 0.0, vertices = 0.0;
  for (int length = 1; length <= 8; ++length) {
    const std::string name = length == 1   ? "paths_of_1_vertex"
                             : length == 8 ? "paths_of_8_or_more_vertices"
                                           : "paths_of_" + std::to_string(length) + "_vertices";
    const double count = rouletted.stats.value(name);
    counted += count;
    if (length < 8) vertices += length * count;
  }
  EXPECT_EQ(counted, rouletted.stats.value("paths"));
  EXPECT_GT(rouletted.stats.value("paths_of_8_or_more_vertices"), 0.0);
  EXPECT_GT(rouletted.stats.value("paths_of_4_vertices"), 0.0);
  EXPECT_LT(vertices, rouletted.stats.value("path_vertices"));
}

// A diffuse floor under a square light of the classic model, seen from above.
std::string floorUnderALight(const std::string& light) {
  return "image: {width: 24, height: 24, background: [0, 0, 0]}\n"
         "camera: {position: [0, 6, 0.01], look_at: [0, 0, 0], fov: 50}\n"
         "lights:\n  - " +
         light +
         "\n"
         "materials:\n"
         "  floor: {color: [0.8, 0.8, 0.8], ka: 0, kd: 0.9}\n"
         "  block: {color: [0.5, 0.5, 0.5], ka: 0, kd: 0.9}\n"
         "objects:\n"
         "  - plane: {point: [0, 0, 0], normal: [0, 1, 0], material: floor}\n"
         "  - box: {min: [-0.5, 0.5, -0.5], max: [0.5, 1.0, 0.5], material: block}\n";
}

TEST(PathTracing, ItsDirectLightIsTheDistributedRayTracersSoftShadow) {
  const std::string scene = floorUnderALight(
      "rect: {corner: [-1, 3, -1], edge1: [2, 0, 0], edge2: [0, 0, 2], "
      "color: [1, 1, 1]}");
  const RenderResult path = render(scene, "path-tracing", [](auto& s) {
    s.maxDepth = 1 + 1;  // the eye's ray's surface and its shadow rays alone
    s.progression.samples = 256;
  });
  const RenderResult cook = render(scene, "distributed-ray-tracing", [](auto& s) {
    s.sampling = {256, SamplePattern::Jittered};
  });
  EXPECT_LT(rmse(path.image, cook.image), 0.02);
  EXPECT_GT(meanOf(path.image), 0.2);
}

// An emitting panel, out of sight, over a glossy floor, a ball and a block.
std::string litRoom() {
  return "image: {width: 20, height: 16, background: [0, 0, 0]}\n"
         "camera: {position: [0, 1.2, 3], look_at: [0, 0.3, 0], fov: 50}\n"
         "materials:\n"
         "  lamp: {color: [0, 0, 0], kd: 0, emission: [6, 6, 6]}\n"
         "  matte: {color: [0.7, 0.6, 0.5], ka: 0, kd: 0.8}\n"
         "  glossy: {color: [0.2, 0.2, 0.2], ka: 0, kd: 0.3, ks: 0.6, n: 60}\n"
         "objects:\n"
         "  - polygon: {vertices: [[-0.4, 2.5, -0.4], [0.4, 2.5, -0.4], [0.4, 2.5, 0.4], "
         "[-0.4, 2.5, 0.4]], material: lamp}\n"
         "  - plane: {point: [0, 0, 0], normal: [0, 1, 0], material: glossy}\n"
         "  - sphere: {center: [0.6, 0.5, 0], radius: 0.5, material: matte}\n"
         "  - box: {min: [-1.4, 0, -0.5], max: [-0.4, 1.0, 0.5], material: matte}\n";
}

RenderResult litRoomBy(LightSampling sampling, int samples, std::uint64_t seed = 0) {
  return render(litRoom(), "path-tracing", [&](auto& s) {
    s.lightSampling = sampling;
    s.progression.samples = samples;
    s.seed = seed;
  });
}

// Each way of finding the light converges to one image.
TEST(PathTracing, EveryWayOfFindingTheLightHasOneMean) {
  const double reference = meanOf(litRoomBy(LightSampling::Both, 4096, 99).image);
  for (const LightSampling sampling :
       {LightSampling::Lights, LightSampling::Brdf, LightSampling::Both})
    EXPECT_NEAR(meanOf(litRoomBy(sampling, 1024).image), reference, 0.04 * reference)
        << lightSamplingName(sampling);
}

// On Veach's glossy plates each way alone is noisy where the other is good,
// and the two weighted together have the least error at equal samples.
TEST(PathTracing, BothWaysWeightedHaveTheLeastErrorOnVeachsPlates) {
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/glossy-plates.yaml");
  const auto rendered = [&](LightSampling sampling, int samples, std::uint64_t seed) {
    RenderSettings settings = settingsFor(scene);
    settings.width = 96;
    settings.height = 64;
    settings.lightSampling = sampling;
    settings.progression.samples = samples;
    settings.seed = seed;
    RenderObserver observer;
    return findRenderer("path-tracing")->render(scene, settings, observer).image;
  };
  // The plates alone, below the lights, whose own edges are as noisy either way.
  const auto platesOf = [](const Image& image) {
    Image plates(image.width(), image.height() / 2);
    for (int y = 0; y < plates.height(); ++y)
      for (int x = 0; x < plates.width(); ++x)
        plates.at(x, y) = image.at(x, y + image.height() - plates.height());
    return plates;
  };
  const Image reference = platesOf(rendered(LightSampling::Both, 2048, 5));
  const double lights = rmse(platesOf(rendered(LightSampling::Lights, 16, 0)), reference);
  const double brdf = rmse(platesOf(rendered(LightSampling::Brdf, 16, 0)), reference);
  const double both = rmse(platesOf(rendered(LightSampling::Both, 16, 0)), reference);
  EXPECT_LT(both, 0.9 * lights);
  EXPECT_LT(both, 0.9 * brdf);
}

// Unbiased, and converging as Monte Carlo does: the error against a
// reference of many more samples falls as 1 / sqrt(samples), a slope of
// -1/2 in log-log.
TEST(PathTracing, TheErrorFallsAsOneOverTheSquareRootOfTheSamples) {
  const Image reference = litRoomBy(LightSampling::Both, 4096, 7).image;
  std::vector<double> logSamples, logErrors;
  for (const int samples : {4, 16, 64, 256}) {
    logSamples.push_back(std::log(samples));
    logErrors.push_back(std::log(rmse(litRoomBy(LightSampling::Both, samples).image, reference)));
  }
  const double n = static_cast<double>(logSamples.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < logSamples.size(); ++i) {
    sx += logSamples[i];
    sy += logErrors[i];
    sxx += logSamples[i] * logSamples[i];
    sxy += logSamples[i] * logErrors[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, -0.5, 0.1);
}

TEST(PathTracing, TheSameSeedGivesTheSameImageOnAnyNumberOfThreads) {
  const auto on = [](int threads) {
    return render(litRoom(), "path-tracing", [&](auto& s) {
      s.threads = threads;
      s.progression.samples = 8;
    });
  };
  const RenderResult one = on(1), three = on(3);
  EXPECT_EQ(one.image.pixels(), three.image.pixels());
  EXPECT_EQ(one.stats.value("rays"), three.stats.value("rays"));
}

TEST(PathTracing, StopsAtTheNoiseAskedForAndKeepsItsVariance) {
  const RenderResult result = render(litRoom(), "path-tracing", [](auto& s) {
    s.progression.samples = 4096;
    s.progression.noiseTarget = 0.1;
  });
  EXPECT_LE(result.stats.value("noise"), 0.1);
  EXPECT_LT(result.stats.value("samples_per_pixel"), 4096);
  const Image& variance = result.buffers.at("variance");
  EXPECT_GT(meanOf(variance), 0.0);
  const RenderResult more = render(litRoom(), "path-tracing", [](auto& s) {
    s.progression.samples = 4096;
    s.progression.noiseTarget = 0.05;
  });
  EXPECT_LT(meanOf(more.buffers.at("variance")), meanOf(variance));
}

// A time budget ends the passes before the one that would pass it.
TEST(PathTracing, StopsWithinItsTimeLimit) {
  const auto start = std::chrono::steady_clock::now();
  const RenderResult result = render(litRoom(), "path-tracing", [](auto& s) {
    s.progression.samples = kMostSamples;
    s.progression.timeLimit = 0.3;
  });
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  EXPECT_LT(seconds.count(), 1.5);
  EXPECT_LT(result.stats.value("samples_per_pixel"), kMostSamples);
  EXPECT_GE(result.stats.value("passes"), 2);
}

// A front end watching (the studio) sees the image refine: after every tile
// of every pass, the mean of the samples so far, the last of which is the
// image itself.
TEST(PathTracing, ShowsTheImageSoFarAfterEveryTileOfEveryPass) {
  struct Watching final : RenderObserver {
    void onPixelsDone(const PixelRect& region, const Image& image) override {
      ++shown;
      if (seen.pixels().empty()) seen = Image(image.width(), image.height());
      for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) seen.at(x, y) = image.at(x, y);
    }
    int shown = 0;
    Image seen;
  } watching;
  const Scene scene = loadScene(litRoom(), "test.yaml");
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.threads = 2;
  settings.progression.samples = 12;
  const RenderResult result = findRenderer("path-tracing")->render(scene, settings, watching);
  EXPECT_EQ(watching.shown, 3 * 2);  // three passes of the image's two tiles
  EXPECT_LT(rmse(watching.seen, result.image), 1e-6);
}

}  // namespace
}  // namespace rise
