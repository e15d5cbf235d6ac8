#include "render_job.hpp"

#include <algorithm>
#include <exception>

#include "algorithms/registry.hpp"

namespace rise::studio {
namespace {

PixelRect around(const PixelRect& a, const PixelRect& b) {
  if (a.isEmpty()) return b;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

}  // namespace

RenderJob::RenderJob(const Renderer& renderer, std::shared_ptr<const Scene> scene,
                     const RenderSettings& settings, std::optional<StepBudget> steps)
    : renderer_(renderer),
      scene_(std::move(scene)),
      settings_(settings),
      start_(std::chrono::steady_clock::now()) {
  if (steps) recorder_.emplace(*steps);
  thread_ = std::thread([this] { run(); });
}

RenderJob::~RenderJob() {
  cancel();
  thread_.join();
}

void RenderJob::run() {
  try {
    result_ = renderTimed(renderer_, *scene_, settings_, *this);
  } catch (const std::exception& error) {
    failure_ = error.what();
  }
  end_ = std::chrono::steady_clock::now();
  length_ = std::chrono::duration<double>(end_ - start_).count();
  finished_ = true;
}

void RenderJob::cancel() {
  if (cancelled_.exchange(true)) return;
  cancelledAt_ = std::chrono::steady_clock::now();
}

double RenderJob::secondsToStop() const {
  return std::chrono::duration<double>(end_ - cancelledAt_).count();
}

double RenderJob::seconds() const {
  if (finished_) return length_;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void RenderJob::onPixelsDone(const PixelRect& region, const Image& image) {
  const std::scoped_lock lock(pixelsMutex_);
  // Made here, on a worker, rather than on the window's thread.
  if (finishedPixels_.width() == 0) finishedPixels_ = Image(settings_.width, settings_.height);
  for (int y = region.y0; y < region.y1; ++y)
    for (int x = region.x0; x < region.x1; ++x) finishedPixels_.at(x, y) = image.at(x, y);
  finishedRegions_.push_back(region);
}

PixelRect RenderJob::takeFinishedPixels(Image& shown) {
  const std::scoped_lock lock(pixelsMutex_);
  PixelRect changed{0, 0, 0, 0};
  for (const PixelRect& region : finishedRegions_) {
    for (int y = region.y0; y < region.y1; ++y)
      for (int x = region.x0; x < region.x1; ++x) shown.at(x, y) = finishedPixels_.at(x, y);
    changed = around(changed, region);
  }
  finishedRegions_.clear();
  return changed;
}

}  // namespace rise::studio
