// The light of the classic model's lights (point, spot and area lights) on a
// surface, found by shadow rays: before any light passes between patches,
// what each element reflects of them, and where meshing asks, how fast it
// changes across an element.
#pragma once

#include <cstdint>

#include "radiosity/elements.hpp"
#include "ray/scene_intersector.hpp"

namespace rise {

// The side of a surface at `centre` (its normal `normal`) that faces `point`.
int sideTowards(const Vec3& centre, const Vec3& normal, const Vec3& point);

// A point just off the surface at `centre`, on its side that faces
// `towards`: rays leave from there, past the surface itself.
Vec3 leaving(const Vec3& centre, const Vec3& normal, const Vec3& towards, float offset);

class DirectLight {
 public:
  // `blockers`: what casts shadows; `offset`: how far off a surface its
  // shadow rays leave.
  DirectLight(const Scene& scene, const SceneIntersector& blockers, float offset)
      : scene_(scene), blockers_(blockers), offset_(offset) {}

  // The light each side of a diffuse surface at `point` reflects (its
  // reflectance `reflectance`; its back too where `twoSided`): each light
  // sampled at 4 x 4 points of its area (a point light 16 times the same
  // point), whose irradiance is pi times their colour. Adds its shadow rays
  // to `rays`.
  TwoSides reflected(const Vec3& point, const Vec3& normal, bool twoSided, const Color& reflectance,
                     std::uint64_t& rays) const;
  // The same as if nothing cast shadows, found without rays.
  TwoSides reflectedUnblocked(const Vec3& point, const Vec3& normal, bool twoSided,
                              const Color& reflectance) const;

 private:
  TwoSides reflected(const Vec3& point, const Vec3& normal, bool twoSided, const Color& reflectance,
                     std::uint64_t* rays) const;

  const Scene& scene_;
  const SceneIntersector& blockers_;
  float offset_;
};

}  // namespace rise
