#include "texture.hpp"

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "io/image_io.hpp"

namespace rise::studio {
namespace {

// The display byte of every linear value in [0, 1], in steps fine enough
// for the darkest sRGB levels: a table, as a large image is encoded while the
// window waits.
constexpr int kEncodingSteps = 1 << 14;

const std::array<unsigned char, kEncodingSteps + 1>& srgbBytes() {
  static const auto table = [] {
    std::array<unsigned char, kEncodingSteps + 1> bytes{};
    for (int i = 0; i <= kEncodingSteps; ++i)
      bytes[static_cast<std::size_t>(i)] = static_cast<unsigned char>(
          srgbFromLinear(static_cast<float>(i) / kEncodingSteps) * 255.0f + 0.5f);
    return bytes;
  }();
  return table;
}

std::vector<unsigned char> displayBytes(const Image& image, const PixelRect& region, bool encode) {
  std::vector<unsigned char> bytes;
  bytes.reserve(static_cast<std::size_t>(region.width()) * region.height() * 4);
  const auto& srgb = srgbBytes();
  const auto byte = [&](float value) {
    const float clamped = std::clamp(value, 0.0f, 1.0f);
    return encode ? srgb[static_cast<std::size_t>(clamped * kEncodingSteps + 0.5f)]
                  : static_cast<unsigned char>(clamped * 255.0f + 0.5f);
  };
  for (int y = region.y0; y < region.y1; ++y)
    for (int x = region.x0; x < region.x1; ++x) {
      const Color& color = image.at(x, y);
      bytes.insert(bytes.end(), {byte(color.r), byte(color.g), byte(color.b), 255});
    }
  return bytes;
}

}  // namespace

Texture::~Texture() {
  if (id_ != 0) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)), width_(other.width_), height_(other.height_) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  return *this;
}

void Texture::upload(const Image& image, bool encode) {
  if (id_ == 0) glGenTextures(1, &id_);
  width_ = image.width();
  height_ = image.height();
  glBindTexture(GL_TEXTURE_2D, id_);
  // Pixels stay square and sharp when zoomed in, as a student wants to see them.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<unsigned char> bytes = displayBytes(image, {0, 0, width_, height_}, encode);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               bytes.data());
}

void Texture::update(const Image& image, const PixelRect& region, bool encode) {
  if (id_ == 0 || image.width() != width_ || image.height() != height_) {
    upload(image, encode);
    return;
  }
  const PixelRect area = region.intersection({0, 0, width_, height_});
  if (area.isEmpty()) return;
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<unsigned char> bytes = displayBytes(image, area, encode);
  glTexSubImage2D(GL_TEXTURE_2D, 0, area.x0, area.y0, area.width(), area.height(), GL_RGBA,
                  GL_UNSIGNED_BYTE, bytes.data());
}

}  // namespace rise::studio
