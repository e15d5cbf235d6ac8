// The surfaces that give off light (a material's `emission`), as the path
// tracer samples them for its shadow rays (next-event estimation): a point
// chosen on one of them, with the density it was chosen with per unit of
// area. An emitter is chosen by its power, its luminance times its area, and
// a point on it uniformly by area; the density of a point is then its
// luminance over all the emitters' power, wherever it lies. Spheres are
// sampled over their whole surface, and surfaces whose triangles are
// themselves (polygons, boxes, meshes standing still) triangle by triangle;
// any other shape that emits is found only by the paths that happen to hit
// it, and its density here is zero.
#pragma once

#include <optional>
#include <unordered_set>
#include <vector>

#include "core/color.hpp"
#include "core/math.hpp"
#include "scene/scene.hpp"

namespace rise {

struct EmitterPoint {
  Vec3 position{0.0f};
  Vec3 normal{0.0f};  // unit; emitters give off light on both sides
  Color radiance{0.0f};
  float areaDensity = 0.0f;  // per unit of area
};

class Emitters {
 public:
  explicit Emitters(const Scene& scene);

  bool empty() const { return parts_.empty(); }
  int count() const { return static_cast<int>(parts_.size()); }

  // A point chosen by `choice` (in [0, 1)) and `u` (in the unit square).
  EmitterPoint sample(float choice, const Vec2& u) const;
  // The density per unit of area with which sample() chooses a point of the
  // shape `shape`, whose material's radiance is `radiance`: zero for a shape
  // it never chooses.
  float areaDensity(const Shape& shape, const Color& radiance) const;

 private:
  // A triangle, or a sphere (centre in corners[0], radius in radius).
  struct Part {
    std::array<Vec3, 3> corners;
    float radius = 0.0f;
    float area = 0.0f;
    Color radiance{0.0f};
  };
  void addShape(const Shape& shape, const Color& radiance);

  std::vector<Part> parts_;
  std::vector<float> cumulativePower_;  // of the parts, in order, the last the total
  std::unordered_set<const Shape*> sampled_;
};

}  // namespace rise
