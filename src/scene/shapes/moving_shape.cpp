#include "scene/shapes/moving_shape.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace rise {

MovingShape::MovingShape(std::unique_ptr<Shape> shape, const TransformSpec& open,
                         const TransformSpec& close)
    : Shape(shape->material()), shape_(std::move(shape)), open_(open), close_(close) {}

AffineMap MovingShape::placementAt(float time) const {
  return AffineMap(worldFromObject(interpolate(open_, close_, time)));
}

bool MovingShape::intersect(const Ray& ray, float tMin, Hit& hit,
                            IntersectionCounters& counters) const {
  if (!shape_->intersect(placementAt(ray.time).toObject(ray), tMin, hit, counters)) return false;
  hit.shape = this;
  return true;
}

SurfacePoint MovingShape::surfaceAt(const Ray& ray, const Hit& hit) const {
  const AffineMap placement = placementAt(ray.time);
  return placement.toWorld(shape_->surfaceAt(placement.toObject(ray), hit));
}

SurfacePoint MovingShape::pointAt(const Ray& ray, const Hit& hit) const {
  const AffineMap placement = placementAt(ray.time);
  return placement.toWorld(shape_->pointAt(placement.toObject(ray), hit));
}

// The shape stays inside the ball around its box. The ball's centre follows a
// path sampled at many instants; between two samples (a straight step, or a
// short arc of the rotation) it strays from both by at most the step's
// length, which pads the balls.
Bounds3 MovingShape::bounds() const {
  const Bounds3 object = shape_->bounds();
  if (!object.isFinite()) return object;
  constexpr int kSteps = 32;
  const Vec3 centre = object.centre();
  const float radius = 0.5f * glm::length(object.extent());
  const float largestScale = maxComponent(glm::max(glm::abs(open_.scale), glm::abs(close_.scale)));

  std::vector<Vec3> path;
  float longestStep = 0.0f;
  for (int step = 0; step <= kSteps; ++step) {
    path.push_back(placementAt(static_cast<float>(step) / kSteps).pointToWorld(centre));
    if (step > 0) longestStep = std::max(longestStep, glm::length(path[step] - path[step - 1]));
  }
  const Vec3 reach(radius * largestScale + longestStep);
  Bounds3 swept;
  for (const Vec3& point : path) {
    swept.grow(point - reach);
    swept.grow(point + reach);
  }
  return swept;
}

// Where the shape is at the instant drawn.
void MovingShape::tessellate(const TessellationSettings& settings, Tessellation& out) const {
  tessellatePlaced(*shape_, worldFromObject(interpolate(open_, close_, settings.time)), settings,
                   out);
}

std::uint64_t MovingShape::tessellatedTriangles(int level) const {
  return shape_->tessellatedTriangles(level);
}

}  // namespace rise
