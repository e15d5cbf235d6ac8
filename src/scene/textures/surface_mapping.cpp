#include "scene/textures/surface_mapping.hpp"

#include <algorithm>
#include <cmath>

#include "core/warps.hpp"

namespace rise {

float turnAroundAxis(const Vec3& axis, const Vec3& direction) {
  Vec3 across, acrossToo;
  orthonormalBasis(axis, across, acrossToo);
  const float angle = std::atan2(glm::dot(direction, acrossToo), glm::dot(direction, across));
  const float turn = angle / (2.0f * kPi);
  return turn < 0.0f ? turn + 1.0f : turn;
}

float turnAtStep(float step, int segments) { return step / static_cast<float>(segments); }

Vec3 turnTangent(const Vec3& axis, const Vec3& acrossAxis) {
  return 2.0f * kPi * glm::cross(axis, acrossAxis);
}

void sphericalTangents(const Vec3& axis, const Vec3& fromCenter, Vec3& dpdu, Vec3& dpdv) {
  const float height = glm::dot(fromCenter, axis);
  dpdu = turnTangent(axis, fromCenter - height * axis);
  // Northwards along the meridian, half a circle of the sphere's radius.
  const float radiusSquared = glm::dot(fromCenter, fromCenter);
  const Vec3 north = radiusSquared * axis - height * fromCenter;
  const float northLength = glm::length(north);
  dpdv = northLength > 0.0f ? (kPi * std::sqrt(radiusSquared) / northLength) * north : Vec3(0.0f);
}

Vec2 sphericalUv(const Vec3& axis, const Vec3& unitDirection) {
  const float height = std::clamp(glm::dot(unitDirection, axis), -1.0f, 1.0f);
  return {turnAroundAxis(axis, unitDirection), 1.0f - std::acos(height) / kPi};
}

Vec2 diskUv(const Vec3& position, const Vec3& center, const Vec3& outwardNormal, float radius) {
  Vec3 across, acrossToo;
  orthonormalBasis(outwardNormal, across, acrossToo);
  return Vec2(0.5f) + planarUv(position, center, across, acrossToo) / (2.0f * radius);
}

void triangleTangents(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec2& uv0,
                      const Vec2& uv1, const Vec2& uv2, Vec3& dpdu, Vec3& dpdv) {
  // p1 - p0 = du1 dpdu + dv1 dpdv and p2 - p0 = du2 dpdu + dv2 dpdv, solved.
  const Vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
  const float determinant = d1.x * d2.y - d1.y * d2.x;
  if (determinant == 0.0f) {
    dpdu = dpdv = Vec3(0.0f);
    return;
  }
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;
  dpdu = (d2.y * e1 - d1.y * e2) / determinant;
  dpdv = (d1.x * e2 - d2.x * e1) / determinant;
}

void diskTangents(const Vec3& outwardNormal, float radius, Vec3& dpdu, Vec3& dpdv) {
  orthonormalBasis(outwardNormal, dpdu, dpdv);
  dpdu *= 2.0f * radius;
  dpdv *= 2.0f * radius;
}

void cubeFaceAxes(const Vec3& faceNormal, Vec3& uAxis, Vec3& vAxis) {
  const bool onTopOrBottom = faceNormal.y != 0.0f;
  vAxis = onTopOrBottom ? Vec3(0.0f, 0.0f, -faceNormal.y) : Vec3(0.0f, 1.0f, 0.0f);
  uAxis = glm::cross(vAxis, faceNormal);
}

Vec2 cubeFaceUv(const Vec3& position, const Vec3& faceNormal, const Vec3& min, const Vec3& max) {
  Vec3 uAxis, vAxis;
  cubeFaceAxes(faceNormal, uAxis, vAxis);
  // The face's corner where u and v are least, and its extent along each.
  const Vec3 size = max - min;
  const Vec3 lowCorner = glm::mix(max, min, glm::step(Vec3(0.0f), uAxis + vAxis));
  return {glm::dot(position - lowCorner, uAxis) / glm::dot(size, glm::abs(uAxis)),
          glm::dot(position - lowCorner, vAxis) / glm::dot(size, glm::abs(vAxis))};
}

void cubeFaceTangents(const Vec3& faceNormal, const Vec3& min, const Vec3& max, Vec3& dpdu,
                      Vec3& dpdv) {
  cubeFaceAxes(faceNormal, dpdu, dpdv);
  const Vec3 size = max - min;
  dpdu *= glm::dot(size, glm::abs(dpdu));
  dpdv *= glm::dot(size, glm::abs(dpdv));
}

Vec3 cubeFaceFacing(const Vec3& normal) {
  const int axis = largestAxis(glm::abs(normal));
  Vec3 face(0.0f);
  face[axis] = normal[axis] < 0.0f ? -1.0f : 1.0f;
  return face;
}

void projectedTangents(const Vec3& normal, const Vec3& alongU, const Vec3& alongV, Vec3& dpdu,
                       Vec3& dpdv) {
  dpdu = dpdv = Vec3(0.0f);
  const float lengthU = glm::dot(alongU, alongU), lengthV = glm::dot(alongV, alongV);
  if (lengthU == 0.0f || lengthV == 0.0f) return;
  // The gradients of u and of v (perpendicular tangents: each along its own,
  // at the inverse rate), restricted to the tangent plane.
  const Vec3 gradientU = alongU / lengthU - (glm::dot(alongU, normal) / lengthU) * normal;
  const Vec3 gradientV = alongV / lengthV - (glm::dot(alongV, normal) / lengthV) * normal;
  // dP/du is the direction in the plane across gradientV along which u
  // grows at 1 per unit; dP/dv likewise: the dual basis of the gradients.
  const float determinant = glm::dot(normal, glm::cross(gradientU, gradientV));
  if (std::abs(determinant) <=
      1e-6f * std::sqrt(glm::dot(gradientU, gradientU) * glm::dot(gradientV, gradientV)))
    return;
  dpdu = glm::cross(gradientV, normal) / determinant;
  dpdv = glm::cross(normal, gradientU) / determinant;
}

}  // namespace rise
