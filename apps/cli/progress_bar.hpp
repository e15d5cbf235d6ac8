#pragma once

#include <chrono>
#include <string>

#include "render/renderer.hpp"

namespace rise::cli {

// A one-line progress bar on standard error while a render runs, drawn only
// when standard error is a terminal (so logs and pipes stay clean), and
// erased when the render ends. It hands the render `steps` to record its
// steps in, when given.
class ProgressBar final : public RenderObserver {
 public:
  explicit ProgressBar(std::string label, StepRecorder* steps = nullptr);
  ~ProgressBar() override;

  void onProgress(double fractionDone) override;
  StepRecorder* stepRecorder() override { return steps_; }

 private:
  std::string label_;
  bool enabled_;
  int lastPercent_ = -1;
  std::chrono::steady_clock::time_point start_;
  StepRecorder* steps_;
};

}  // namespace rise::cli
