// The image as it is made: every algorithm tells its observer of the pixels
// each task finished (RenderObserver::onPixelsDone), which the studio shows
// while the render runs; and a cancelled render stops at its tasks' end.
#include <gtest/gtest.h>

#include <mutex>

#include "algorithms/registry.hpp"
#include "algorithms/settings_for_scene.hpp"
#include "io/scene_file.hpp"

namespace rise {
namespace {

// Copies every region it is told of into an image of its own, counting
// how often each pixel came.
class RegionCopier final : public RenderObserver {
 public:
  RegionCopier(int width, int height) : copied(width, height), reports(width, height) {}

  void onPixelsDone(const PixelRect& region, const Image& image) override {
    const std::scoped_lock lock(mutex_);
    ++regions;
    for (int y = region.y0; y < region.y1; ++y)
      for (int x = region.x0; x < region.x1; ++x) {
        copied.at(x, y) = image.at(x, y);
        reports.at(x, y) += Color(1.0f);
      }
    if (cancelAfterFirst) cancelled_ = true;
  }
  void onProgress(double) override {
    if (cancelAtFirstProgress) cancelled_ = true;
  }
  bool cancelled() const override { return cancelled_; }

  Image copied;
  Image reports;
  int regions = 0;
  bool cancelAfterFirst = false;
  bool cancelAtFirstProgress = false;

 private:
  std::mutex mutex_;
  std::atomic<bool> cancelled_{false};
};

Scene classic() { return loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/classic.yaml"); }

RenderSettings settingsAt(const Scene& scene, int width, int height) {
  RenderRequest request;
  request.image.width = width;
  request.image.height = height;
  request.settings.threads = 3;
  return settingsFor(scene, request);
}

// An odd size, so that the last tiles and bands are cut short.
TEST(ProgressiveImage, EveryPixelIsToldAsTheImageWillBe) {
  const Scene scene = classic();
  const RenderSettings settings = settingsAt(scene, 83, 61);
  for (const Renderer* renderer : allRenderers()) {
    RegionCopier observer(settings.width, settings.height);
    const RenderResult result = renderer->render(scene, settings, observer);
    EXPECT_GT(observer.regions, 0) << renderer->name();
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x) {
        ASSERT_GE(observer.reports.at(x, y).r, 1.0f) << renderer->name() << " " << x << "," << y;
        // One sample a pixel through the box filter: each pixel's colour is
        // final as soon as its task is done.
        ASSERT_EQ(observer.copied.at(x, y), result.image.at(x, y))
            << renderer->name() << " " << x << "," << y;
      }
  }
}

TEST(ProgressiveImage, ACancelledRenderStopsAtItsTasksEnd) {
  const Scene scene = classic();
  const RenderSettings settings = settingsAt(scene, 640, 480);
  for (const Renderer* renderer : allRenderers()) {
    RegionCopier observer(settings.width, settings.height);
    observer.cancelAfterFirst = true;
    renderer->render(scene, settings, observer);
    // The tasks under way when the first ended, at most one a thread, and
    // none after.
    EXPECT_LE(observer.regions, settings.threads) << renderer->name();
  }
}

// Cancelled at the first step of work that reports its progress, with
// several samples a pixel: whatever an algorithm was doing, it returns, and
// reads nothing it had not made yet (the sanitized build watches).
TEST(ProgressiveImage, ACancelledRenderStopsWhereverItWas) {
  const Scene scene = classic();
  RenderSettings settings = settingsAt(scene, 160, 120);
  settings.sampling.samples = 4;
  settings.sampling.pattern = SamplePattern::Jittered;
  for (const Renderer* renderer : allRenderers()) {
    RegionCopier observer(settings.width, settings.height);
    observer.cancelAtFirstProgress = true;
    renderer->render(scene, settings, observer);
    EXPECT_TRUE(observer.cancelled()) << renderer->name();
  }
}

}  // namespace
}  // namespace rise
