#include "scene/shapes/box.hpp"

#include <algorithm>
#include <array>

#include "scene/textures/surface_mapping.hpp"

namespace rise {

namespace {

// The primitive a box hit records: 2 axis, plus 1 for the face on the max side.
int faceIndex(int axis, bool maxSide) { return 2 * axis + (maxSide ? 1 : 0); }

Vec3 faceNormal(int face) {
  Vec3 normal(0.0f);
  normal[face / 2] = face % 2 == 1 ? 1.0f : -1.0f;
  return normal;
}

}  // namespace

Box::Box(Vec3 min, Vec3 max, int material)
    : Shape(material), min_(glm::min(min, max)), max_(glm::max(min, max)) {}

bool Box::intersect(const Ray& ray, float tMin, Hit& hit, IntersectionCounters& counters) const {
  ++counters.tests;
  float tEnter = -kInfinity;
  float tExit = kInfinity;
  int enterFace = 0;
  int exitFace = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const float origin = ray.origin[axis];
    const float direction = ray.direction[axis];
    if (direction == 0.0f) {
      // Parallel to this pair of planes: between them for every t, or never.
      if (origin < min_[axis] || origin > max_[axis]) return false;
      continue;
    }
    const bool towardsMax = direction > 0.0f;
    const float inverseDirection = 1.0f / direction;
    const float tIn = ((towardsMax ? min_[axis] : max_[axis]) - origin) * inverseDirection;
    const float tOut = ((towardsMax ? max_[axis] : min_[axis]) - origin) * inverseDirection;
    if (tIn > tEnter) {
      tEnter = tIn;
      enterFace = faceIndex(axis, !towardsMax);
    }
    if (tOut < tExit) {
      tExit = tOut;
      exitFace = faceIndex(axis, towardsMax);
    }
  }
  if (tEnter > tExit) return false;
  if (tEnter > tMin && tEnter < hit.t) {
    hit.t = tEnter;
    hit.primitive = enterFace;
  } else if (tExit > tMin && tExit < hit.t) {
    hit.t = tExit;
    hit.primitive = exitFace;
  } else {
    return false;
  }
  hit.shape = this;
  return true;
}

SurfacePoint Box::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Vec3 position = ray.at(hit.t);
  const Vec3 normal = faceNormal(hit.primitive);
  SurfacePoint surface(position, normal, cubeFaceUv(position, normal, min_, max_));
  cubeFaceTangents(normal, min_, max_, surface.dpdu, surface.dpdv);
  return surface;
}

Bounds3 Box::bounds() const { return {min_, max_}; }

void Box::tessellate(const TessellationSettings&, Tessellation& out) const {
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const bool maxSide = face % 2 == 1;
    // u x v is the axis, so u then v turns counter-clockwise around +axis.
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    std::array<int, 4> corners;
    for (int corner = 0; corner < 4; ++corner) {
      Vec3 position = maxSide ? max_ : min_;
      position[u] = (corner == 1 || corner == 2) ? max_[u] : min_[u];
      position[v] = corner >= 2 ? max_[v] : min_[v];
      const Vec3 normal = faceNormal(face);
      corners[corner] = out.addVertex({position, normal, cubeFaceUv(position, normal, min_, max_)});
    }
    if (!maxSide) std::reverse(corners.begin(), corners.end());
    out.addConvexPolygon(corners);
  }
  out.enclosesSolid = true;
}

}  // namespace rise
