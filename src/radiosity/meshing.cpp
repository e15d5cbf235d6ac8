#include "radiosity/meshing.hpp"

#include <algorithm>

#include "raster/visible_surface_renderer.hpp"

namespace rise {

float sceneSize(const Scene& scene) {
  Bounds3 bounds;
  for (const std::unique_ptr<Shape>& shape : scene.shapes)
    if (const Bounds3 shapeBounds = shape->bounds(); shapeBounds.isFinite())
      bounds.grow(shapeBounds);
  const float size = bounds.isEmpty() ? 0.0f : glm::length(bounds.extent());
  return size > 0.0f ? size : 1.0f;
}

namespace {

// The scene's triangles, a plane's square at most four times the size of
// the rest: the light of patches far beyond would be solved for nothing.
TessellatedScene sceneTriangles(const Scene& scene, const RenderSettings& settings) {
  RenderSettings near = settings;
  near.planeSize = std::min(settings.planeSize, 4.0f * sceneSize(scene));
  return tessellateForRaster(scene, near);
}

// Without a patch size, a 24th of the scene's size, made larger until the
// patches are at most kMostPatchesByDefault.
constexpr std::uint64_t kMostPatchesByDefault = 3000;

float patchSideOf(const Scene& scene, const RenderSettings& settings,
                  const TessellatedScene& triangles) {
  if (settings.radiosity.patchSize > 0.0f) return settings.radiosity.patchSize;
  const float size = sceneSize(scene);
  float side = size / 24.0f;
  while (side < size && patchCount(triangles, side) > kMostPatchesByDefault) side *= 1.25f;
  return side;
}

}  // namespace

RadiosityMesh meshForRadiosity(const Scene& scene, const RenderSettings& settings) {
  const TessellatedScene triangles = sceneTriangles(scene, settings);
  const float side = patchSideOf(scene, settings, triangles);
  RadiosityMesh mesh{meshElements(triangles, side), {}, side};
  mesh.patchMesh = gatherPatches(mesh.elementMesh, side);
  return mesh;
}

RadiosityMeshSize radiosityMeshSize(const Scene& scene, const RenderSettings& settings) {
  const TessellatedScene triangles = sceneTriangles(scene, settings);
  const float side = patchSideOf(scene, settings, triangles);
  return {elementCount(triangles, side), patchCount(triangles, side)};
}

}  // namespace rise
