#include "radiosity/hemicube.hpp"

#include <algorithm>

#include "core/warps.hpp"

namespace rise {

namespace {

// The centre of texel i of a face `resolution` texels wide, from -1 to 1.
float texelCentre(int i, int resolution) {
  return (static_cast<float>(i) + 0.5f) * 2.0f / static_cast<float>(resolution) - 1.0f;
}

}  // namespace

Hemicube::Hemicube(int resolution) : resolution_(resolution + resolution % 2) {
  const float texelArea = 4.0f / static_cast<float>(resolution_ * resolution_);
  const int half = resolution_ / 2;
  for (int y = 0; y < resolution_; ++y)
    for (int x = 0; x < resolution_; ++x) {
      const float u = texelCentre(x, resolution_), v = texelCentre(y, resolution_);
      const float spread = u * u + v * v + 1.0f;
      topDelta_.push_back(texelArea / (kPi * spread * spread));
      // A side face's row y, above the surface for y < half, lies at the
      // height -v along the normal.
      if (y < half) sideDelta_.push_back(-v * texelArea / (kPi * spread * spread));
    }
  for (int face = 0; face < 5; ++face) {
    depth_[static_cast<std::size_t>(face)].resize(topDelta_.size());
    seen_[static_cast<std::size_t>(face)].resize(topDelta_.size());
  }
}

PixelRect Hemicube::above(int face) const {
  return {0, 0, resolution_, face == 0 ? resolution_ : resolution_ / 2};
}

float Hemicube::deltaFormFactor(int face, int x, int y) const {
  const std::size_t texel = static_cast<std::size_t>(y) * resolution_ + x;
  return face == 0 ? topDelta_[texel] : sideDelta_[texel];
}

void Hemicube::draw(const Vec3& point, const Vec3& normal,
                    std::span<const HemicubeTriangle> triangles, int ignored) {
  Vec3 right, up;
  orthonormalBasis(normal, right, up);
  views_[0] = {point, right, up, normal, true, 0.0f, resolution_};
  const std::array<Vec3, 4> sides = {right, -right, up, -up};
  for (int side = 0; side < 4; ++side) {
    const Vec3& forward = sides[static_cast<std::size_t>(side)];
    views_[static_cast<std::size_t>(side) + 1] = {
        point, glm::cross(forward, normal), normal, forward, true, 0.0f, resolution_};
  }
  for (int face = 0; face < 5; ++face) {
    std::fill(depth_[face].begin(), depth_[face].end(), kInfinity);
    std::fill(seen_[face].begin(), seen_[face].end(), -1);
  }
  for (const HemicubeTriangle& triangle : triangles) {
    if (triangle.receiver == ignored) continue;
    // Wholly below the surface's plane: seen by none of the faces.
    if (std::all_of(triangle.corners.begin(), triangle.corners.end(),
                    [&](const Vec3& corner) { return glm::dot(corner - point, normal) <= 0.0f; }))
      continue;
    for (int face = 0; face < 5; ++face) {
      if (!polygon_.project(views_[static_cast<std::size_t>(face)], triangle.corners)) continue;
      std::vector<float>& depth = depth_[static_cast<std::size_t>(face)];
      std::vector<int>& seen = seen_[static_cast<std::size_t>(face)];
      polygon_.forEachTexel(above(face), [&](int x, int y, float nearness) {
        const std::size_t texel = static_cast<std::size_t>(y) * resolution_ + x;
        if (nearness >= depth[texel]) return;
        depth[texel] = nearness;
        seen[texel] = triangle.receiver;
      });
    }
  }
}

std::uint64_t Hemicube::addFormFactors(const Vec3& point, const Vec3& normal,
                                       std::span<const HemicubeTriangle> triangles, int ignored,
                                       std::span<float> formFactors) {
  draw(point, normal, triangles, ignored);
  std::uint64_t covered = 0;
  for (int face = 0; face < 5; ++face) {
    const PixelRect rows = above(face);
    for (int y = rows.y0; y < rows.y1; ++y)
      for (int x = rows.x0; x < rows.x1; ++x) {
        const int receiver = seen_[face][static_cast<std::size_t>(y) * resolution_ + x];
        if (receiver < 0) continue;
        formFactors[static_cast<std::size_t>(receiver)] += deltaFormFactor(face, x, y);
        ++covered;
      }
  }
  return covered;
}

}  // namespace rise
