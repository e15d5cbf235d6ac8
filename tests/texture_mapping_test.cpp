// Projected texture mappings (scene/projected_mapping.hpp): each puts a known
// place of the texture at a known place of the object, computed in the
// object's own space so that the texture moves with it; the tessellations
// carry the same coordinates without smearing the texture across the seam;
// the ray tracer and the visible-surface algorithms draw it at the same
// place; and the scene file's `mapping` key, with its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "io/image_io.hpp"
#include "io/scene_error.hpp"
#include "io/scene_file.hpp"
#include "scene/scene.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/mapped_shape.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/textures/mesh_mapping.hpp"
#include "scene/textures/surface_mapping.hpp"
#include "support/raster_testing.hpp"
#include "support/shape_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

using shape_testing::expectTangentsMatchTheMapping;
using shape_testing::expectUv;
using shape_testing::intersect;
using shape_testing::uSpan;
using shape_testing::uvSeenAlong;

constexpr float kTolerance = 1e-4f;

// The fraction of a turn around y from +x towards -z (the u of a sphere)
// and the latitude from the south pole (its v), of a direction.
Vec2 longitudeAndLatitude(const Vec3& direction) {
  const float turn = std::atan2(-direction.z, direction.x) / (2.0f * kPi);
  const float latitude = std::asin(direction.y / glm::length(direction));
  return {turn < 0.0f ? turn + 1.0f : turn, 0.5f + latitude / kPi};
}

std::unique_ptr<Shape> mapped(std::unique_ptr<Shape> shape, Projection projection,
                              const Vec3& axis = Vec3(0, 1, 0)) {
  return std::make_unique<MappedShape>(std::move(shape), Mapping{projection, axis});
}

TEST(ProjectedMapping, SphericalIsTheLongitudeAndLatitudeFromTheBoxsCentre) {
  // The box's centre is (1, 1, 1).
  const auto box = mapped(std::make_unique<Box>(Vec3(0.0f), Vec3(2.0f), 0), Projection::Spherical);
  expectUv(uvSeenAlong(*box, Vec3(1.5f, 1.5f, -5), Vec3(0, 0, 1)),
           longitudeAndLatitude(Vec3(0.5f, 0.5f, -1.0f)));
  expectUv(uvSeenAlong(*box, Vec3(1.0f, 9.0f, 1.5f), Vec3(0, -1, 0)),
           longitudeAndLatitude(Vec3(0.0f, 1.0f, 0.5f)));
  expectUv(uvSeenAlong(*box, Vec3(-5, 0.25f, 0.5f), Vec3(1, 0, 0)),
           longitudeAndLatitude(Vec3(-1.0f, -0.75f, -0.5f)));
}

TEST(ProjectedMapping, SphericalOnASphereIsTheSpheresOwnMapping) {
  const Sphere sphere(Vec3(1, 2, 3), 2.0f, 0);
  const auto mappedSphere =
      mapped(std::make_unique<Sphere>(Vec3(1, 2, 3), 2.0f, 0), Projection::Spherical);
  for (const Vec3& direction : {Vec3(0, 0, 1), Vec3(-1, 0.3f, 0.2f), Vec3(0.4f, -1, -0.3f)}) {
    const Vec3 origin = Vec3(1, 2, 3) - 5.0f * direction + Vec3(0.3f, 0.2f, 0.1f);
    expectUv(uvSeenAlong(*mappedSphere, origin, direction), uvSeenAlong(sphere, origin, direction));
  }
}

TEST(ProjectedMapping, CylindricalTurnsAroundTheAxisAndRisesAlongTheBox) {
  // The box's centre is (0, 2, 0); it rises from y = 0 to 4.
  const auto box =
      mapped(std::make_unique<Box>(Vec3(-1, 0, -1), Vec3(1, 4, 1), 0), Projection::Cylindrical);
  expectUv(uvSeenAlong(*box, Vec3(0.5f, 1, -5), Vec3(0, 0, 1)),
           {longitudeAndLatitude(Vec3(0.5f, 0, -1)).x, 0.25f});
  expectUv(uvSeenAlong(*box, Vec3(-5, 3.5f, 0.25f), Vec3(1, 0, 0)),
           {longitudeAndLatitude(Vec3(-1, 0, 0.25f)).x, 0.875f});
  // About z: v from the back of the box (z = -1) to its front, and a
  // quarter turn counter-clockwise, seen from the axis's tip, from +x to +y.
  const auto turned = mapped(std::make_unique<Box>(Vec3(-1, 0, -1), Vec3(1, 4, 1), 0),
                             Projection::Cylindrical, Vec3(0, 0, 1));
  const Vec2 towardsX = uvSeenAlong(*turned, Vec3(5, 2, 0.5f), Vec3(-1, 0, 0));
  const Vec2 towardsY = uvSeenAlong(*turned, Vec3(0, 9, 0.5f), Vec3(0, -1, 0));
  EXPECT_NEAR(towardsX.y, 0.75f, kTolerance);
  EXPECT_NEAR(std::fmod(towardsY.x - towardsX.x + 1.0f, 1.0f), 0.25f, kTolerance);
}

TEST(ProjectedMapping, PlanarProjectsAlongZOntoTheBoxSeenFromTheFront) {
  // The sphere's box is [-1, 1]^3; seen from -z, u grows to the right (-x).
  const auto sphere = mapped(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, 0), Projection::Planar);
  expectUv(uvSeenAlong(*sphere, Vec3(0.5f, 0.25f, -5), Vec3(0, 0, 1)), {0.25f, 0.625f});
  // Through to the back, the same coordinates.
  expectUv(uvSeenAlong(*sphere, Vec3(0.5f, 0.25f, 5), Vec3(0, 0, -1)), {0.25f, 0.625f});
}

TEST(ProjectedMapping, BoxProjectsFromTheFaceTheSurfaceFacesMost) {
  const auto sphere = mapped(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, 0), Projection::Box);
  // Facing +x: seen from +x, u grows to the right (-z), v up.
  expectUv(uvSeenAlong(*sphere, Vec3(5, 0.3f, 0.2f), Vec3(-1, 0, 0)), {0.4f, 0.65f});
  // Facing +y: u along x, v along -z.
  expectUv(uvSeenAlong(*sphere, Vec3(0.2f, 5, 0.3f), Vec3(0, -1, 0)), {0.6f, 0.35f});
  // On a box, the box's own mapping.
  const Box box(Vec3(0.0f), Vec3(2.0f, 1.0f, 4.0f), 0);
  const auto mappedBox =
      mapped(std::make_unique<Box>(Vec3(0.0f), Vec3(2.0f, 1.0f, 4.0f), 0), Projection::Box);
  for (const Ray& ray :
       {Ray{Vec3(0.5f, 0.75f, -5), Vec3(0, 0, 1)}, Ray{Vec3(7, 0.25f, 1), Vec3(-1, 0, 0)},
        Ray{Vec3(1.5f, 3, 1), Vec3(0, -1, 0)}})
    expectUv(uvSeenAlong(*mappedBox, ray.origin, ray.direction),
             uvSeenAlong(box, ray.origin, ray.direction));
}

TEST(ProjectedMapping, TangentsAreTheDerivativesOfTheMappingAlongTheSurface) {
  for (const Projection projection :
       {Projection::Spherical, Projection::Cylindrical, Projection::Planar, Projection::Box}) {
    SCOPED_TRACE(static_cast<int>(projection));
    expectTangentsMatchTheMapping(
        *mapped(std::make_unique<Box>(Vec3(0.0f), Vec3(2, 3, 2), 0), projection),
        Vec3(1.3f, 1.8f, -5), Vec3(0, 0, 1));
    expectTangentsMatchTheMapping(
        *mapped(std::make_unique<Sphere>(Vec3(0.0f), 1.0f, 0), projection), Vec3(0.3f, 0.4f, -5),
        glm::normalize(Vec3(0.1f, 0, 1)));
  }
}

Tessellation tessellationOf(const Shape& shape) {
  Tessellation out;
  TessellationSettings settings;
  settings.level = 4;
  shape.tessellate(settings, out);
  return out;
}

TEST(ProjectedMapping, TessellationHasTheRayTracersCoordinatesAtItsVertices) {
  const auto box = mapped(std::make_unique<Box>(Vec3(-1.0f), Vec3(1.0f), 0), Projection::Spherical);
  const Tessellation tessellation = tessellationOf(*box);
  for (const SurfaceVertex& vertex : tessellation.vertices) {
    // Away from the box's edges, where a ray along the normal finds the face.
    const Vec3 out = glm::abs(vertex.position);
    if ((out.x > 0.95f) + (out.y > 0.95f) + (out.z > 0.95f) > 1) continue;
    const auto hit = intersect(*box, Ray{vertex.position + vertex.normal, -vertex.normal});
    ASSERT_TRUE(hit.found);
    const float uDifference = std::abs(hit.surface.uv.x - vertex.uv.x);
    const bool onTheAxis = std::abs(vertex.position.x) + std::abs(vertex.position.z) < 1e-4f;
    if (!onTheAxis) {
      EXPECT_NEAR(std::min(uDifference, std::abs(uDifference - 1.0f)), 0.0f, 1e-4f);
    }
    EXPECT_NEAR(hit.surface.uv.y, vertex.uv.y, 1e-4f);
  }
}

// The triangles are the shape's own; the projection rides along, placed
// with them, for the coordinates at every point between the corners.
TEST(ProjectedMapping, TessellationCarriesTheProjectionWhereverItIsPlaced) {
  const Cylinder cylinder(Vec3(0.0f), Vec3(0, 1, 0), 0.5f, 4.0f, 0);
  TransformSpec placement;
  placement.rotateDegrees = Vec3(0.0f, 30.0f, 10.0f);
  placement.translate = Vec3(1.0f, 2.0f, 3.0f);
  const TransformedShape placed(
      mapped(std::make_unique<Cylinder>(cylinder), Projection::Cylindrical),
      worldFromObject(placement));
  const Tessellation tessellation = tessellationOf(placed);
  EXPECT_EQ(tessellation.triangles.size(), tessellationOf(cylinder).triangles.size());
  ASSERT_NE(tessellation.projection, nullptr);
  EXPECT_TRUE(tessellation.projectionPlacement == worldFromObject(placement));
  EXPECT_EQ(tessellationOf(cylinder).projection, nullptr);
}

// A cube of eight shared corners, its faces wound counter-clockwise seen
// from outside.
MeshGeometry cube() {
  MeshGeometry mesh;
  for (int corner = 0; corner < 8; ++corner)
    mesh.positions.push_back(Bounds3{Vec3(-1.0f), Vec3(1.0f)}.corner(corner));
  // Corner k has x from bit 0, y from bit 1, z from bit 2.
  for (const std::array<int, 4> face :
       {std::array{0, 2, 3, 1}, std::array{4, 5, 7, 6}, std::array{0, 4, 6, 2},
        std::array{1, 3, 7, 5}, std::array{2, 6, 7, 3}, std::array{0, 1, 5, 4}}) {
    mesh.triangles.push_back({face[0], face[1], face[2]});
    mesh.triangles.push_back({face[0], face[2], face[3]});
  }
  return mesh;
}

TEST(MeshMapping, SplitsEachCornerOfACubeIntoOneVertexPerFace) {
  std::array poses{cube(), cube()};
  for (Vec3& position : poses[1].positions) position += Vec3(5, 0, 0);
  applyMapping(Mapping{Projection::Box}, poses);
  // A corner keeps one vertex for the faces that give it the same
  // coordinates, and gets another for each that does not.
  ASSERT_GT(poses[0].positions.size(), 8u);
  ASSERT_EQ(poses[0].uvs.size(), poses[0].positions.size());
  const Bounds3 box{Vec3(-1.0f), Vec3(1.0f)};
  for (const auto& triangle : poses[0].triangles) {
    const Vec3 face = cubeFaceFacing(
        glm::cross(poses[0].positions[triangle[1]] - poses[0].positions[triangle[0]],
                   poses[0].positions[triangle[2]] - poses[0].positions[triangle[0]]));
    for (int corner : triangle)
      expectUv(poses[0].uvs[corner],
               cubeFaceUv(poses[0].positions[corner], face, box.min, box.max));
  }
  // The later pose keeps the first's coordinates and triangles, moved.
  EXPECT_EQ(poses[1].uvs, poses[0].uvs);
  EXPECT_EQ(poses[1].triangles, poses[0].triangles);
  for (std::size_t vertex = 0; vertex < poses[0].positions.size(); ++vertex)
    EXPECT_EQ(poses[1].positions[vertex], poses[0].positions[vertex] + Vec3(5, 0, 0));
}

TEST(TextureExamples, LoadWithTheirMapsAndMappings) {
  const std::filesystem::path examples = std::filesystem::path(RISE_SOURCE_DIR) / "examples";
  const Scene globe = loadSceneFile(examples / "globe.yaml");
  ASSERT_EQ(globe.shapes.size(), 7u);
  EXPECT_TRUE(globe.materials[0].ksTexture);
  // The cube mapped spherically: its +y face's middle is the north pole.
  const Bounds3 cube = globe.shapes[3]->bounds();
  const Vec3 top(cube.centre().x, cube.max.y + 1.0f, cube.centre().z);
  EXPECT_NEAR(uvSeenAlong(*globe.shapes[3], top, Vec3(0, -1, 0)).y, 1.0f, kTolerance);
  EXPECT_TRUE(loadSceneFile(examples / "normal-map.yaml").materials[2].normalMap);
  EXPECT_EQ(loadSceneFile(examples / "textures.yaml").shapes.size(), 5u);
}

std::string errorLoading(const std::string& object) {
  try {
    loadScene(
        "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nmaterials: {m: {}}\nobjects:\n"
        "  - " +
            object + "\n",
        "test.yaml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "no error";
}

TEST(MappingSceneFile, NamesAnUnknownMappingAndTheAcceptedOnes) {
  EXPECT_EQ(errorLoading("box: {min: [0, 0, 0], max: [1, 1, 1], material: m, mapping: cubic}"),
            "test.yaml:4:65: 'mapping' in box is 'cubic'; expected one of: uv, spherical, "
            "cylindrical, planar, box");
  EXPECT_EQ(errorLoading("sphere: {center: [0, 0, 0], radius: 1, material: m, mapping: spherica}"),
            "test.yaml:4:66: 'mapping' in sphere is 'spherica'; did you mean 'spherical'?");
  EXPECT_EQ(errorLoading("mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 2]], "
                         "material: m, mapping: [uv]}"),
            "test.yaml:4:99: 'mapping' in mesh is ['uv']; expected a name");
}

TEST(MappingSceneFile, TakesAnAxisOnlyForTheTurningMappings) {
  EXPECT_EQ(errorLoading("box: {min: [0, 0, 0], max: [1, 1, 1], material: m, mapping: {planar: "
                         "{axis: [0, 0, 1]}}}"),
            "test.yaml:4:66: the planar mapping takes no axis; expected 'mapping: planar', or an "
            "axis for spherical or cylindrical");
  EXPECT_EQ(errorLoading("box: {min: [0, 0, 0], max: [1, 1, 1], material: m, mapping: {cylindric: "
                         "{axis: [0, 0, 1]}}}"),
            "test.yaml:4:66: unknown mapping 'cylindric' in 'mapping' in box; did you mean "
            "'cylindrical'?");
  EXPECT_EQ(errorLoading("box: {min: [0, 0, 0], max: [1, 1, 1], material: m, mapping: "
                         "{cylindrical: {axes: [0, 0, 1]}}}"),
            "test.yaml:4:80: unknown key 'axes' in the cylindrical mapping; did you mean 'axis'?");
  EXPECT_EQ(errorLoading("box: {min: [0, 0, 0], max: [1, 1, 1], material: m, mapping: "
                         "{cylindrical: {axis: [0, 0, 0]}}}"),
            "test.yaml:4:86: 'axis' in the cylindrical mapping is [0, 0, 0]; expected a "
            "direction, not the zero vector");
}

TEST(MappingSceneFile, APlaneTakesNoMapping) {
  EXPECT_EQ(errorLoading("plane: {point: [0, 0, 0], normal: [0, 1, 0], material: m, mapping: box}"),
            "test.yaml:4:63: unknown key 'mapping' in plane; expected one of: point, normal, "
            "material, transform, motion");
}

TEST(MappingSceneFile, UvIsTheShapesOwnMapping) {
  const Scene scene = loadScene(
      "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nmaterials: {m: {}}\nobjects:\n"
      "  - sphere: {center: [0, 0, 0], radius: 1, material: m, mapping: uv}\n"
      "  - sphere: {center: [0, 0, 0], radius: 1, material: m, mapping: {spherical: {axis: [0, 0, "
      "1]}}}\n",
      "test.yaml");
  const Sphere sphere(Vec3(0.0f), 1.0f, 0);
  expectUv(uvSeenAlong(*scene.shapes[0], Vec3(0.3f, 0.2f, -5), Vec3(0, 0, 1)),
           uvSeenAlong(sphere, Vec3(0.3f, 0.2f, -5), Vec3(0, 0, 1)));
  // About z, the point facing -z is the south pole.
  EXPECT_NEAR(uvSeenAlong(*scene.shapes[1], Vec3(0, 0, -5), Vec3(0, 0, 1)).y, 0.0f, kTolerance);
}

}  // namespace
}  // namespace rise
