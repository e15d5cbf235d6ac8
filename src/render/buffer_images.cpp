#include "render/buffer_images.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rise {
namespace {

template <typename PixelToDisplay>
Image mapPixels(const Image& raw, PixelToDisplay toDisplay) {
  Image image(raw.width(), raw.height());
  for (int y = 0; y < raw.height(); ++y)
    for (int x = 0; x < raw.width(); ++x) image.at(x, y) = toDisplay(raw.at(x, y));
  return image;
}

Image visualizeDepth(const Image& raw) {
  float nearest = kInfinity;
  float farthest = -kInfinity;
  for (const Color& pixel : raw.pixels())
    if (std::isfinite(pixel.r)) {
      nearest = std::min(nearest, pixel.r);
      farthest = std::max(farthest, pixel.r);
    }
  // Linear in the inverse depth, as a z-buffer keeps it: the levels go to
  // the near surfaces, where the eye tells depths apart, and the far reaches
  // of a floor, a ray tracer's infinite plane or a rasterizer's square of
  // 100,000 units alike, take the few darkest.
  const float nearestInverse = 1.0f / nearest, farthestInverse = 1.0f / farthest;
  const float range = nearestInverse - farthestInverse;
  return mapPixels(raw, [&](const Color& depth) {
    if (!std::isfinite(depth.r)) return Color(0.0f);
    // When every hit is at one depth, all of them are the nearest.
    return Color(range > 0.0f ? (1.0f / depth.r - farthestInverse) / range : 1.0f);
  });
}

Image visualizeShadowMap(const Image& raw) {
  float nearest = kInfinity;
  for (const Color& pixel : raw.pixels())
    if (pixel.r > 0.0f) nearest = std::min(nearest, pixel.r);
  return mapPixels(raw, [&](const Color& depth) {
    return depth.r > 0.0f && std::isfinite(depth.r) ? Color(nearest / depth.r) : Color(0.0f);
  });
}

Image visualizeNormal(const Image& raw) {
  return mapPixels(raw, [](const Color& normal) {
    return normal == Color(0.0f) ? Color(0.0f) : 0.5f * normal + 0.5f;
  });
}

// R. Du's degree-5 polynomial fit of Turbo: the coefficients of x^0 ... x^5.
using TurboPolynomial = float[6];
constexpr TurboPolynomial kTurboRed = {0.13572138f,   4.61539260f,    -42.66032258f,
                                       132.13108234f, -152.94239396f, 59.28637943f};
constexpr TurboPolynomial kTurboGreen = {0.09140261f,   2.19418839f, 4.84296658f,
                                         -14.18503333f, 4.27729857f, 2.82956604f};
constexpr TurboPolynomial kTurboBlue = {0.10667330f,   12.64194608f,  -60.58204836f,
                                        110.36276771f, -89.90310912f, 27.34824973f};

float evaluate(const TurboPolynomial& coefficients, float x) {
  float value = 0.0f;
  for (int power = 5; power >= 0; --power) value = value * x + coefficients[power];
  return value;
}

// The fit strays slightly below 0 near x = 1, hence the final clamp.
Color turbo(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  const Color color(evaluate(kTurboRed, x), evaluate(kTurboGreen, x), evaluate(kTurboBlue, x));
  return glm::clamp(color, 0.0f, 1.0f);
}

Image visualizeCost(const Image& raw) {
  float largest = 0.0f;
  for (const Color& pixel : raw.pixels()) largest = std::max(largest, pixel.r);
  return mapPixels(raw, [largest](const Color& cost) {
    return turbo(largest > 0.0f ? cost.r / largest : 0.0f);
  });
}

// A bright colour for each face number: the bits of a hash of the number
// (Wang's integer hash) become the three channels.
Image visualizeFace(const Image& raw) {
  return mapPixels(raw, [](const Color& face) {
    if (face.r < 0.0f) return Color(0.0f);
    auto hash = static_cast<std::uint32_t>(face.r);
    hash = (hash ^ 61u) ^ (hash >> 16);
    hash *= 9u;
    hash ^= hash >> 4;
    hash *= 0x27d4eb2du;
    hash ^= hash >> 15;
    const auto channel = [&](int shift) {
      return 0.25f + 0.75f * static_cast<float>((hash >> shift) & 0xffu) / 255.0f;
    };
    return Color(channel(0), channel(8), channel(16));
  });
}

}  // namespace

Image visualizeBuffer(std::string_view name, const Image& raw) {
  if (name == "depth") return visualizeDepth(raw);
  if (name == "normal") return visualizeNormal(raw);
  if (name == "cost") return visualizeCost(raw);
  if (name == "face") return visualizeFace(raw);
  if (name == "shadow-map") return visualizeShadowMap(raw);
  // The standard error, whose scale is the pixel's own, on the cost's colours.
  if (name == "variance")
    return visualizeCost(mapPixels(raw, [](const Color& variance) { return glm::sqrt(variance); }));
  throw std::invalid_argument("unknown buffer '" + std::string(name) +
                              "' (known: depth, normal, cost, face, shadow-map, variance)");
}

}  // namespace rise
