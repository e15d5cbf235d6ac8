#include "io/shape_reader.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "core/text.hpp"
#include "io/mapping_reader.hpp"
#include "io/mesh_reader.hpp"
#include "scene/shapes/box.hpp"
#include "scene/shapes/cone.hpp"
#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/mapped_shape.hpp"
#include "scene/shapes/moving_shape.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/shapes/triangle.hpp"
#include "scene/transform.hpp"

namespace rise {

namespace {

// How close to a line three triangle corners may be (the sine of the angle
// between two edges) before the triangle has no area to hit.
constexpr float kCollinearSine = 1e-6f;

int readMaterialReference(const Field& field, const SceneMaterials& materials,
                          std::string_view shapeName) {
  const std::string name = readName(field);
  if (const std::optional<int> found = materials.find(name)) return *found;
  const std::string problem =
      "undefined material " + inQuotes(name) + " in " + std::string(shapeName);
  if (materials.empty()) failAt(field.mark, problem + "; the scene defines no materials");
  failAt(field.mark, problem + "; " + suggestAlternative(name, materials.names()));
}

Vec3 readScale(const Field& field) {
  if (!field.node.isSequence() && !field.node.isScalar())
    failExpected(field, "a number or a list of 3 numbers [x, y, z]");
  const Vec3 scale = field.node.isSequence() ? readVec3(field) : Vec3(readNumber(field));
  if (glm::any(glm::equal(scale, Vec3(0.0f))))
    failExpected(field, "a scale that is not 0 on any axis");
  return scale;
}

// A `transform`, or a `motion`: the placement at the shutter's close, its
// keys changing those of `start`, the placement at the shutter's open.
TransformSpec readPlacement(const Field& field, const std::string& name, TransformSpec start) {
  const CheckedMap map(field, name, {"scale", "rotate", "translate"});
  TransformSpec spec = start;
  readIfPresent(map, "scale", spec.scale, readScale);
  readIfPresent(map, "rotate", spec.rotateDegrees, readVec3);
  readIfPresent(map, "translate", spec.translate, readVec3);
  return spec;
}

// The points of a list, placed in the world.
std::vector<Vec3> readPlacedPoints(const Field& field, std::string_view expectation,
                                   std::size_t minPoints, std::size_t maxPoints,
                                   const Mat4& worldFromObject) {
  std::vector<Vec3> points = readPoints(field, expectation, minPoints, maxPoints);
  for (Vec3& point : points) point = Vec3(worldFromObject * glm::vec4(point, 1.0f));
  return points;
}

// Each shape reader builds its shape from its properties. Shapes made of
// vertices take the object's transform into them (but for a triangle or
// polygon with a mapping, which it wears in its own space); the others are
// built in their own space and wrapped in a TransformedShape. Files that a
// shape names are found from the scene file's folder.
using ShapeReader = std::unique_ptr<Shape> (*)(const CheckedMap& properties, int material,
                                               const Mat4& worldFromObject, SceneFiles& files);

std::unique_ptr<Shape> readPlane(const CheckedMap& plane, int material, const Mat4&, SceneFiles&) {
  const Vec3 point = readVec3(plane.required("point"));
  const Vec3 normal = readDirection(plane.required("normal"));
  return std::make_unique<Plane>(point, normal, material);
}

std::unique_ptr<Shape> readSphere(const CheckedMap& sphere, int material, const Mat4&,
                                  SceneFiles&) {
  const Vec3 center = readVec3(sphere.required("center"));
  const float radius = readPositive(sphere.required("radius"));
  return std::make_unique<Sphere>(center, radius, material);
}

std::unique_ptr<Shape> readBox(const CheckedMap& box, int material, const Mat4&, SceneFiles&) {
  const Field minField = box.required("min");
  const Field maxField = box.required("max");
  const Vec3 min = readVec3(minField);
  const Vec3 max = readVec3(maxField);
  if (!glm::all(glm::greaterThan(max, min)))
    failExpected(maxField,
                 "a corner greater than 'min' " + describe(minField.node) + " in x, y and z");
  return std::make_unique<Box>(min, max, material);
}

// Cylinders and cones: a base point, an axis, a radius and a height.
template <typename AxialShape>
std::unique_ptr<Shape> readAxialShape(const CheckedMap& shape, int material, const Mat4&,
                                      SceneFiles&) {
  const Vec3 base = readVec3(shape.required("base"));
  const Vec3 axis = readDirection(shape.required("axis"));
  const float radius = readPositive(shape.required("radius"));
  const float height = readPositive(shape.required("height"));
  return std::make_unique<AxialShape>(base, axis, radius, height, material);
}

std::unique_ptr<Shape> readTriangle(const CheckedMap& triangle, int material,
                                    const Mat4& worldFromObject, SceneFiles&) {
  const Field field = triangle.required("vertices");
  const std::vector<Vec3> v =
      readPlacedPoints(field, "a list of 3 points [x, y, z]", 3, 3, worldFromObject);
  const Vec3 edge1 = v[1] - v[0];
  const Vec3 edge2 = v[2] - v[0];
  if (glm::length(glm::cross(edge1, edge2)) <=
      kCollinearSine * glm::length(edge1) * glm::length(edge2))
    failAt(field.mark, field.name + " lie on one line; expected the corners of a triangle");
  return std::make_unique<Triangle>(std::array<Vec3, 3>{v[0], v[1], v[2]}, material);
}

std::unique_ptr<Shape> readPolygon(const CheckedMap& polygon, int material,
                                   const Mat4& worldFromObject, SceneFiles&) {
  const Field field = polygon.required("vertices");
  std::vector<Vec3> vertices =
      readPlacedPoints(field, "a list of 3 or more points [x, y, z]", 3, SIZE_MAX, worldFromObject);
  if (!isPlanarConvexPolygon(vertices))
    failAt(field.mark, field.name +
                           " are not the corners of a flat convex polygon; expected points in "
                           "one plane, in order around a convex outline");
  return std::make_unique<ConvexPolygon>(std::move(vertices), material);
}

struct ShapeKind {
  std::string name;
  std::vector<std::string> keys;
  bool takesTransformIntoVertices;
  ShapeReader read;
};

const std::vector<ShapeKind>& shapeKinds() {
  static const std::vector<ShapeKind> kinds{
      {"plane", {"point", "normal"}, false, readPlane},
      {"sphere", {"center", "radius", "mapping"}, false, readSphere},
      {"box", {"min", "max", "mapping"}, false, readBox},
      {"cylinder",
       {"base", "axis", "radius", "height", "mapping"},
       false,
       readAxialShape<Cylinder>},
      {"cone", {"base", "axis", "radius", "height", "mapping"}, false, readAxialShape<Cone>},
      {"triangle", {"vertices", "mapping"}, true, readTriangle},
      {"polygon", {"vertices", "mapping"}, true, readPolygon},
      {"mesh", {"vertices", "faces", "file", "frame", "frames", "mapping"}, true, readMesh},
  };
  return kinds;
}

}  // namespace

std::vector<std::unique_ptr<Shape>> readObject(const Field& item, SceneMaterials& materials,
                                               SceneFiles& files) {
  std::vector<std::string> kindNames;
  for (const ShapeKind& kind : shapeKinds()) kindNames.push_back(kind.name);
  const MapEntry entry = readKindAndProperties(item, "shape", kindNames);
  const ShapeKind& kind = *std::find_if(shapeKinds().begin(), shapeKinds().end(),
                                        [&](const ShapeKind& k) { return k.name == entry.key; });

  std::vector<std::string> keys = kind.keys;
  keys.insert(keys.end(), {"material", "transform", "motion"});
  const CheckedMap properties(makeField(entry.value, kind.name, entry.keyMark), kind.name, keys);
  const bool wearsFileMaterials =
      kind.name == "mesh" && properties.optional("file") && !properties.optional("material");
  std::optional<int> material;
  if (!wearsFileMaterials) {
    material = readMaterialReference(properties.required("material"), materials, kind.name);
    if (kind.name == "mesh") material = withMd2Skin(properties, *material, materials, files);
  }
  TransformSpec transform;
  if (const std::optional<Field> field = properties.optional("transform"))
    transform = readPlacement(*field, "the transform of " + kind.name, TransformSpec{});
  std::optional<TransformSpec> close;
  if (const std::optional<Field> field = properties.optional("motion"))
    close = readPlacement(*field, "the motion of " + kind.name, transform);
  const auto moving = [&](std::unique_ptr<Shape> shape) -> std::unique_ptr<Shape> {
    return std::make_unique<MovingShape>(std::move(shape), transform, *close);
  };

  std::vector<std::unique_ptr<Shape>> shapes;
  if (wearsFileMaterials) {
    shapes = readMeshInItsMaterials(properties, close ? Mat4(1.0f) : worldFromObject(transform),
                                    materials, files);
    if (close)
      for (std::unique_ptr<Shape>& shape : shapes) shape = moving(std::move(shape));
    return shapes;
  }
  // A mesh takes its mapping into its vertices as it loads (mapAndPlace);
  // another shape wears it in its own space, inside its placement.
  std::optional<Mapping> mapping;
  if (const std::optional<Field> field = properties.optional("mapping");
      field && kind.name != "mesh")
    mapping = readMapping(*field);
  const auto readInOwnSpace = [&] {
    std::unique_ptr<Shape> shape = kind.read(properties, *material, Mat4(1.0f), files);
    if (!mapping) return shape;
    return std::unique_ptr<Shape>(std::make_unique<MappedShape>(std::move(shape), *mapping));
  };
  const Mat4 toWorld = worldFromObject(transform);
  if (close)
    shapes.push_back(moving(readInOwnSpace()));
  else if (kind.takesTransformIntoVertices && !mapping)
    shapes.push_back(kind.read(properties, *material, toWorld, files));
  else if (transform.isIdentity())
    shapes.push_back(readInOwnSpace());
  else
    shapes.push_back(std::make_unique<TransformedShape>(readInOwnSpace(), toWorld));
  return shapes;
}

std::string describeObject(const Field& item) {
  return readMap(item, "an object", item.name).front().key + " at line " +
         std::to_string(item.mark.line + 1);
}

}  // namespace rise
