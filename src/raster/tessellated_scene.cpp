#include "raster/tessellated_scene.hpp"

namespace rise {
namespace {

bool contains(const Bounds3& box, const Vec3& point) {
  return glm::all(glm::greaterThanEqual(point, box.min)) &&
         glm::all(glm::lessThanEqual(point, box.max));
}

}  // namespace

void PlacedProjection::mapOnto(SurfacePoint& surface) const {
  SurfacePoint mapped = placement_.toObject(surface);
  mapping_->mapOnto(mapped);
  const SurfacePoint world = placement_.toWorld(mapped);
  surface.uv = world.uv;
  surface.dpdu = world.dpdu;
  surface.dpdv = world.dpdv;
}

Vec2 PlacedProjection::stepTo(const SurfacePoint& surface, const Vec3& position) const {
  SurfacePoint there = surface;
  there.position = position;
  const SurfacePoint object = placement_.toObject(there);
  return mapping_->step(surface.uv, mapping_->uvAt(object.position, object.normal));
}

TessellatedScene tessellateScene(const Scene& scene, const TessellationSettings& settings) {
  TessellatedScene tessellated;
  for (std::size_t shape = 0; shape < scene.shapes.size(); ++shape) {
    Tessellation part;
    scene.shapes[shape]->tessellate(settings, part);
    // An eye inside a solid's box may be inside the solid, where its back
    // faces are the ones in view.
    const bool cullable =
        part.enclosesSolid && !contains(scene.shapes[shape]->bounds(), settings.viewpoint);
    tessellated.projections.push_back(
        part.projection ? std::optional<PlacedProjection>(std::in_place, *part.projection,
                                                          part.projectionPlacement)
                        : std::nullopt);
    // A shape that wraps a mesh into one primitive (a moving mesh) is
    // tested whole.
    const bool onePrimitive = scene.shapes[shape]->primitiveCount() == 1;
    const int firstVertex = static_cast<int>(tessellated.vertices.size());
    tessellated.vertices.insert(tessellated.vertices.end(), part.vertices.begin(),
                                part.vertices.end());
    tessellated.faces.reserve(tessellated.faces.size() + part.triangles.size());
    for (std::size_t triangle = 0; triangle < part.triangles.size(); ++triangle) {
      const auto& [a, b, c] = part.triangles[triangle];
      tessellated.faces.push_back({{firstVertex + a, firstVertex + b, firstVertex + c},
                                   static_cast<int>(shape),
                                   onePrimitive ? 0 : part.primitives[triangle],
                                   scene.shapes[shape]->material(),
                                   cullable});
    }
  }
  return tessellated;
}

}  // namespace rise
