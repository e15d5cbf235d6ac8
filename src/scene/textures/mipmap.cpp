#include "scene/textures/mipmap.hpp"

#include <algorithm>
#include <cmath>

#include "scene/textures/texel_sampling.hpp"

namespace rise {

namespace {

// The longest footprint the elliptical average follows, in widths of its
// shorter side: a longer one is widened, read on a coarser level, so that
// the texels summed stay few (Heckbert's thesis bounds them the same way).
constexpr float kMostAnisotropy = 16.0f;
// The Gaussian's falloff, exp(-alpha r^2) over the ellipse's radius r in
// [0, 1], as in Heckbert's thesis.
constexpr float kFalloff = 2.0f;

// Half the size (rounded up), each texel the mean of the 2 x 2 it covers;
// the image repeats, so an odd edge averages with the other side.
Image halved(const Image& image) {
  Image half(std::max(1, (image.width() + 1) / 2), std::max(1, (image.height() + 1) / 2));
  for (int y = 0; y < half.height(); ++y)
    for (int x = 0; x < half.width(); ++x)
      half.at(x, y) =
          0.25f *
          (repeatedTexel(image, 2 * x, 2 * y) + repeatedTexel(image, 2 * x + 1, 2 * y) +
           repeatedTexel(image, 2 * x, 2 * y + 1) + repeatedTexel(image, 2 * x + 1, 2 * y + 1));
  return half;
}

}  // namespace

MipMap::MipMap(const Image& image) : levels_{image} {
  while (levels_.back().width() > 1 || levels_.back().height() > 1)
    levels_.push_back(halved(levels_.back()));
}

float MipMap::levelFor(float texels) const {
  const float top = static_cast<float>(levels_.size() - 1);
  return texels > 1.0f ? std::min(std::log2(texels), top) : 0.0f;
}

Color MipMap::trilinearAt(const Vec2& uv, const PixelFootprint& footprint) const {
  const Vec2 size(static_cast<float>(levels_[0].width()), static_cast<float>(levels_[0].height()));
  const float level = levelFor(
      std::max(glm::length(footprint.acrossX * size), glm::length(footprint.downY * size)));
  const auto finer = static_cast<std::size_t>(std::floor(level));
  const std::size_t coarser = std::min(finer + 1, levels_.size() - 1);
  return glm::mix(bilinearAt(levels_[finer], uv), bilinearAt(levels_[coarser], uv),
                  level - static_cast<float>(finer));
}

float MipMap::Ellipse::longerSquared() const {
  return 0.5f * (xx + yy) + std::hypot(0.5f * (xx - yy), xy);
}

float MipMap::Ellipse::shorterSquared() const {
  return std::max(0.5f * (xx + yy) - std::hypot(0.5f * (xx - yy), xy), 0.0f);
}

MipMap::Ellipse MipMap::ellipseOf(const PixelFootprint& footprint) const {
  const Vec2 size(static_cast<float>(levels_[0].width()), static_cast<float>(levels_[0].height()));
  // In texels, rows running down as v runs up.
  const Vec2 a(footprint.acrossX.x * size.x, -footprint.acrossX.y * size.y);
  const Vec2 b(footprint.downY.x * size.x, -footprint.downY.y * size.y);
  return {a.x * a.x + b.x * b.x, a.x * a.y + b.x * b.y, a.y * a.y + b.y * b.y};
}

Color MipMap::ellipticalAverageAt(const Vec2& uv, const PixelFootprint& footprint) const {
  Ellipse ellipse = ellipseOf(footprint);
  const float longer = ellipse.longerSquared(), shorter = ellipse.shorterSquared();
  // Smaller than a texel: the texture magnified, read as the other filters
  // read it.
  if (longer <= 1.0f) return bilinearAt(levels_[0], uv);
  // Too long: the shorter axis widened to a 1 / kMostAnisotropy of the
  // longer, along its own direction, perpendicular to the longer's.
  const float widest = longer / (kMostAnisotropy * kMostAnisotropy);
  if (shorter < widest) {
    const Vec2 alongLonger = std::abs(ellipse.xx - longer) > std::abs(ellipse.yy - longer)
                                 ? Vec2(ellipse.xy, longer - ellipse.xx)
                                 : Vec2(longer - ellipse.yy, ellipse.xy);
    const Vec2 across = glm::normalize(Vec2(-alongLonger.y, alongLonger.x));
    const float widen = widest - shorter;
    ellipse.xx += widen * across.x * across.x;
    ellipse.xy += widen * across.x * across.y;
    ellipse.yy += widen * across.y * across.y;
  }
  const float level = levelFor(std::sqrt(std::max(shorter, widest)));
  // Wider than the whole texture, which repeats: the average of it all, the
  // one texel of the top level, without summing the periods the footprint
  // spans (millions, for a texture repeated a thousand times).
  if (!std::isfinite(longer) || level >= static_cast<float>(levels_.size() - 1))
    return levels_.back().at(0, 0);
  const auto finer = static_cast<int>(std::floor(level));
  const int coarser = std::min(finer + 1, static_cast<int>(levels_.size()) - 1);
  const Color atFiner = ellipticalAverageOn(finer, uv, ellipse);
  if (coarser == finer) return atFiner;
  return glm::mix(atFiner, ellipticalAverageOn(coarser, uv, ellipse),
                  level - static_cast<float>(finer));
}

// The weighted sum over the texels whose centres lie inside the ellipse,
// widened by one texel of this level all round (its texels are the samples
// of a continuous image: the filter must span at least one).
Color MipMap::ellipticalAverageOn(int level, const Vec2& uv, const Ellipse& ellipse) const {
  const Image& image = levels_[level];
  const float shrink = std::ldexp(1.0f, -2 * level);
  const float xx = ellipse.xx * shrink + 1.0f, xy = ellipse.xy * shrink,
              yy = ellipse.yy * shrink + 1.0f;
  const float determinant = xx * yy - xy * xy;
  // Texel (i, j)'s centre is at (i, j) from here.
  const Vec2 centre = texelCoordinates(image, uv) - Vec2(0.5f);
  const float halfWidth = std::sqrt(xx), halfHeight = std::sqrt(yy);
  const auto first = [](float from) { return static_cast<long long>(std::ceil(from)); };
  const auto last = [](float to) { return static_cast<long long>(std::floor(to)); };
  const float rim = std::exp(-kFalloff);
  Color sum(0.0f);
  float weights = 0.0f;
  for (long long j = first(centre.y - halfHeight); j <= last(centre.y + halfHeight); ++j) {
    const float dy = static_cast<float>(j) - centre.y;
    for (long long i = first(centre.x - halfWidth); i <= last(centre.x + halfWidth); ++i) {
      const float dx = static_cast<float>(i) - centre.x;
      const float radius2 = (yy * dx * dx - 2.0f * xy * dx * dy + xx * dy * dy) / determinant;
      if (radius2 >= 1.0f) continue;
      const float weight = std::exp(-kFalloff * radius2) - rim;
      sum += weight * repeatedTexel(image, i, j);
      weights += weight;
    }
  }
  return weights > 0.0f ? sum / weights : bilinearAt(image, uv);
}

}  // namespace rise
