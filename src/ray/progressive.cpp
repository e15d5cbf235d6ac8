#include "ray/progressive.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/elapsed.hpp"
#include "core/random.hpp"

namespace rise {

RenderSettings passSettings(const RenderSettings& settings, int pass) {
  RenderSettings passed = settings;
  const int left = settings.progression.samples - pass * kSamplesPerPass;
  passed.sampling.samples = std::clamp(left, 0, kSamplesPerPass);
  passed.sampling.pattern = SamplePattern::Jittered;
  passed.seed = pixelSeed(settings.seed, pass, -1);
  return passed;
}

namespace {

double pixelsOf(const PixelRect& area) {
  return static_cast<double>(area.width()) * static_cast<double>(area.height());
}

// The passes' sums, for the whole image: where a render is of a region, the
// image so far is shown and kept at the pixels' own places.
class Passes final : public ProgressivePass, public RenderObserver {
 public:
  Passes(const RenderSettings& settings, RenderObserver& outer)
      : settings_(settings),
        outer_(outer),
        sum_(settings.width, settings.height),
        shown_(Image::unfilled(settings.width, settings.height)),
        luminanceSums_(static_cast<std::size_t>(settings.width) * settings.height, 0.0),
        squareSums_(luminanceSums_.size(), 0.0),
        passesAsked_((settings.progression.samples + kSamplesPerPass - 1) / kSamplesPerPass) {}

  void begin(int pass, int samples) {
    pass_ = pass;
    passSamples_ = samples;
  }
  void add(RenderResult passResult);
  double noise() const;
  RenderResult result(double seconds) const;

  int samplesTaken() const { return samplesTaken_; }

  RenderObserver& observer() override { return *this; }
  void addSample(const Vec2& raster, const Color& color) override {
    const std::size_t at = indexOf(static_cast<int>(raster.x), static_cast<int>(raster.y));
    const double value = luminance(color);
    luminanceSums_[at] += value;
    squareSums_[at] += value * value;
  }

  StepRecorder* stepRecorder() override { return pass_ == 0 ? outer_.stepRecorder() : nullptr; }
  bool cancelled() const override { return outer_.cancelled(); }
  void onProgress(double fraction) override {
    outer_.onProgress(std::min(1.0, (pass_ + fraction) / passesAsked_));
  }
  void onRegionDone(const PixelRect& region) override { outer_.onRegionDone(region); }
  // The image so far: the passes before, with this pass's samples.
  void onPixelsDone(const PixelRect& region, const Image& image) override {
    const float before = static_cast<float>(samplesTaken_);
    const float now = static_cast<float>(passSamples_);
    for (int y = region.y0; y < region.y1; ++y)
      for (int x = region.x0; x < region.x1; ++x)
        shown_.at(x, y) = (sum_.at(x, y) + now * image.at(x, y)) / (before + now);
    outer_.onPixelsDone(region, shown_);
  }

 private:
  std::size_t indexOf(int x, int y) const {
    return static_cast<std::size_t>(std::clamp(y, 0, settings_.height - 1)) * settings_.width +
           static_cast<std::size_t>(std::clamp(x, 0, settings_.width - 1));
  }
  // A pixel's variance of its mean, in luminance.
  double varianceOfMean(std::size_t at) const {
    const double n = samplesTaken_;
    if (n < 2.0) return 0.0;
    const double mean = luminanceSums_[at] / n;
    return std::max(0.0, (squareSums_[at] / n - mean * mean) / (n - 1.0));
  }

  const RenderSettings& settings_;
  RenderObserver& outer_;
  Image sum_, shown_;
  std::vector<double> luminanceSums_, squareSums_;
  RenderResult first_;
  Stats stats_;
  int passesAsked_, pass_ = 0, passSamples_ = 0, samplesTaken_ = 0;
};

void Passes::add(RenderResult passResult) {
  const PixelRect area = settings_.area();
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x)
      sum_.at(x, y) +=
          static_cast<float>(passSamples_) * passResult.image.at(x - area.x0, y - area.y0);
  stats_.accumulate(passResult.stats);
  samplesTaken_ += passSamples_;
  if (pass_ == 0) {
    first_ = std::move(passResult);
  } else if (const auto cost = passResult.buffers.find("cost"); cost != passResult.buffers.end()) {
    Image& total = first_.buffers.at("cost");
    for (int y = 0; y < total.height(); ++y)
      for (int x = 0; x < total.width(); ++x) total.at(x, y) += cost->second.at(x, y);
  }
}

double Passes::noise() const {
  const PixelRect area = settings_.area();
  double variance = 0.0, brightness = 0.0;
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x) {
      const std::size_t at = indexOf(x, y);
      variance += varianceOfMean(at);
      brightness += luminanceSums_[at] / std::max(samplesTaken_, 1);
    }
  return brightness > 0.0 ? std::sqrt(variance / pixelsOf(area)) / (brightness / pixelsOf(area))
                          : 0.0;
}

RenderResult Passes::result(double seconds) const {
  RenderResult result = first_;
  const PixelRect area = settings_.area();
  Image variance(area.width(), area.height());
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x) {
      result.image.at(x - area.x0, y - area.y0) = sum_.at(x, y) / static_cast<float>(samplesTaken_);
      variance.at(x - area.x0, y - area.y0) =
          Color(static_cast<float>(varianceOfMean(indexOf(x, y))));
    }
  if (settings_.wantsBuffer("variance")) result.buffers["variance"] = std::move(variance);
  // Counts add up over the passes; what is per ray is worked out again.
  result.stats = {};
  for (const auto& [name, value] : stats_.entries()) {
    const std::string perRay = "_per_ray";
    const bool ratio = name.size() > perRay.size() && name.ends_with(perRay);
    result.stats.add(name, ratio
                               ? perEach(stats_.value(name.substr(0, name.size() - perRay.size())),
                                         stats_.value("rays"))
                               : value);
  }
  result.stats.add("passes", (samplesTaken_ + kSamplesPerPass - 1) / kSamplesPerPass);
  result.stats.add("noise", noise());
  result.stats.add("samples_per_second", perEach(pixelsOf(area) * samplesTaken_, seconds));
  return result;
}

}  // namespace

RenderResult renderProgressively(const RenderSettings& settings, RenderObserver& observer,
                                 const PassRender& renderPass) {
  Passes passes(settings, observer);
  const auto start = std::chrono::steady_clock::now();
  double lastPassSeconds = 0.0;
  for (int pass = 0;; ++pass) {
    const RenderSettings passed = passSettings(settings, pass);
    if (passed.sampling.samples == 0) break;
    passes.begin(pass, passed.sampling.samples);
    RenderResult passResult;
    lastPassSeconds = secondsOf([&] { passResult = renderPass(passed, passes); });
    if (observer.cancelled()) return passResult;
    passes.add(std::move(passResult));
    const double elapsed = secondsSince(start);
    const Progression& asked = settings.progression;
    if (asked.timeLimit > 0.0 && elapsed + lastPassSeconds > asked.timeLimit) break;
    if (asked.noiseTarget > 0.0 && pass >= 1 && passes.noise() <= asked.noiseTarget) break;
  }
  return passes.result(secondsSince(start));
}

}  // namespace rise
