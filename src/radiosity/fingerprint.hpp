// What radiosity's solution depends on, as one number: two scenes with the
// same fingerprint have the same solution, whatever their cameras, and a
// front end that moves the camera alone (the studio orbiting a lit room)
// draws the solution again without solving it.
#pragma once

#include <cstdint>

#include "radiosity/meshing.hpp"

namespace rise {

// Of the mesh before subdivision (its vertices and faces, which hold the
// shapes' places and materials), the materials' colours, the lights (by what
// they give at points around the mesh) and radiosity's settings.
std::uint64_t fingerprintOf(const Scene& scene, const RadiosityMesh& mesh,
                            const RadiositySettings& settings);

}  // namespace rise
