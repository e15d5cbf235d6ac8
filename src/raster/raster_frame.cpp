#include "raster/raster_frame.hpp"

namespace rise {

RasterFrame::RasterFrame(int width, int height, const Color& background,
                         const ScreenGeometry& screen, const SurfaceShader& shader)
    : screen_(screen), shader_(shader) {
  result_.image = Image(width, height, background);
  depth_ = &(result_.buffers["depth"] = Image(width, height, Color(kInfinity)));
  normal_ = &(result_.buffers["normal"] = Image(width, height));
  face_ = &(result_.buffers["face"] = Image(width, height, Color(-1.0f)));
  cost_ = &(result_.buffers["cost"] = Image(width, height));
}

void RasterFrame::setVisible(int x, int y, int face) {
  const ShadedPixel pixel =
      shader_.shade(face, Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  result_.image.at(x, y) = pixel.color;
  depth_->at(x, y) = Color(pixel.depth);
  normal_->at(x, y) = pixel.normal;
  face_->at(x, y) = Color(static_cast<float>(screen_.faces[face].sceneFace));
}

std::uint64_t RasterFrame::coveredPixels() const {
  std::uint64_t covered = 0;
  for (const Color& face : face_->pixels()) covered += face.r >= 0.0f ? 1 : 0;
  return covered;
}

}  // namespace rise
