#include "progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

namespace rise::cli {

ProgressBar::ProgressBar(std::string label, StepRecorder* steps)
    : label_(std::move(label)),
      enabled_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      steps_(steps) {}

ProgressBar::~ProgressBar() {
  if (enabled_ && lastPercent_ >= 0) std::fputs("\r\033[K", stderr);
}

void ProgressBar::onProgress(double fractionDone) {
  const int percent = static_cast<int>(fractionDone * 100.0);
  if (!enabled_ || percent == lastPercent_) return;
  lastPercent_ = percent;

  constexpr int kBarWidth = 30;
  const int filled = percent * kBarWidth / 100;
  const std::string bar = std::string(filled, '=') + std::string(kBarWidth - filled, ' ');
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
  std::fprintf(stderr, "\r%s [%s] %3d%%  %.1f s", label_.c_str(), bar.c_str(), percent,
               elapsed.count());
  std::fflush(stderr);
}

}  // namespace rise::cli
