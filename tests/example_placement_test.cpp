// Where the examples' comments say things are, the viewer finds them. Each
// claim below is one an example's opening comment makes in words ("the red
// ball, on the right of the image"); the test looks through the example's
// camera, pixel by pixel, at which of its shapes is nearest, and holds the
// middle of each shape's pixels to the words. The camera of most examples
// looks along +z, which puts +x on the image's left: a comment that reads
// the coordinates instead of the image fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "io/scene_file.hpp"
#include "ray/scene_intersector.hpp"
#include "scene/camera.hpp"
#include "scene/scene.hpp"

namespace rise {
namespace {

constexpr int kWidth = 96;

// The middle of the pixels where a shape is the nearest, as fractions of the
// image's width and height from its top-left corner, in an image of the
// example's own shape.
struct Seen {
  float x = 0.0f, y = 0.0f;
  int pixels = 0;
};

std::vector<Seen> whereEachShapeIsSeen(const Scene& scene) {
  const int height = std::max(1, kWidth * scene.image.height / scene.image.width);
  const ViewFrame view(scene.camera, kWidth, height);
  const SceneIntersector intersector(scene, Accel::Bvh);
  std::vector<Seen> seen(scene.shapes.size());
  IntersectionCounters counters;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Ray ray = view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      Hit hit;
      if (!intersector.nearest(ray, 0.0f, hit, counters)) continue;
      const auto shape = std::find_if(scene.shapes.begin(), scene.shapes.end(),
                                      [&](const auto& s) { return s.get() == hit.shape; });
      if (shape == scene.shapes.end()) {
        ADD_FAILURE() << "a hit on a shape the scene does not list";
        continue;
      }
      Seen& where = seen[shape - scene.shapes.begin()];
      where.x += (static_cast<float>(x) + 0.5f) / static_cast<float>(kWidth);
      where.y += (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
      ++where.pixels;
    }
  for (Seen& where : seen)
    if (where.pixels > 0) {
      where.x /= static_cast<float>(where.pixels);
      where.y /= static_cast<float>(where.pixels);
    }
  return seen;
}

enum class Across { Left, Middle, Right };

struct Placement {
  int shape;  // its place in the example's `objects`, counting from 0
  Across across;
};

// What one example's comment says: where some shapes are across the image,
// rows of shapes from left to right, and pairs of which is higher in it.
struct Claims {
  std::string example;
  std::vector<Placement> placements;
  std::vector<std::vector<int>> leftToRight;
  std::vector<std::pair<int, int>> higherThan;
};

void PrintTo(const Claims& claims, std::ostream* out) { *out << claims.example; }

const std::vector<Claims>& everyClaim() {
  static const std::vector<Claims> claims = {
      {"checker-filtering.yaml", {}, {{0, 1, 2, 3, 4}}, {}},
      {"classic.yaml",
       {{1, Across::Middle},
        {2, Across::Right},
        {3, Across::Left},
        {4, Across::Right},
        {5, Across::Left},
        {8, Across::Middle}},
       {{7, 1, 6}},
       {{8, 1}}},
      {"depth-of-field.yaml", {{1, Across::Right}}, {{5, 4, 3, 2, 1}}, {}},
      {"globe.yaml", {}, {{1, 2, 3}, {4, 5, 6}}, {{1, 4}, {2, 5}, {3, 6}}},
      {"glossy-metal.yaml", {}, {{1, 2, 3, 4}}, {}},
      {"md2.yaml",
       {{1, Across::Middle}, {2, Across::Right}, {3, Across::Left}, {4, Across::Left}},
       {},
       {}},
      {"motion-blur.yaml",
       {{1, Across::Right}, {2, Across::Left}, {3, Across::Left}},
       {{3, 2, 1}},
       {{2, 1}, {2, 3}}},
      {"normal-map.yaml", {{0, Across::Right}, {1, Across::Left}, {2, Across::Left}}, {}, {}},
      {"obj.yaml", {{1, Across::Right}, {2, Across::Left}}, {}, {}},
      {"ply.yaml", {{1, Across::Right}, {2, Across::Left}}, {}, {}},
      {"soft-shadows.yaml", {}, {{3, 2, 1}}, {}},
      {"textures.yaml",
       {{1, Across::Middle}, {2, Across::Left}, {3, Across::Right}, {4, Across::Right}},
       {},
       {{3, 4}}},
  };
  return claims;
}

bool isWhere(const Seen& seen, Across across) {
  switch (across) {
    case Across::Left:
      return seen.x < 0.45f;
    case Across::Middle:
      return seen.x > 0.35f && seen.x < 0.65f;
    case Across::Right:
      return seen.x > 0.55f;
  }
  return false;
}

const char* nameOf(Across across) {
  return across == Across::Left ? "left" : across == Across::Middle ? "middle" : "right";
}

class ExampleComment : public testing::TestWithParam<Claims> {};

TEST_P(ExampleComment, PlacesWhatItNamesWhereTheViewerSeesIt) {
  const Claims& claims = GetParam();
  const Scene scene = loadSceneFile(std::string(RISE_SOURCE_DIR) + "/examples/" + claims.example);
  const std::vector<Seen> seen = whereEachShapeIsSeen(scene);
  const auto described = [&](int shape) {
    return "shape " + std::to_string(shape) + " seen around (" + std::to_string(seen[shape].x) +
           ", " + std::to_string(seen[shape].y) + ") over " + std::to_string(seen[shape].pixels) +
           " pixels";
  };
  for (const Placement& placement : claims.placements) {
    ASSERT_GT(seen[placement.shape].pixels, 0) << described(placement.shape);
    EXPECT_TRUE(isWhere(seen[placement.shape], placement.across))
        << described(placement.shape) << ", said to be on the " << nameOf(placement.across);
  }
  for (const std::vector<int>& row : claims.leftToRight)
    for (std::size_t i = 1; i < row.size(); ++i)
      EXPECT_LT(seen[row[i - 1]].x, seen[row[i]].x)
          << described(row[i - 1]) << " is said to be left of " << described(row[i]);
  for (const auto& [higher, lower] : claims.higherThan)
    EXPECT_LT(seen[higher].y, seen[lower].y)
        << described(higher) << " is said to be higher than " << described(lower);
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleComment, testing::ValuesIn(everyClaim()),
                         [](const testing::TestParamInfo<Claims>& info) {
                           std::string name = info.param.example.substr(
                               0, info.param.example.size() - std::string(".yaml").size());
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace rise
