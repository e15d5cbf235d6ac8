#include "raster/raster_frame.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

namespace rise {

RasterFrame::RasterFrame(const RenderSettings& settings, const Color& background,
                         const ScreenGeometry& screen, const SurfaceShader& shader,
                         const Workers& workers, StepRecorder* steps, ShadowVolumes* shadowVolumes)
    : screen_(screen),
      shader_(shader),
      steps_(steps),
      shadowVolumes_(shadowVolumes),
      background_(background),
      wantsFaces_(settings.wantsBuffer("face")) {
  // Filling image-sized buffers is a fair share of a frame of a large image:
  // only those wanted are made, and the render's workers share them.
  std::vector<std::pair<Image*, Color>> fills{{&result_.image, background}};
  if (settings.wantsBuffer("cost"))
    fills.emplace_back(cost_ = &result_.buffers["cost"], Color(0.0f));
  if (settings.wantsBuffer("depth"))
    fills.emplace_back(depth_ = &result_.buffers["depth"], Color(kInfinity));
  if (settings.wantsBuffer("normal"))
    fills.emplace_back(normal_ = &result_.buffers["normal"], Color(0.0f));
  const int width = settings.width, height = settings.height;
  const int count = static_cast<int>(fills.size());
  workers.forEachRange(count + 1, 1, [&](int fill, int, int) {
    if (fill == count)
      faces_.assign(static_cast<std::size_t>(width) * height, -1);
    else
      *fills[fill].first = Image(width, height, fills[fill].second);
  });
}

namespace {

using Clock = std::chrono::steady_clock;

// Far longer than shading a pixel takes, and shorter than the system's
// slice of time for a thread.
constexpr std::int64_t kPausedNanoseconds = 50'000;

// What reading the clock twice adds to a time measured between the reads:
// the least of a few tries, as the reads themselves are the work.
std::int64_t clockReadNanoseconds() {
  static const std::int64_t nanoseconds = [] {
    Clock::duration least = Clock::duration::max();
    for (int i = 0; i < 32; ++i) {
      const Clock::time_point start = Clock::now();
      least = std::min(least, Clock::now() - start);
    }
    return std::chrono::duration_cast<std::chrono::nanoseconds>(least).count();
  }();
  return nanoseconds;
}

}  // namespace

ShadedPixel RasterFrame::shadeAt(int x, int y, int face) const {
  // A clock read costs as much as shading a plain pixel: only some are timed.
  if ((static_cast<std::int64_t>(y) * width() + x) % kShadingTimedEvery != 0)
    return shadingOf(x, y, face);
  const Clock::time_point start = Clock::now();
  ShadedPixel pixel = shadingOf(x, y, face);
  const std::int64_t nanoseconds =
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
  timedPixels_.fetch_add(1, std::memory_order_relaxed);
  // A thread the system paused while it shaded was timed for the pause:
  // such a pixel stands for none, the others for it.
  if (nanoseconds > kPausedNanoseconds) return pixel;
  timedShadingNanoseconds_.fetch_add(
      std::max<std::int64_t>(nanoseconds - clockReadNanoseconds(), 0), std::memory_order_relaxed);
  keptPixels_.fetch_add(1, std::memory_order_relaxed);
  return pixel;
}

double RasterFrame::shadingSecondsEstimate() const {
  const std::int64_t kept = keptPixels_.load();
  if (kept == 0) return 0.0;
  return 1e-9 * static_cast<double>(timedShadingNanoseconds_.load()) * kShadingTimedEvery *
         static_cast<double>(timedPixels_.load()) / static_cast<double>(kept);
}

ShadedPixel RasterFrame::shadingOf(int x, int y, int face) const {
  const Vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
  const PixelGeometry geometry = depth_ || normal_ ? PixelGeometry::Wanted : PixelGeometry::Skipped;
  if (!shadowVolumes_ || isTransparent(face)) return shader_.shade(face, centre, nullptr, geometry);
  const PixelShadows shadows = shadowVolumes_->at(x, y);
  return shader_.shade(face, centre, shadows.any() ? &shadows : nullptr, geometry);
}

void RasterFrame::setVisible(int x, int y, int face) {
  const ShadedPixel pixel = shadeAt(x, y, face);
  result_.image.at(x, y) = pixel.color;
  if (depth_) depth_->at(x, y) = Color(pixel.depth);
  if (normal_) normal_->at(x, y) = pixel.normal;
  faces_[static_cast<std::size_t>(y) * width() + x] = screen_.faces[face].sceneFace;
}

void RasterFrame::blendVisible(int x, int y, int face) {
  const Color behind = result_.image.at(x, y);
  setVisible(x, y, face);
  result_.image.at(x, y) += filterOf(face) * behind;
}

Color RasterFrame::blendedOver(int x, int y, int face, const Color& behind) const {
  return writeOf(x, y, face, 0.0f).color + filterOf(face) * behind;
}

Color RasterFrame::filterOf(int face) const {
  const Material& material = shader_.materialOf(face);
  return material.transmission * material.color;
}

PixelWrite RasterFrame::writeOf(int x, int y, int face, float inverseDepth, bool kept) const {
  const ShadedPixel pixel = shadeAt(x, y, face);
  return {x, y, pixel.color, screen_.faces[face].sceneFace, inverseDepth, kept};
}

StepShape outlineOf(std::span<const Vec3> corners, std::string role) {
  StepShape shape{StepShape::Kind::Polygon, std::move(role), {}};
  for (const Vec3& corner : corners) shape.points.emplace_back(corner);
  return shape;
}

std::uint64_t RasterFrame::coveredPixels() const {
  return static_cast<std::uint64_t>(
      std::count_if(faces_.begin(), faces_.end(), [](int face) { return face >= 0; }));
}

RenderResult RasterFrame::takeResult() {
  if (wantsFaces_) {
    Image& faces = result_.buffers["face"] = Image(width(), height());
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x)
        faces.at(x, y) =
            Color(static_cast<float>(faces_[static_cast<std::size_t>(y) * width() + x]));
  }
  return std::move(result_);
}

}  // namespace rise
