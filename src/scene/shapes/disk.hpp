#pragma once

#include "core/ray.hpp"

namespace rise {

// Where the ray meets the disk of the given center, normal (any length) and
// squared radius, if that is at t in (tMin, tMax): the caps of cylinders and
// cones. Its rim belongs to it; a ray in its plane misses it.
bool intersectDisk(const Ray& ray, Vec3 center, Vec3 normal, float radiusSquared, float tMin,
                   float tMax, float& t);

}  // namespace rise
