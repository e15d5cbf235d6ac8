#include "ray/ritter_sphere.hpp"

#include <array>
#include <cassert>

namespace rise {
namespace {

// The report's CheckPoint. A point outside the sphere becomes the far end of
// a new diameter whose other end is the old sphere's far side, opposite the
// point; the new sphere holds the old one and the point. (The report's
// pseudo-code moves the centre but forgets to keep the new radius; Ritter's
// original keeps it, as here.)
void takeIn(BoundingSphere& sphere, const Vec3& point) {
  const float oldToPoint = glm::distance(sphere.centre, point);
  if (oldToPoint <= sphere.radius) return;
  const float newRadius = 0.5f * (sphere.radius + oldToPoint);
  const float oldToNew = oldToPoint - newRadius;
  sphere.centre = (newRadius * sphere.centre + oldToNew * point) / oldToPoint;
  sphere.radius = newRadius;
}

}  // namespace

BoundingSphere ritterBoundingSphere(std::span<const Vec3> points) {
  assert(!points.empty());
  // First pass: along each axis, the point with the least and the one with
  // the greatest coordinate.
  std::array<Vec3, 3> least{points[0], points[0], points[0]};
  std::array<Vec3, 3> greatest = least;
  for (const Vec3& point : points) {
    for (int axis = 0; axis < 3; ++axis) {
      if (point[axis] < least[axis][axis]) least[axis] = point;
      if (point[axis] > greatest[axis][axis]) greatest[axis] = point;
    }
  }
  // Of those three pairs, the one farthest apart is the first diameter.
  int widest = 0;
  for (int axis = 1; axis < 3; ++axis) {
    if (glm::distance(least[axis], greatest[axis]) > glm::distance(least[widest], greatest[widest]))
      widest = axis;
  }
  BoundingSphere sphere;
  sphere.centre = 0.5f * (least[widest] + greatest[widest]);
  sphere.radius = glm::distance(greatest[widest], sphere.centre);
  // Second pass: grow the sphere over every point left outside it.
  for (const Vec3& point : points) takeIn(sphere, point);
  return sphere;
}

}  // namespace rise
