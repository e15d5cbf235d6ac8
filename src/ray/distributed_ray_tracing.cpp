// Distributed ray tracing, after Cook, Porter and Carpenter (1984).
//
// Whitted's ray tracer takes one ray for each choice that light could make:
// the eye is a pinhole, the shutter opens for an instant, a light is a point,
// a mirror is perfect. The fuzzy phenomena of real images are averages over
// those choices, and Cook's insight is that the rays a pixel already takes
// for anti-aliasing can sample them at no extra cost. Each of the pixel's n
// samples carries a value in each of five dimensions:
//   pixel  where in the pixel its ray passes (anti-aliasing);
//   lens   where on a thin lens it leaves from: the ray passes through the
//          point the pinhole ray meets on the plane in focus, so that plane
//          stays sharp and the rest blurs with its distance (depth of field);
//   time   when in the shutter interval it travels: moving shapes are where
//          that fraction of their motion has taken them (motion blur);
//   light  where on each area light its shadow rays aim (soft shadows);
//   gloss  where around the ideal direction its reflected and refracted rays
//          go, within a cone whose half-angle's tangent is the material's
//          roughness (gloss and translucency).
// Each dimension's n values are stratified (jittered) on their own and then
// shuffled apart (Cook, "Stochastic sampling in computer graphics", ACM TOG
// 1986), so that every dimension is well spread and no two are correlated:
// the sample in the pixel's top-left cell does not always take the lens's
// top-left too (core/sampler.hpp lays them out). Surfaces deeper along a path
// draw fresh random values. The
// recursion itself is Whitted's (ray_tracing.cpp), asked these choices
// instead of his single ray; with no lens, no shutter interval, no area light
// and no roughness, the image is Whitted's with the same samples.
#include "ray/distributed_ray_tracing.hpp"

#include "core/warps.hpp"
#include "ray/ray_tracing.hpp"

namespace rise {

const AlgorithmDescription& DistributedRayTracer::description() const {
  static const AlgorithmDescription description = rayTracingAlgorithm(
      "distributed-ray-tracing",
      "Cook's distributed ray tracing: depth of field, motion blur, soft shadows, gloss",
      "R. L. Cook, T. Porter, L. Carpenter, Distributed ray tracing, SIGGRAPH 1984",
      {Effect::Shadows, Effect::Reflection, Effect::Refraction, Effect::DepthOfField,
       Effect::MotionBlur, Effect::SoftShadows, Effect::Gloss});
  return description;
}

namespace {

// One sample's values in the four dimensions beyond the pixel's, each in
// [0, 1).
struct CameraSample {
  Vec2 lens;
  float time;
  Vec2 light;
  Vec2 gloss;
};

// The lens, the light and the gloss in the unit square; the time in [0, 1).
constexpr SampleLayout kCameraLayout{.squares = 3, .intervals = 1};

CameraSample cameraSample(SampleValues& values) {
  CameraSample sample;
  sample.lens = values.next2D();
  sample.time = values.next1D();
  sample.light = values.next2D();
  sample.gloss = values.next2D();
  return sample;
}

// A direction spread around `ideal` (unit) within a cone whose half-angle has
// the tangent `roughness`, chosen by the sample u. The spread direction is
// kept on the same side of the surface as the ideal one, mirrored across it
// if it strayed.
Vec3 spread(const Vec3& ideal, float roughness, const Vec2& u, const Vec3& normal) {
  if (roughness == 0.0f) return ideal;
  Vec3 across, up;
  orthonormalBasis(ideal, across, up);
  const Vec2 offset = roughness * squareToDisk(u);
  Vec3 direction = glm::normalize(ideal + offset.x * across + offset.y * up);
  const float idealSide = glm::dot(ideal, normal);
  const float side = glm::dot(direction, normal);
  if (side * idealSide < 0.0f) direction -= 2.0f * side * normal;
  return direction;
}

// The path's choices: at the surface seen from the eye, the sample's own
// stratified light and gloss values; deeper, the sample's next values,
// beyond its layout and so fresh random ones.
class DistributedChoices final : public PathChoices {
 public:
  DistributedChoices(const CameraSample& sample, SampleValues& values)
      : sample_(sample), values_(values) {}

  LightSample aimAt(const Light& light, const Vec3& point, int depth) override {
    return light.illuminate(point, depth == 1 ? sample_.light : values_.next2D());
  }
  Vec3 scatter(const Vec3& ideal, float roughness, const Vec3& normal, int depth) override {
    return spread(ideal, roughness, depth == 1 ? sample_.gloss : values_.next2D(), normal);
  }

 private:
  const CameraSample& sample_;
  SampleValues& values_;
};

}  // namespace

RenderResult DistributedRayTracer::render(const Scene& scene, const RenderSettings& settings,
                                          RenderObserver& observer) const {
  return traceTiles(scene, settings, observer, [&](const TracingContext& context, TileTrace& tile) {
    traceEachSample(
        tile, settings, kCameraLayout,
        [&](const Vec2& raster, SampleValues& values, TraceCounters& counters, RayTree* tree) {
          const CameraSample sample = cameraSample(values);
          Ray ray = thinLensRay(context.view, raster, sample.lens);
          ray.time = scene.camera.sceneTime(sample.time);
          if (tree)
            tree->dimensions = SampleDimensions{sample.lens, ray.time, sample.light, sample.gloss};
          DistributedChoices choices(sample, values);
          return tracePrimary(context, ray, choices, counters, tree);
        });
  });
}

}  // namespace rise
