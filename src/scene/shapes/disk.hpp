#pragma once

#include "core/bounds.hpp"
#include "core/ray.hpp"

namespace rise {

// Where the ray meets the disk of the given center, normal (any length) and
// squared radius, if that is at t in (tMin, tMax): the caps of cylinders and
// cones. Its rim belongs to it; a ray in its plane misses it.
bool intersectDisk(const Ray& ray, Vec3 center, Vec3 normal, float radiusSquared, float tMin,
                   float tMax, float& t);

// The box around the disk of the given center, unit normal and radius: along
// each world axis the disk reaches radius times the sine of the angle between
// that axis and the normal, radius * sqrt(1 - normal[axis]^2).
Bounds3 diskBounds(Vec3 center, Vec3 unitNormal, float radius);

}  // namespace rise
