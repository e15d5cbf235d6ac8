#include "ray/ray_tracing.hpp"

#include "ray/scene_intersector.hpp"
#include "render/tiles.hpp"
#include "shading/phong.hpp"

namespace rise {
namespace {

// Rays cast, by kind, and the intersection tests they cost.
struct TraceCounters {
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  std::uint64_t reflectionRays = 0;
  std::uint64_t refractionRays = 0;
  IntersectionCounters intersections;

  std::uint64_t rays() const { return primaryRays + shadowRays + reflectionRays + refractionRays; }

  TraceCounters& operator+=(const TraceCounters& other) {
    primaryRays += other.primaryRays;
    shadowRays += other.shadowRays;
    reflectionRays += other.reflectionRays;
    refractionRays += other.refractionRays;
    intersections.tests += other.intersections.tests;
    return *this;
  }
};

// What the primary ray of a pixel found, for the auxiliary buffers.
struct PrimarySample {
  Color color;
  float depth = kInfinity;
  Vec3 normal{0.0f};
};

// The surface at a hit as the shading sees it: the normal turned towards the
// side the ray came from, and whether the ray is entering the solid.
struct ShadingFrame {
  SurfacePoint surface;
  Vec3 normal;    // unit, on the ray's side of the surface
  Vec3 toViewer;  // unit, back along the ray
  bool entering;
};

ShadingFrame shadingFrame(const Ray& ray, const Hit& hit) {
  ShadingFrame frame;
  frame.surface = hit.shape->surfaceAt(ray, hit);
  frame.toViewer = -glm::normalize(ray.direction);
  frame.entering = glm::dot(frame.surface.normal, frame.toViewer) > 0.0f;
  frame.normal = frame.entering ? frame.surface.normal : -frame.surface.normal;
  return frame;
}

// A ray leaving the surface along `direction`, started a little off the
// surface on the side it travels to, so that it does not hit it again.
Ray spawnRay(const ShadingFrame& frame, const Vec3& direction) {
  const float side = glm::dot(direction, frame.normal) >= 0.0f ? 1.0f : -1.0f;
  return Ray{frame.surface.position + (side * kRayEpsilon) * frame.normal, direction};
}

class WhittedTracer {
 public:
  WhittedTracer(const Scene& scene, int maxDepth)
      : scene_(scene), intersector_(scene), maxDepth_(maxDepth) {}

  PrimarySample tracePrimary(const Ray& ray, TraceCounters& counters) const {
    ++counters.primaryRays;
    Hit hit;
    if (!intersector_.nearest(ray, 0.0f, hit, counters.intersections))
      return {scene_.image.background};
    const ShadingFrame frame = shadingFrame(ray, hit);
    return {shade(frame, scene_.materialOf(*hit.shape), 1, counters), hit.t, frame.surface.normal};
  }

 private:
  // Intersect, then Shade: the colour seen along a secondary ray.
  Color trace(const Ray& ray, int depth, TraceCounters& counters) const {
    Hit hit;
    if (!intersector_.nearest(ray, 0.0f, hit, counters.intersections))
      return scene_.image.background;
    return shade(shadingFrame(ray, hit), scene_.materialOf(*hit.shape), depth, counters);
  }

  Color shade(const ShadingFrame& frame, const Material& material, int depth,
              TraceCounters& counters) const {
    const Color surfaceColor = material.colorAt(frame.surface);
    Color color = phongAmbient(material, surfaceColor, scene_.ambient) +
                  directLight(frame, material, surfaceColor, counters);
    if (depth >= maxDepth_) return color;
    if (material.reflection > 0.0f)
      color += material.reflection * reflected(frame, depth, counters);
    if (material.transmission > 0.0f)
      color += material.transmission * material.color * refracted(frame, material, depth, counters);
    return color;
  }

  // The Phong terms of every light that a shadow ray reaches.
  Color directLight(const ShadingFrame& frame, const Material& material, const Color& surfaceColor,
                    TraceCounters& counters) const {
    Color color(0.0f);
    for (const auto& light : scene_.lights) {
      const LightSample sample = light->illuminate(frame.surface.position);
      if (glm::dot(frame.normal, sample.toLight) <= 0.0f) continue;
      ++counters.shadowRays;
      const Ray shadowRay = spawnRay(frame, sample.toLight);
      const Color visible =
          intersector_.transmittance(shadowRay, 0.0f, sample.distance, counters.intersections);
      if (visible == Color(0.0f)) continue;
      color += visible * phongDirect(material, surfaceColor, frame.normal, frame.toViewer, sample);
    }
    return color;
  }

  Color reflected(const ShadingFrame& frame, int depth, TraceCounters& counters) const {
    ++counters.reflectionRays;
    const Vec3 mirror = glm::reflect(-frame.toViewer, frame.normal);
    return trace(spawnRay(frame, mirror), depth + 1, counters);
  }

  // Snell's law with the relative index of the two sides; past the critical
  // angle there is no refracted ray and the light reflects totally.
  Color refracted(const ShadingFrame& frame, const Material& material, int depth,
                  TraceCounters& counters) const {
    ++counters.refractionRays;
    const float eta = frame.entering ? 1.0f / material.ior : material.ior;
    Vec3 direction = glm::refract(-frame.toViewer, frame.normal, eta);
    if (direction == Vec3(0.0f)) direction = glm::reflect(-frame.toViewer, frame.normal);
    return trace(spawnRay(frame, direction), depth + 1, counters);
  }

  const Scene& scene_;
  SceneIntersector intersector_;
  int maxDepth_;
};

void addStats(Stats& stats, const TraceCounters& counters) {
  stats.add("rays", static_cast<double>(counters.rays()));
  stats.add("primary_rays", static_cast<double>(counters.primaryRays));
  stats.add("shadow_rays", static_cast<double>(counters.shadowRays));
  stats.add("reflection_rays", static_cast<double>(counters.reflectionRays));
  stats.add("refraction_rays", static_cast<double>(counters.refractionRays));
  stats.add("intersection_tests", static_cast<double>(counters.intersections.tests));
  stats.add("intersection_tests_per_ray", static_cast<double>(counters.intersections.tests) /
                                              static_cast<double>(counters.rays()));
}

}  // namespace

RenderResult WhittedRayTracer::render(const Scene& scene, const RenderSettings& settings,
                                      RenderObserver& observer) const {
  const int width = settings.width;
  const int height = settings.height;
  const ViewFrame view(scene.camera, width, height);
  const WhittedTracer tracer(scene, settings.maxDepth);

  RenderResult result;
  result.image = Image(width, height);
  Image& depth = result.buffers["depth"] = Image(width, height, Color(kInfinity));
  Image& normal = result.buffers["normal"] = Image(width, height);
  Image& cost = result.buffers["cost"] = Image(width, height);

  const std::vector<Tile> tiles = makeTiles(width, height);
  std::vector<TraceCounters> tileCounters(tiles.size());
  renderTiles(tiles, settings.threads, observer, [&](const Tile& tile) {
    TraceCounters& counters = tileCounters[tile.index];
    for (int y = tile.y0; y < tile.y1; ++y) {
      for (int x = tile.x0; x < tile.x1; ++x) {
        const std::uint64_t testsBefore = counters.intersections.tests;
        const Ray ray = view.primaryRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        const PrimarySample sample = tracer.tracePrimary(ray, counters);
        result.image.at(x, y) = sample.color;
        depth.at(x, y) = Color(sample.depth);
        normal.at(x, y) = sample.normal;
        cost.at(x, y) = Color(static_cast<float>(counters.intersections.tests - testsBefore));
      }
    }
  });

  TraceCounters total;
  for (const TraceCounters& counters : tileCounters) total += counters;
  addStats(result.stats, total);
  return result;
}

}  // namespace rise
