#include "raster/raster_frame.hpp"

#include <array>

namespace rise {

RasterFrame::RasterFrame(int width, int height, const Color& background,
                         const ScreenGeometry& screen, const SurfaceShader& shader,
                         const Workers& workers, StepRecorder* steps, ShadowVolumes* shadowVolumes)
    : screen_(screen),
      shader_(shader),
      steps_(steps),
      shadowVolumes_(shadowVolumes),
      background_(background) {
  // Filling five image-sized buffers is a fair share of a frame of a large
  // image: the render's workers share it.
  const std::array<Color, 5> fills = {background, Color(kInfinity), Color(0.0f), Color(-1.0f),
                                      Color(0.0f)};
  std::array<Image, 5> images;
  workers.forEachRange(static_cast<int>(images.size()), 1, [&](int image, int, int) {
    images[image] = Image(width, height, fills[image]);
  });
  result_.image = std::move(images[0]);
  depth_ = &(result_.buffers["depth"] = std::move(images[1]));
  normal_ = &(result_.buffers["normal"] = std::move(images[2]));
  face_ = &(result_.buffers["face"] = std::move(images[3]));
  cost_ = &(result_.buffers["cost"] = std::move(images[4]));
}

ShadedPixel RasterFrame::shadeAt(int x, int y, int face) const {
  const Vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
  if (!shadowVolumes_ || isTransparent(face)) return shader_.shade(face, centre);
  const PixelShadows shadows = shadowVolumes_->at(x, y);
  return shader_.shade(face, centre, shadows.any() ? &shadows : nullptr);
}

void RasterFrame::setVisible(int x, int y, int face) {
  const ShadedPixel pixel = shadeAt(x, y, face);
  result_.image.at(x, y) = pixel.color;
  depth_->at(x, y) = Color(pixel.depth);
  normal_->at(x, y) = pixel.normal;
  face_->at(x, y) = Color(static_cast<float>(screen_.faces[face].sceneFace));
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
  std::uint64_t covered = 0;
  for (const Color& face : face_->pixels()) covered += face.r >= 0.0f ? 1 : 0;
  return covered;
}

}  // namespace rise
