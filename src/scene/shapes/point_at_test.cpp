// A shape's point alone (Shape::pointAt), for a material that reads no
// texture coordinates: the very point and normals surfaceAt finds, for the
// shapes that find it apart and for those that wrap them.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "scene/shapes/box.hpp"
#include "scene/shapes/mapped_shape.hpp"
#include "scene/shapes/moving_shape.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/transform.hpp"
#include "support/shape_testing.hpp"

namespace rise {
namespace {

struct NamedShape {
  std::string name;
  std::unique_ptr<Shape> shape;
};

std::vector<NamedShape> shapes() {
  const auto sphere = [] { return std::make_unique<Sphere>(Vec3(0.3f, -0.2f, 0.1f), 1.3f, 0); };
  const TransformSpec turned{.scale = Vec3(1.5f, 0.7f, 1.0f),
                             .rotateDegrees = Vec3(20.0f, 35.0f, 5.0f),
                             .translate = Vec3(0.1f, 0.2f, -0.2f)};
  std::vector<NamedShape> all;
  all.push_back({"sphere", sphere()});
  all.push_back(
      {"placed sphere", std::make_unique<TransformedShape>(sphere(), worldFromObject(turned))});
  all.push_back(
      {"moving sphere", std::make_unique<MovingShape>(sphere(), TransformSpec{}, turned)});
  all.push_back({"mapped sphere", std::make_unique<MappedShape>(sphere(), Mapping{})});
  all.push_back({"box", std::make_unique<Box>(Vec3(-1.0f), Vec3(1.0f, 0.5f, 0.8f), 0)});
  return all;
}

TEST(PointAt, FindsTheSurfacePointsPointAndNormals) {
  for (const auto& [name, shape] : shapes()) {
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
      const float a = 0.0157f * static_cast<float>(i);
      Ray ray{Vec3(4.0f * std::cos(a), 0.5f * std::sin(3.0f * a), 4.0f * std::sin(a)),
              Vec3(-std::cos(a), 0.1f * std::cos(5.0f * a), -std::sin(a))};
      ray.time = 0.0025f * static_cast<float>(i);
      const auto result = shape_testing::intersect(*shape, ray);
      if (!result.found) continue;
      ++hits;
      const SurfacePoint full = shape->surfaceAt(ray, result.hit);
      const SurfacePoint point = shape->pointAt(ray, result.hit);
      EXPECT_EQ(point.position, full.position) << name;
      EXPECT_EQ(point.normal, full.normal) << name;
      EXPECT_EQ(point.shadingNormal, full.shadingNormal) << name;
    }
    EXPECT_GT(hits, 300) << name;
  }
}

}  // namespace
}  // namespace rise
