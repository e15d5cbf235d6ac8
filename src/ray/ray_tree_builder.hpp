// Records the tree of rays of one sample (render/ray_tree.hpp) as the
// recursion of ray_tracing.cpp traces it: each ray begins, meets a surface or
// the background, spawns shadow rays and more rays, and ends with the colour
// it brings back.
#pragma once

#include "core/ray.hpp"
#include "render/ray_tree.hpp"
#include "scene/scene.hpp"

namespace rise {

// Its calls are kept out of line (gnu::noinline): inlined, even where they
// are not taken, they would swell the recursion of a render nobody watches
// and crowd out what it inlines for speed.
class RayTreeBuilder {
 public:
  RayTreeBuilder(const Scene& scene, RayTree& tree) : scene_(scene), tree_(tree) {}

  // A ray begins, from the ray being traced now; `weight` is what the colour
  // it brings back is multiplied by at its parent's surface.
  [[gnu::noinline]] void begin(RayKind kind, const Ray& ray, int depth, const Color& weight);
  // The current ray met a surface.
  [[gnu::noinline]] void hit(const Hit& hit, const SurfacePoint& surface);
  // The ambient term at the current ray's surface.
  [[gnu::noinline]] void ambient(const Color& term);
  // A shadow ray from the current ray's surface towards `light`, `distance`
  // away: the fraction of the light that got through, and the Phong model's
  // diffuse and specular terms there.
  [[gnu::noinline]] void shadow(const Ray& ray, const Light& light, float distance,
                                const Color& visible, const Color& diffuse, const Color& specular);
  // The path tracer's record of the current ray's surface, to fill in.
  [[gnu::noinline]] PathVertex& pathVertex();
  // A shadow ray from the current ray's surface to a point of an emitter,
  // `distance` away, blocked or not: `lit` (f Le cos / p) weighed by `weight`.
  [[gnu::noinline]] void emitterShadow(const Ray& ray, float distance, bool reaches,
                                       const Color& lit, float weight);
  // The current ray ends, bringing back `color`.
  [[gnu::noinline]] void end(const Color& color);

 private:
  RayNode& current() { return tree_.rays[static_cast<std::size_t>(current_)]; }
  int add(RayNode node);
  // A shadow ray leaving the current ray's surface.
  RayNode shadowFromCurrent(const Ray& ray);

  const Scene& scene_;
  RayTree& tree_;
  int current_ = -1;
};

}  // namespace rise
