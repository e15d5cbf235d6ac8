// Ken Perlin's gradient noise as he improved it: "Improving Noise",
// SIGGRAPH 2002. Space is cut into unit cubes; each lattice point has a
// pseudo-random gradient, one of the twelve directions to the edges' middles
// of a cube, picked by hashing the point through a permutation of 0..255;
// the noise at a point blends the dot products of the eight corners'
// gradients with the offsets to the point, by the quintic 6t^5 - 15t^4 + 10t^3,
// whose first and second derivatives vanish at the lattice, so that the
// noise has no visible grid.
#pragma once

#include "core/math.hpp"

namespace rise {

// The noise at a point, in about [-1, 1], zero at every lattice point and
// repeating every 256 units along each axis.
float perlinNoise(const Vec3& point);

// Perlin's turbulence: the sum of |noise| over `octaves` octaves, each at
// twice the frequency and half the amplitude of the one before ("An Image
// Synthesizer", SIGGRAPH 1985).
float turbulence(const Vec3& point, int octaves);

}  // namespace rise
