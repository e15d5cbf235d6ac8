// Comparing the images of two algorithms pixel by pixel, as a viewer sees
// them (8-bit sRGB levels), everywhere but along the outlines, where the
// tessellated shapes of the visible-surface algorithms and the exact ones of
// the ray tracers may show different surfaces at a pixel.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <string_view>
#include <vector>

#include "algorithms/registry.hpp"
#include "io/image_io.hpp"
#include "render/renderer.hpp"

namespace rise::image_agreement_testing {

inline RenderResult renderWith(std::string_view algorithm, const Scene& scene,
                               const RenderSettings& settings) {
  RenderObserver observer;
  return findRenderer(algorithm)->render(scene, settings, observer);
}

// A colour channel as an 8-bit sRGB level.
inline int level(float linear) {
  return static_cast<int>(std::lround(255.0f * srgbFromLinear(std::clamp(linear, 0.0f, 1.0f))));
}

inline int levelDifference(const Color& a, const Color& b) {
  int worst = 0;
  for (int channel = 0; channel < 3; ++channel)
    worst = std::max(worst, std::abs(level(a[channel]) - level(b[channel])));
  return worst;
}

// Where one of two renders of `scene` sees nothing, or sees the surface
// nearly edge-on (within `grazingDegrees`), or the two see surfaces whose
// normals differ by more than `creaseDegrees` (the two sides of a crease,
// such as a cylinder's rim); and the pixels next to those.
inline std::vector<bool> outlines(const Scene& scene, const RenderResult& a, const RenderResult& b,
                                  float grazingDegrees = 15.0f, float creaseDegrees = 30.0f) {
  const int width = a.image.width(), height = a.image.height();
  const ViewFrame view(scene.camera, width, height);
  const Image& depthA = a.buffers.at("depth");
  const Image& depthB = b.buffers.at("depth");
  const Image& normalA = a.buffers.at("normal");
  const Image& normalB = b.buffers.at("normal");
  const float grazingSine = std::sin(grazingDegrees * kPi / 180.0f);
  const float creaseCosine = std::cos(creaseDegrees * kPi / 180.0f);
  std::vector<bool> apart(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec3 towardsPixel =
          view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f).direction;
      apart[y * width + x] =
          !std::isfinite(depthA.at(x, y).r) || !std::isfinite(depthB.at(x, y).r) ||
          std::abs(glm::dot(normalA.at(x, y), glm::normalize(towardsPixel))) < grazingSine ||
          glm::dot(normalA.at(x, y), normalB.at(x, y)) < creaseCosine;
    }
  std::vector<bool> near(apart.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
          if (apart[ny * width + nx]) near[y * width + x] = true;
        }
  return near;
}

// The largest difference between two images (in levels, or pixels of
// offset) over the pixels compared, where it is, and how many pixels were
// compared.
struct Agreement {
  int worst = 0;
  int worstX = -1;
  int worstY = -1;
  int pixelsCompared = 0;
};

inline std::ostream& operator<<(std::ostream& out, const Agreement& agreement) {
  return out << "at worst " << agreement.worst << " at (" << agreement.worstX << ", "
             << agreement.worstY << ") over " << agreement.pixelsCompared << " pixels";
}

inline Agreement agreementWhere(const Image& a, const Image& b,
                                const std::function<bool(int, int)>& compared) {
  Agreement agreement;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      if (!compared(x, y)) continue;
      ++agreement.pixelsCompared;
      const int difference = levelDifference(a.at(x, y), b.at(x, y));
      if (difference <= agreement.worst) continue;
      agreement = {difference, x, y, agreement.pixelsCompared};
    }
  return agreement;
}

// Over every pixel but the outlines.
inline Agreement agreementInside(const Scene& scene, const RenderResult& a, const RenderResult& b) {
  const std::vector<bool> outline = outlines(scene, a, b);
  const int width = a.image.width();
  return agreementWhere(a.image, b.image, [&](int x, int y) { return !outline[y * width + x]; });
}

// The largest difference between the steps from pixel to pixel (to the next
// across, and the next down) of two images, over the pairs of neighbours
// neither of which is on an outline: where one image has an edge the other
// has not, such as a facet of a tessellated surface.
inline Agreement stepAgreementInside(const Scene& scene, const RenderResult& a,
                                     const RenderResult& b) {
  const std::vector<bool> outline = outlines(scene, a, b);
  const int width = a.image.width(), height = a.image.height();
  const auto inside = [&](int x, int y) {
    return x < width && y < height && !outline[y * width + x];
  };
  Agreement agreement;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (const auto& [nx, ny] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
        if (!inside(x, y) || !inside(nx, ny)) continue;
        ++agreement.pixelsCompared;
        int worst = 0;
        for (int channel = 0; channel < 3; ++channel) {
          const int stepA = level(a.image.at(nx, ny)[channel]) - level(a.image.at(x, y)[channel]);
          const int stepB = level(b.image.at(nx, ny)[channel]) - level(b.image.at(x, y)[channel]);
          worst = std::max(worst, std::abs(stepA - stepB));
        }
        if (worst > agreement.worst) agreement = {worst, x, y, agreement.pixelsCompared};
      }
  return agreement;
}

// How far, in pixels, the pixels of `drawn` inside the outlines are from
// where `reference` shows their colour (the distance, in the larger of x and
// y, to the nearest pixel of that colour, searched up to `farthest`, and
// farthest + 1 when none is found): where two images of a texture of flat
// texels agree but for texel edges a little apart, their offset.
inline Agreement offsetInside(const Scene& scene, const RenderResult& drawn,
                              const RenderResult& reference, int farthest = 8) {
  const std::vector<bool> outline = outlines(scene, drawn, reference);
  const Image& a = drawn.image;
  const Image& b = reference.image;
  const auto same = [](const Color& p, const Color& q) { return levelDifference(p, q) <= 1; };
  Agreement agreement;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      if (outline[y * a.width() + x]) continue;
      ++agreement.pixelsCompared;
      int offset = 0;
      while (offset <= farthest) {
        bool found = false;
        for (int dy = -offset; dy <= offset && !found; ++dy)
          for (int dx = -offset; dx <= offset && !found; ++dx) {
            const int nx = x + dx, ny = y + dy;
            found = nx >= 0 && ny >= 0 && nx < a.width() && ny < a.height() &&
                    same(a.at(x, y), b.at(nx, ny));
          }
        if (found) break;
        ++offset;
      }
      if (offset > agreement.worst) agreement = {offset, x, y, agreement.pixelsCompared};
    }
  return agreement;
}

}  // namespace rise::image_agreement_testing
