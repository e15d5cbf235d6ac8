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

namespace {

constexpr int kFacesPerRange = 16384;

// The faces of one shape's triangles, in their order, from `firstFace` on;
// its vertices start at `firstVertex`.
void addFaces(const Scene& scene, int shape, const Tessellation& part, const Vec3& viewpoint,
              int firstVertex, std::size_t firstFace, const Workers& workers,
              TessellatedScene& tessellated) {
  // An eye inside a solid's box may be inside the solid, where its back
  // faces are the ones in view.
  const bool cullable = part.enclosesSolid && !contains(scene.shapes[shape]->bounds(), viewpoint);
  // A shape that wraps a mesh into one primitive (a moving mesh) is tested
  // whole.
  const bool onePrimitive = scene.shapes[shape]->primitiveCount() == 1;
  const int material = scene.shapes[shape]->material();
  workers.forEachRange(static_cast<int>(part.triangles.size()), kFacesPerRange,
                       [&](int, int begin, int end) {
                         for (int triangle = begin; triangle < end; ++triangle) {
                           const auto& [a, b, c] = part.triangles[triangle];
                           tessellated.faces[firstFace + triangle] = {
                               {firstVertex + a, firstVertex + b, firstVertex + c},
                               shape,
                               onePrimitive ? 0 : part.primitives[triangle],
                               material,
                               cullable};
                         }
                       });
}

}  // namespace

// Every shape is cut into triangles before any is gathered, so that the
// scene's arrays are made once, at their full size: growing them shape by
// shape would copy a large mesh's faces again for each shape after it.
TessellatedScene tessellateScene(const Scene& scene, const TessellationSettings& settings,
                                 const Workers& workers) {
  std::vector<Tessellation> parts(scene.shapes.size());
  std::size_t vertexCount = 0, faceCount = 0;
  for (std::size_t shape = 0; shape < scene.shapes.size(); ++shape) {
    scene.shapes[shape]->tessellate(settings, parts[shape]);
    vertexCount += parts[shape].vertices.size();
    faceCount += parts[shape].triangles.size();
  }
  TessellatedScene tessellated;
  tessellated.vertices.reserve(vertexCount);
  tessellated.faces.resize(faceCount);
  std::size_t firstFace = 0;
  for (std::size_t shape = 0; shape < parts.size(); ++shape) {
    Tessellation& part = parts[shape];
    tessellated.projections.push_back(
        part.projection ? std::optional<PlacedProjection>(std::in_place, *part.projection,
                                                          part.projectionPlacement)
                        : std::nullopt);
    const int firstVertex = static_cast<int>(tessellated.vertices.size());
    tessellated.vertices.insert(tessellated.vertices.end(), part.vertices.begin(),
                                part.vertices.end());
    addFaces(scene, static_cast<int>(shape), part, settings.viewpoint, firstVertex, firstFace,
             workers, tessellated);
    firstFace += part.triangles.size();
    part = Tessellation();  // its triangles are the scene's now
  }
  return tessellated;
}

}  // namespace rise
