// Warps: maps from the unit square, where samples are stratified
// (core/sampler.hpp), onto the domains an algorithm samples: a lens's disk,
// the directions of a hemisphere or of the sphere, a cone of directions. A
// warp that keeps the square's strata apart keeps the samples well spread
// where they land. Each warp's density, per unit of area or of solid angle,
// is given beside it: a Monte Carlo estimate divides by it, and the tests
// hold each warp's samples against it (tests/support/chi_square_testing.hpp).
//
// Directions are given in the warp's own frame, its axis +z; the
// orthonormal basis of an axis turns them into the world's
// (fromLocal).
#pragma once

#include "core/math.hpp"

namespace rise {

// Two unit vectors that complete `axis` (unit) to a right-handed
// orthonormal basis.
void orthonormalBasis(const Vec3& axis, Vec3& u, Vec3& v);

// `local`, a direction whose +z is `axis` (unit), in the world.
Vec3 fromLocal(const Vec3& local, const Vec3& axis);

// The unit square onto the unit disk, strata apart and areas equal (Shirley
// and Chiu, "A low distortion map between disk and square", 1997); the
// square's centre to the disk's. Uniform: the density is 1 / pi.
Vec2 squareToDisk(const Vec2& u);
inline constexpr float kDiskDensity = 1.0f / kPi;

// Uniform over the unit sphere's directions: 1 / (4 pi) a steradian.
Vec3 squareToUniformSphere(const Vec2& u);
inline constexpr float kUniformSphereDensity = 1.0f / (4.0f * kPi);

// Uniform over the hemisphere about +z: 1 / (2 pi) a steradian.
Vec3 squareToUniformHemisphere(const Vec2& u);
inline constexpr float kUniformHemisphereDensity = 1.0f / (2.0f * kPi);

// Cosine-weighted over the hemisphere about +z (Malley's method: the disk
// lifted onto the hemisphere), as a diffuse surface scatters light: the
// density is cos(theta) / pi, 0 below the horizon.
Vec3 squareToCosineHemisphere(const Vec2& u);
float cosineHemisphereDensity(const Vec3& direction);

// Uniform over the cone about +z whose half-angle has the cosine
// `cosineOfHalfAngle` (in [-1, 1)), as the directions towards a sphere seen
// from outside it: 1 / (2 pi (1 - cosine)) a steradian inside, 0 outside.
Vec3 squareToUniformCone(const Vec2& u, float cosineOfHalfAngle);
float uniformConeDensity(const Vec3& direction, float cosineOfHalfAngle);

// The lobe of Phong's highlight about +z, cos^n(theta) normalised over the
// hemisphere, as the modified Phong BRDF (Lafortune and Willems 1994) is
// sampled: the density is (n + 1) / (2 pi) cos^n(theta), 0 below the
// horizon.
Vec3 squareToPhongLobe(const Vec2& u, float exponent);
float phongLobeDensity(const Vec3& direction, float exponent);

}  // namespace rise
