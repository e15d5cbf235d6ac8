// The tree of rays behind one sample of a pixel, as a ray tracer records it
// for a student to open: every ray with its kind, where it went and what it
// hit, every light's shadow verdict, the Phong terms, the weights on the way
// back to the eye, and what each ray added to the pixel. The contributions of
// all its rays add up to the sample's colour.
#pragma once

#include <optional>
#include <vector>

#include "core/color.hpp"
#include "core/math.hpp"

namespace rise {

enum class RayKind { Primary, Shadow, Reflection, Refraction };

const char* toString(RayKind kind);  // "primary", "shadow", ...

// What a path tracer records at a hit: the light the surface emits as
// counted (times the weight multiple importance sampling gave it against a
// shadow ray), the density of the direction the path went on in per
// steradian (for a mirror or glass, the chance of its lobe), and Russian
// roulette's verdict.
struct PathVertex {
  Color emitted{0.0f};
  float emittedWeight = 1.0f;
  float density = 0.0f;
  bool singular = false;
  float survival = 1.0f;
  bool endedByRoulette = false;
};

// A ray of the tree. `weight` is what the colour it brings back is
// multiplied by on its way to the pixel: 1 for the primary ray, times the
// material's reflection for a mirror ray, times its transmission and colour
// for a refracted one, and for a path the product of f cos / p on the way
// (roulette included). `contribution` is what the ray itself adds to the
// pixel (weight times its ambient term or the background; for a shadow ray,
// the parent's weight times the light's Phong terms that got through);
// `color` is everything it brings back, its children's included, before its
// weight.
struct RayNode {
  RayKind kind = RayKind::Primary;
  int depth = 1;  // the primary ray is 1; a shadow ray has its surface's depth
  Vec3 origin{0.0f};
  Vec3 direction{0.0f};
  Color weight{1.0f};
  Color contribution{0.0f};
  Color color{0.0f};
  int parent = -1;
  std::vector<int> children;

  // What the ray met: for a shadow ray, the light it aims at.
  bool hit = false;
  int object = -1;  // the shape's index in the scene, -1 for none
  float distance = 0.0f;
  Vec3 point{0.0f};
  Vec3 normal{0.0f};
  Vec2 uv{0.0f};
  Color ambient{0.0f};  // the Phong ambient term at the hit

  // Shadow rays: the light, the fraction of its light that got through
  // (zero when an opaque shape blocks it) and its Phong terms at the hit.
  int light = -1;
  Color transmittance{0.0f};
  Color diffuse{0.0f};
  Color specular{0.0f};

  // Path tracing: see PathVertex. For a shadow ray to an emitter (light
  // -1): f Le cos / p of the point it aims at in `diffuse`, and its weight
  // against the BRDF's sample.
  std::optional<PathVertex> path;
  float misWeight = 1.0f;
};

// The coordinates of a sample in Cook's dimensions beyond the pixel: where on
// the lens, when in the shutter interval, where on the lights, where in the
// gloss lobes (each in [0, 1)).
struct SampleDimensions {
  Vec2 lens{0.5f};
  float time = 0.0f;
  Vec2 light{0.5f};
  Vec2 gloss{0.5f};
};

struct RayTree {
  glm::ivec2 pixel{0};
  int sample = 0;                              // its place among the pixel's samples
  Vec2 raster{0.0f};                           // where its primary ray passes through the image
  std::optional<SampleDimensions> dimensions;  // distributed ray tracing only
  Color color{0.0f};                           // the sample's colour
  std::vector<RayNode> rays;                   // the primary ray first
};

}  // namespace rise
