// An image on the graphics card, for Dear ImGui to draw: linear colours are
// encoded as sRGB for the screen, as the command line's PNG files are.
#pragma once

#include <cstdint>

#include "core/image.hpp"

namespace rise::studio {

class Texture {
 public:
  Texture() = default;
  ~Texture();
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;

  // Replaces the whole texture by `image`, linear colours (`encode`) or
  // display values already (buffer pictures, difference images).
  void upload(const Image& image, bool encode = true);
  // Replaces the pixels of `region` by those of `image` (the texture's size).
  void update(const Image& image, const PixelRect& region, bool encode = true);

  bool empty() const { return id_ == 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  void* handle() const { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(id_)); }

 private:
  unsigned id_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace rise::studio
