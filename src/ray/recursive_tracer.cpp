#include "ray/recursive_tracer.hpp"

#include "core/sampling.hpp"
#include "scene/light.hpp"
#include "shading/phong.hpp"

namespace rise {

// The surface at a hit as the shading sees it: the normal turned towards the
// side the ray came from, and whether the ray is entering the solid.
struct ShadingFrame {
  SurfacePoint surface;
  Vec3 normal;         // the geometric normal, unit, on the ray's side of the surface
  Vec3 shadingNormal;  // the smooth normal for shading, on the same side
  Vec3 toViewer;       // unit, back along the ray
  float time;          // the ray's instant, which the rays it spawns keep
  bool entering;
};

namespace {

ShadingFrame shadingFrame(const Ray& ray, const Hit& hit, const Material& material) {
  ShadingFrame frame;
  frame.surface = hit.shape->surfaceAt(ray, hit);
  frame.surface.shadingNormal = material.shadingNormalAt(frame.surface);
  frame.toViewer = -glm::normalize(ray.direction);
  frame.time = ray.time;
  frame.entering = glm::dot(frame.surface.normal, frame.toViewer) > 0.0f;
  frame.normal = frame.entering ? frame.surface.normal : -frame.surface.normal;
  frame.shadingNormal = frame.entering ? frame.surface.shadingNormal : -frame.surface.shadingNormal;
  return frame;
}

// A ray leaving the surface along `direction`, started a little off the
// surface on the side it travels to, so that it does not hit it again.
Ray spawnRay(const ShadingFrame& frame, const Vec3& direction) {
  const float side = glm::dot(direction, frame.normal) >= 0.0f ? 1.0f : -1.0f;
  return Ray{frame.surface.position + (side * kRayEpsilon) * frame.normal, direction, frame.time};
}

// A direction spread around `ideal` (unit) within a cone whose half-angle has
// the tangent `roughness`, chosen by the sample u: Cook's gloss (reflection)
// and translucency (refraction). The spread direction is kept on the same
// side of the surface as the ideal one, mirrored across it if it strayed.
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

}  // namespace

SampleResult RecursiveTracer::tracePrimary(const Ray& ray, PathSampler& paths,
                                           TraceCounters& counters) const {
  ++counters.primaryRays;
  Hit hit;
  if (!intersector_.nearest(ray, 0.0f, hit, counters.intersections))
    return {scene_.image.background};
  const Material& material = scene_.materialOf(*hit.shape);
  const ShadingFrame frame = shadingFrame(ray, hit, material);
  return {shade(frame, material, 1, paths, counters), hit.t * glm::length(ray.direction),
          frame.surface.normal};
}

Color RecursiveTracer::trace(const Ray& ray, int depth, PathSampler& paths,
                             TraceCounters& counters) const {
  Hit hit;
  if (!intersector_.nearest(ray, 0.0f, hit, counters.intersections)) return scene_.image.background;
  const Material& material = scene_.materialOf(*hit.shape);
  return shade(shadingFrame(ray, hit, material), material, depth, paths, counters);
}

Color RecursiveTracer::shade(const ShadingFrame& frame, const Material& material, int depth,
                             PathSampler& paths, TraceCounters& counters) const {
  const SurfaceColors colors = material.colorsAt(frame.surface);
  Color color = phongAmbient(material, colors, scene_.ambient) +
                directLight(frame, material, colors, depth, paths, counters);
  if (depth >= maxDepth_) return color;
  if (material.reflection > 0.0f)
    color += material.reflection * reflected(frame, material, depth, paths, counters);
  if (material.transmission > 0.0f)
    color +=
        material.transmission * material.color * refracted(frame, material, depth, paths, counters);
  return color;
}

// The Phong terms of every light that a shadow ray reaches.
Color RecursiveTracer::directLight(const ShadingFrame& frame, const Material& material,
                                   const SurfaceColors& colors, int depth, PathSampler& paths,
                                   TraceCounters& counters) const {
  Color color(0.0f);
  for (const auto& light : scene_.lights) {
    const LightSample sample = light->illuminate(frame.surface.position, paths.lightSample(depth));
    if (glm::dot(frame.normal, sample.toLight) <= 0.0f) continue;
    ++counters.shadowRays;
    const Color visible = intersector_.transmittance(spawnRay(frame, sample.toLight), 0.0f,
                                                     sample.distance, counters.intersections);
    if (visible == Color(0.0f)) continue;
    color += visible * phongDirect(material, colors, frame.shadingNormal, frame.toViewer, sample);
  }
  return color;
}

Color RecursiveTracer::reflected(const ShadingFrame& frame, const Material& material, int depth,
                                 PathSampler& paths, TraceCounters& counters) const {
  ++counters.reflectionRays;
  const Vec3 mirror = glm::reflect(-frame.toViewer, frame.shadingNormal);
  const Vec3 direction = spread(mirror, material.roughness, paths.glossSample(depth), frame.normal);
  return trace(spawnRay(frame, direction), depth + 1, paths, counters);
}

// Snell's law with the relative index of the two sides; past the critical
// angle there is no refracted ray and the light reflects totally.
Color RecursiveTracer::refracted(const ShadingFrame& frame, const Material& material, int depth,
                                 PathSampler& paths, TraceCounters& counters) const {
  ++counters.refractionRays;
  const float eta = frame.entering ? 1.0f / material.ior : material.ior;
  Vec3 direction = glm::refract(-frame.toViewer, frame.shadingNormal, eta);
  if (direction == Vec3(0.0f)) direction = glm::reflect(-frame.toViewer, frame.shadingNormal);
  direction = spread(direction, material.roughness, paths.glossSample(depth), frame.normal);
  return trace(spawnRay(frame, direction), depth + 1, paths, counters);
}

}  // namespace rise
