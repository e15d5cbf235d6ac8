// What the algorithms record of their steps tells the truth: replaying the
// recorded steps gives back what the render computed. Depth sort's painting,
// in the recorded order, paints its image; the z-buffer's recorded depth tests
// leave its face buffer; Warnock's settled windows tile the screen once; the
// scanline's spans and one-scanline buffers give its face buffer; and the
// rays of a pixel's trees add up to the pixel's colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"

namespace rise {
namespace {

StepBudget everyStep() {
  StepBudget budget;
  budget.every = 1;
  return budget;
}

StepBudget treeOf(const glm::ivec2& pixel) {
  StepBudget budget;
  budget.treePixel = pixel;
  return budget;
}

class Recording final : public RenderObserver {
 public:
  explicit Recording(StepBudget budget = everyStep()) : recorder(budget) {}
  StepRecorder* stepRecorder() override { return &recorder; }
  StepRecorder recorder;
};

Scene example(const std::string& name) {
  return loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + name);
}

RenderSettings small(const Scene& scene, int width, int height, int samples = 1) {
  RenderRequest request;
  request.image = {width,           height,
                   samples,         samples == 1 ? SamplePattern::None : SamplePattern::Jittered,
                   FilterKind::Box, {}};
  return settingsFor(scene, request);
}

RenderResult render(const std::string& algorithm, const Scene& scene,
                    const RenderSettings& settings, RenderObserver& observer) {
  return findRenderer(algorithm)->render(scene, settings, observer);
}

int faceAt(const RenderResult& result, int x, int y) {
  return static_cast<int>(result.buffers.at("face").at(x, y).r);
}

TEST(StepRecorder, RecordingDoesNotChangeTheImage) {
  const Scene scene = example("classic.yaml");
  const RenderSettings settings = small(scene, 64, 48, 4);
  for (const Renderer* renderer : allRenderers()) {
    RenderObserver nobody;
    Recording recording;
    const Image plain = renderer->render(scene, settings, nobody).image;
    const Image recorded = renderer->render(scene, settings, recording).image;
    EXPECT_EQ(plain.pixels(), recorded.pixels()) << renderer->name();
    EXPECT_FALSE(recording.recorder.allSteps().empty()) << renderer->name();
  }
}

TEST(StepRecorder, DepthSortPaintsItsImageInTheRecordedOrder) {
  for (const char* name : {"classic.yaml", "spheres.yaml"}) {
    const Scene scene = example(name);
    const RenderSettings settings = small(scene, 96, 72);
    Recording recording;
    const RenderResult result = render("depth-sort", scene, settings, recording);
    Image painted(settings.width, settings.height, scene.image.background);
    int paintings = 0, comparisons = 0;
    for (const Step& step : recording.recorder.allSteps()) {
      comparisons += step.kind == "compare";
      if (step.kind != "paint") continue;
      ++paintings;
      for (const PixelWrite& write : step.writes) painted.at(write.x, write.y) = write.color;
    }
    EXPECT_EQ(painted.pixels(), result.image.pixels()) << name;
    // A piece that covers no pixel centre paints nothing, and has no step.
    EXPECT_LE(paintings, result.stats.value("polygons_painted")) << name;
    EXPECT_GT(paintings, 0.9 * result.stats.value("polygons_painted")) << name;
    // Past the recorder's limit, comparisons are no longer recorded.
    if (comparisons < static_cast<int>(StepRecorder::kMostDetailedSteps) / 2) {
      EXPECT_EQ(comparisons, result.stats.value("comparisons")) << name;
    }
  }
}

TEST(StepRecorder, TheZBufferAfterItsLastPolygonIsItsDepthBuffer) {
  const Scene scene = example("classic.yaml");
  const RenderSettings settings = small(scene, 96, 72);
  Recording recording;
  const RenderResult result = render("z-buffer", scene, settings, recording);
  std::vector<float> inverseDepth(static_cast<std::size_t>(settings.width) * settings.height, 0);
  std::vector<int> face(inverseDepth.size(), -1);
  int polygons = 0;
  for (const Step& step : recording.recorder.allSteps()) {
    ASSERT_EQ(step.kind, "polygon");
    ++polygons;
    for (const PixelWrite& write : step.writes) {
      const std::size_t pixel = static_cast<std::size_t>(write.y) * settings.width + write.x;
      // The recorded verdict is the depth test's, made against the buffer as
      // the earlier steps left it.
      EXPECT_EQ(write.kept, write.inverseDepth > inverseDepth[pixel]);
      if (!write.kept) continue;
      inverseDepth[pixel] = write.inverseDepth;
      face[pixel] = write.face;
    }
  }
  EXPECT_LE(polygons, result.stats.value("polygons_drawn"));
  EXPECT_GT(polygons, 0.9 * result.stats.value("polygons_drawn"));
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x)
      ASSERT_EQ(face[static_cast<std::size_t>(y) * settings.width + x], faceAt(result, x, y))
          << x << "," << y;
}

TEST(StepRecorder, WarnocksSettledWindowsTileTheScreenOnce) {
  for (const auto& [width, height] : {std::pair{96, 72}, std::pair{37, 101}}) {
    const Scene scene = example("classic.yaml");
    const RenderSettings settings = small(scene, width, height);
    Recording recording;
    const RenderResult result = render("area-subdivision", scene, settings, recording);
    std::vector<int> settled(static_cast<std::size_t>(width) * height, 0);
    int windows = 0;
    for (const Step& step : recording.recorder.allSteps()) {
      ASSERT_EQ(step.kind, "window");
      ++windows;
      for (const PixelRect& area : step.settled)
        for (int y = area.y0; y < area.y1; ++y)
          for (int x = area.x0; x < area.x1; ++x)
            ++settled[static_cast<std::size_t>(y) * width + x];
    }
    EXPECT_EQ(windows, result.stats.value("windows"));
    EXPECT_TRUE(std::all_of(settled.begin(), settled.end(), [](int times) { return times == 1; }))
        << width << "x" << height;
  }
}

// Spans hold (polygon, face, left, right); the buffers runs of (from x, to x,
// face, w); the transparent layers, where the row has any, runs of (from x,
// to x, faces blended farthest first, faces dropped). The face a pixel shows
// is the nearest blended, or else the buffer's.
TEST(StepRecorder, TheScanlinesSpansAndBuffersGiveItsFaceBuffer) {
  const Scene scene = example("classic.yaml");
  const RenderSettings settings = small(scene, 96, 72);
  Recording recording;
  const RenderResult result = render("scanline", scene, settings, recording);
  const std::vector<Step> steps = recording.recorder.allSteps();
  ASSERT_EQ(steps.size(), static_cast<std::size_t>(settings.height));
  const auto number = [](const StepCell& cell) { return std::get<double>(cell); };
  int rowsWithLayers = 0;
  for (int y = 0; y < settings.height; ++y) {
    const Step& step = steps[static_cast<std::size_t>(y)];
    const StepTable& spans = step.tables[2];
    const StepTable& buffers = step.tables[3];
    ASSERT_EQ(spans.title, "spans");
    std::vector<int> shown(static_cast<std::size_t>(settings.width), -1);
    int x = 0;
    for (const std::vector<StepCell>& run : buffers.rows) {
      ASSERT_EQ(number(run[0]), x);
      for (; x <= static_cast<int>(number(run[1])); ++x)
        shown[x] = static_cast<int>(number(run[2]));
    }
    EXPECT_EQ(x, settings.width);
    if (step.tables.size() > 4) {
      ++rowsWithLayers;
      for (const std::vector<StepCell>& run : step.tables[4].rows) {
        const std::string& blended = std::get<std::string>(run[2]);
        if (blended.empty()) continue;
        const int nearest = std::stoi(blended.substr(blended.rfind(' ') + 1));
        for (x = static_cast<int>(number(run[0])); x <= static_cast<int>(number(run[1])); ++x)
          shown[x] = nearest;
      }
    }
    for (x = 0; x < settings.width; ++x) {
      const int face = shown[x];
      ASSERT_EQ(face, faceAt(result, x, y)) << x << "," << y;
      if (face < 0) continue;
      // The face seen has a span over the pixel's centre.
      const double centre = x + 0.5;
      EXPECT_TRUE(std::any_of(spans.rows.begin(), spans.rows.end(),
                              [&](const auto& span) {
                                return number(span[1]) == face && number(span[2]) <= centre &&
                                       centre < number(span[3]);
                              }))
          << x << "," << y;
    }
  }
  // The rows through the glass sphere.
  EXPECT_GT(rowsWithLayers, settings.height / 4);
}

// The hybrid's first steps are the scanline's, one a scanline, each drawing
// the items of its row where the scanline's face buffer sees a face but
// settling nothing; then its bands of rays settle every pixel once and mark
// those that spawned mirror or glass rays.
TEST(StepRecorder, TheHybridFillsItsItemBufferThenShadesByRays) {
  const Scene scene = example("classic.yaml");
  const RenderSettings settings = small(scene, 96, 72);
  Recording recording;
  render("hybrid", scene, settings, recording);
  RenderObserver nobody;
  const RenderResult scanline = render("scanline", scene, settings, nobody);
  const std::vector<Step> steps = recording.recorder.allSteps();
  const auto height = static_cast<std::size_t>(settings.height);
  ASSERT_GT(steps.size(), height);
  for (std::size_t y = 0; y < height; ++y) {
    const Step& step = steps[y];
    EXPECT_EQ(step.kind, "scanline");
    EXPECT_TRUE(step.settled.empty());
    std::vector<int> row(static_cast<std::size_t>(settings.width), -1);
    for (const PixelWrite& write : step.writes) {
      ASSERT_EQ(write.y, static_cast<int>(y));
      row[static_cast<std::size_t>(write.x)] = write.face;
    }
    for (int x = 0; x < settings.width; ++x)
      EXPECT_EQ(row[static_cast<std::size_t>(x)], faceAt(scanline, x, static_cast<int>(y)))
          << x << "," << y;
  }
  Image settledTimes(settings.width, settings.height);
  int mirrorOrGlass = 0;
  for (std::size_t i = height; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].kind, "rays");
    for (const PixelRect& area : steps[i].settled)
      for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x) settledTimes.at(x, y) += Color(1.0f);
    mirrorOrGlass += static_cast<int>(
        std::count_if(steps[i].shapes.begin(), steps[i].shapes.end(),
                      [](const StepShape& shape) { return shape.role == "rays"; }));
  }
  for (const Color& times : settledTimes.pixels()) ASSERT_EQ(times, Color(1.0f));
  EXPECT_GT(mirrorOrGlass, 0);
}

// The colour a pixel's trees add up to, their samples weighed alike (the box
// filter).
Color treesSum(const std::vector<RayTree>& trees) {
  Color sum(0.0f);
  for (const RayTree& tree : trees)
    for (const RayNode& ray : tree.rays) sum += ray.contribution;
  return sum / static_cast<float>(trees.size());
}

TEST(StepRecorder, ThePixelsRayTreesAddUpToItsColour) {
  const Scene scene = example("classic.yaml");
  // At 160x120: the glass sphere, the mirror sphere, a shadow on the floor,
  // the background.
  const std::map<std::string, glm::ivec2> pixels = {
      {"glass", {80, 55}}, {"mirror", {128, 55}}, {"shadow", {92, 82}}, {"background", {5, 5}}};
  for (const char* algorithm : {"ray-tracing", "distributed-ray-tracing", "hybrid"}) {
    for (int samples : {1, 4}) {
      const RenderSettings settings = small(scene, 160, 120, samples);
      for (const auto& [what, pixel] : pixels) {
        Recording recording(treeOf(pixel));
        const RenderResult result = render(algorithm, scene, settings, recording);
        const std::vector<RayTree> trees = recording.recorder.trees();
        ASSERT_EQ(static_cast<int>(trees.size()), samples) << algorithm << " " << what;
        const Color expected = result.image.at(pixel.x, pixel.y);
        const Color sum = treesSum(trees);
        for (int channel = 0; channel < 3; ++channel)
          EXPECT_NEAR(sum[channel], expected[channel], 1e-4f + 1e-4f * expected[channel])
              << algorithm << " " << what << " " << samples;
      }
    }
  }
}

std::map<RayKind, int> raysByKind(const RayTree& tree) {
  std::map<RayKind, int> kinds;
  for (const RayNode& ray : tree.rays) ++kinds[ray.kind];
  return kinds;
}

// With a circle cut into four segments, a sphere's polygons lie far inside
// its true outline: the hybrid follows the outline once every row is shaded,
// and shades again the pixels it reaches. One more step of rays marks them
// and settles nothing, so that every pixel is still settled once and the
// steps mark every pixel that fell back; and the ray tree of such a pixel is
// its final shading's, its one full primary ray.
TEST(StepRecorder, TheHybridShowsThePixelsAnOutlineShadedAgain) {
  const Scene scene = example("classic.yaml");
  RenderSettings settings = small(scene, 96, 72);
  settings.tessellation = 1;
  Recording recording;
  const RenderResult result = render("hybrid", scene, settings, recording);
  const std::vector<Step> steps = recording.recorder.allSteps();
  Image settledTimes(settings.width, settings.height);
  std::set<std::pair<float, float>> markedFallingBack;
  for (std::size_t i = static_cast<std::size_t>(settings.height); i < steps.size(); ++i) {
    ASSERT_EQ(steps[i].kind, "rays");
    for (const PixelRect& area : steps[i].settled)
      for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x) settledTimes.at(x, y) += Color(1.0f);
    for (const StepShape& shape : steps[i].shapes)
      if (shape.role == "fallback")
        markedFallingBack.insert({shape.points[0].x, shape.points[0].y});
  }
  for (const Color& times : settledTimes.pixels()) ASSERT_EQ(times, Color(1.0f));
  const Step& last = steps.back();
  EXPECT_TRUE(last.settled.empty());
  ASSERT_FALSE(last.tables.empty());
  ASSERT_GT(last.tables.front().rows.size(), 20u);
  EXPECT_EQ(static_cast<double>(markedFallingBack.size()), result.stats.value("fallback_pixels"));

  const auto& row = last.tables.front().rows.front();
  const glm::ivec2 pixel(static_cast<int>(std::get<double>(row[0])),
                         static_cast<int>(std::get<double>(row[1])));
  Recording treeRecording(treeOf(pixel));
  const RenderResult again = render("hybrid", scene, settings, treeRecording);
  const std::vector<RayTree> trees = treeRecording.recorder.trees();
  ASSERT_EQ(trees.size(), 1u);
  EXPECT_EQ(raysByKind(trees.front())[RayKind::Primary], 1);
  const Color expected = again.image.at(pixel.x, pixel.y);
  EXPECT_EQ(expected, result.image.at(pixel.x, pixel.y));
  const Color sum = treesSum(trees);
  for (int channel = 0; channel < 3; ++channel)
    EXPECT_NEAR(sum[channel], expected[channel], 1e-4f + 1e-4f * expected[channel]);
}

TEST(StepRecorder, TreesHoldTheRaysOfGlassAndMirrors) {
  const Scene scene = example("classic.yaml");
  Recording glass(treeOf(glm::ivec2(80, 55)));
  render("ray-tracing", scene, small(scene, 160, 120), glass);
  const RayTree throughGlass = glass.recorder.trees().at(0);
  EXPECT_EQ(throughGlass.rays[0].object, 1);  // the glass sphere, second in the scene
  EXPECT_EQ(raysByKind(throughGlass)[RayKind::Primary], 1);
  EXPECT_GT(raysByKind(throughGlass)[RayKind::Shadow], 0);
  EXPECT_GT(raysByKind(throughGlass)[RayKind::Refraction], 1);  // in, and out again
  Recording mirror(treeOf(glm::ivec2(128, 55)));
  render("ray-tracing", scene, small(scene, 160, 120), mirror);
  const RayTree inMirror = mirror.recorder.trees().at(0);
  EXPECT_EQ(inMirror.rays[0].object, 2);
  EXPECT_GT(raysByKind(inMirror)[RayKind::Reflection], 0);
  Recording shadow(treeOf(glm::ivec2(92, 82)));
  render("ray-tracing", scene, small(scene, 160, 120), shadow);
  const RayTree inShadow = shadow.recorder.trees().at(0);
  EXPECT_EQ(inShadow.rays[0].object, 0);  // the floor
  EXPECT_TRUE(std::any_of(inShadow.rays.begin(), inShadow.rays.end(), [](const RayNode& ray) {
    return ray.kind == RayKind::Shadow && ray.transmittance == Color(0.0f);
  }));
}

TEST(StepRecorder, TheBudgetKeepsEveryNthStepInTheRegionAndTheirPixels) {
  const Scene scene = example("classic.yaml");
  const RenderSettings settings = small(scene, 96, 72);
  StepBudget budget;
  budget.region = PixelRect{0, 0, 48, 36};
  budget.every = 3;
  Recording everyThird(budget);
  const RenderResult result = render("z-buffer", scene, settings, everyThird);
  const std::vector<Step> all = everyThird.recorder.allSteps();
  const std::vector<Step> kept = everyThird.recorder.keptSteps();
  int skipped = 0;
  std::size_t writes = 0;
  for (const Step& step : kept) {
    skipped += step.skippedBefore;
    writes += step.writesBefore.size() + step.writes.size();
  }
  EXPECT_EQ(static_cast<std::size_t>(skipped) + kept.size(), all.size());
  EXPECT_LT(kept.size(), all.size() / 2);
  std::size_t allWrites = 0;
  for (const Step& step : all) allWrites += step.writes.size();
  EXPECT_EQ(writes, allWrites);  // a kept step carries the pixels of those left out
  EXPECT_FALSE(result.image.pixels().empty());
}

}  // namespace
}  // namespace rise
