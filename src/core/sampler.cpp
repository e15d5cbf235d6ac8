#include "core/sampler.hpp"

namespace rise {

Sampler::Sampler(SampleLayout layout)
    : squares_(static_cast<std::size_t>(layout.squares)),
      intervals_(static_cast<std::size_t>(layout.intervals)) {}

const std::vector<Vec2>& Sampler::startPixel(const PixelSampling& sampling, Rng& rng) {
  samples_ = sampling.samples;
  const bool random = sampling.pattern == SamplePattern::Random;
  samplePositions(sampling.pattern, samples_, rng, pixel_);
  for (std::vector<Vec2>& values : squares_)
    samplePositions(random ? SamplePattern::Random : SamplePattern::Jittered, samples_, rng,
                    values);
  for (std::vector<float>& values : intervals_) {
    if (random) {
      values.resize(static_cast<std::size_t>(samples_));
      for (float& value : values) value = rng.uniform();
    } else {
      jitteredValues(samples_, rng, values);
    }
  }
  for (std::vector<Vec2>& values : squares_) shuffle(values, rng);
  for (std::vector<float>& values : intervals_) shuffle(values, rng);
  return pixel_;
}

SampleValues Sampler::valuesOf(int sample, Rng& rng) const { return {*this, sample, rng}; }

Vec2 SampleValues::next2D() {
  if (sampler_ && square_ < sampler_->squares_.size())
    return sampler_->squares_[square_++][static_cast<std::size_t>(sample_)];
  const float u = rng_.uniform();
  return {u, rng_.uniform()};
}

float SampleValues::next1D() {
  if (sampler_ && interval_ < sampler_->intervals_.size())
    return sampler_->intervals_[interval_++][static_cast<std::size_t>(sample_)];
  return rng_.uniform();
}

}  // namespace rise
