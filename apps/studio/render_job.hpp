// One render on a thread of its own, so that the window keeps drawing while
// it runs: the studio asks it, frame by frame, how far it is and which
// pixels are done, and may cancel it, which stops the render's workers at
// their next task.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "render/renderer.hpp"
#include "render/step_recorder.hpp"

namespace rise::studio {

class RenderJob final : public RenderObserver {
 public:
  // With `steps`, the render records the algorithm's steps (and the ray
  // trees of the budget's pixel) as the budget says.
  RenderJob(const Renderer& renderer, std::shared_ptr<const Scene> scene,
            const RenderSettings& settings, std::optional<StepBudget> steps = std::nullopt);
  // Cancels the render and waits for its thread.
  ~RenderJob() override;
  RenderJob(const RenderJob&) = delete;
  RenderJob& operator=(const RenderJob&) = delete;

  const Renderer& renderer() const { return renderer_; }
  const RenderSettings& settings() const { return settings_; }
  const std::shared_ptr<const Scene>& scene() const { return scene_; }

  void cancel();
  bool finished() const { return finished_; }
  double fractionDone() const { return fraction_; }
  double seconds() const;  // since it started; its length once finished

  // Copies into `shown` (the render's size) the pixels finished since the
  // last call, and returns the rectangle around them (empty: none); the
  // pixels between them in `shown` are left as they were.
  PixelRect takeFinishedPixels(Image& shown);

  // Once finished: the result, or why there is none.
  const RenderResult& result() const { return result_; }
  bool succeeded() const { return finished_ && failure_.empty() && !cancelled_; }
  const std::string& failure() const { return failure_; }
  // Once finished after a cancel: the seconds from the cancel to the end.
  double secondsToStop() const;

  void onProgress(double fractionDone) override { fraction_ = fractionDone; }
  bool cancelled() const override { return cancelled_; }
  void onPixelsDone(const PixelRect& region, const Image& image) override;
  StepRecorder* stepRecorder() override { return recorder_ ? &*recorder_ : nullptr; }
  // The steps recorded, once finished; null when none were asked for.
  const StepRecorder* recorder() const { return recorder_ ? &*recorder_ : nullptr; }

 private:
  void run();

  const Renderer& renderer_;
  std::shared_ptr<const Scene> scene_;
  RenderSettings settings_;
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> finished_{false};
  std::atomic<double> fraction_{0.0};
  std::chrono::steady_clock::time_point start_;
  std::atomic<double> length_{0.0};
  std::chrono::steady_clock::time_point cancelledAt_;
  std::chrono::steady_clock::time_point end_;

  std::mutex pixelsMutex_;
  Image finishedPixels_;
  std::vector<PixelRect> finishedRegions_;  // since the last takeFinishedPixels

  std::optional<StepRecorder> recorder_;
  RenderResult result_;
  std::string failure_;
  std::thread thread_;
};

}  // namespace rise::studio
