#include "ray/bounding_spheres.hpp"

#include <array>

#include "scene/shapes/quadratic.hpp"

namespace rise {
namespace {

// The points whose hull holds the shape: the corners of its triangles, or of
// the boxes of primitives that are not triangles. For a mesh these are its
// vertices (each repeated once for each triangle around it, which Ritter's
// passes do not mind).
std::vector<Vec3> hullPoints(const Shape& shape) {
  std::vector<Vec3> points;
  for (int primitive = 0; primitive < shape.primitiveCount(); ++primitive) {
    std::array<Vec3, 3> corners{};
    if (shape.primitiveTriangle(primitive, corners)) {
      points.insert(points.end(), corners.begin(), corners.end());
    } else {
      const Bounds3 box = shape.primitiveBounds(primitive);
      for (int corner = 0; corner < 8; ++corner) points.push_back(box.corner(corner));
    }
  }
  return points;
}

// Ritter's sphere holds every point only up to rounding: widened by a
// millionth of its size, so that no grazing hit on the mesh is lost.
constexpr float kRoundingAllowance = 1e-6f;

std::optional<BoundingSphere> sphereAround(const Shape& shape) {
  if (shape.primitiveCount() < 2 || !shape.bounds().isFinite()) return std::nullopt;
  const std::vector<Vec3> points = hullPoints(shape);
  BoundingSphere sphere = ritterBoundingSphere(points);
  const float size = sphere.radius + glm::length(sphere.centre);
  sphere.radius += kRoundingAllowance * size;
  return sphere;
}

}  // namespace

BoundingSpheres::BoundingSpheres(const std::vector<std::unique_ptr<Shape>>& shapes)
    : shapes_(shapes) {
  spheres_.reserve(shapes.size());
  for (const auto& shape : shapes) spheres_.push_back(sphereAround(*shape));
}

bool BoundingSpheres::mayMeet(std::size_t shape, const Ray& ray, float tMin, float tMax,
                              IntersectionCounters& counters) const {
  const std::optional<BoundingSphere>& sphere = spheres_[shape];
  if (!sphere) return true;
  ++counters.nodesVisited;
  float enter, exit;
  if (!solveLineAtDistance(ray.origin - sphere->centre, ray.direction,
                           sphere->radius * sphere->radius, enter, exit))
    return false;
  return enter < tMax && exit > tMin;
}

bool BoundingSpheres::nearest(const Ray& ray, float tMin, Hit& hit,
                              IntersectionCounters& counters) const {
  bool found = false;
  for (std::size_t i = 0; i < shapes_.size(); ++i)
    if (mayMeet(i, ray, tMin, hit.t, counters))
      found |= shapes_[i]->intersect(ray, tMin, hit, counters);
  return found;
}

void BoundingSpheres::visitCrossings(const Ray& ray, float tMin, float tMax,
                                     CrossingVisitor& visitor,
                                     IntersectionCounters& counters) const {
  for (std::size_t i = 0; i < shapes_.size(); ++i)
    if (mayMeet(i, ray, tMin, tMax, counters) && crosses(*shapes_[i], ray, tMin, tMax, counters) &&
        !visitor.crossed(static_cast<int>(i)))
      return;
}

}  // namespace rise
