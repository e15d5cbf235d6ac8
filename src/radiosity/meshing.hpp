// The scene cut for radiosity as the settings ask: its surfaces tessellated,
// cut into elements and gathered into patches of the patch size, or, without
// one, of a size that keeps the patches few enough to solve in seconds.
#pragma once

#include "radiosity/patches.hpp"
#include "render/render_settings.hpp"

namespace rise {

struct RadiosityMesh {
  ElementMesh elementMesh;
  PatchMesh patchMesh;
  float patchSide = 0.0f;
};

RadiosityMesh meshForRadiosity(const Scene& scene, const RenderSettings& settings);

struct RadiosityMeshSize {
  std::uint64_t elements = 0;
  std::uint64_t patches = 0;
};

// The size of the mesh meshForRadiosity would make, known without making it.
RadiosityMeshSize radiosityMeshSize(const Scene& scene, const RenderSettings& settings);

// The size of what the scene holds that has bounds (a plane has none); 1
// for a scene of none.
float sceneSize(const Scene& scene);

}  // namespace rise
