#include "reports/ray_tree_picture.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "algorithms/registry.hpp"
#include "io/image_io.hpp"

namespace rise {
namespace {

constexpr int kSideWidth = 480;
constexpr int kSideHeight = 360;

// A ray as a segment in the world, from its origin to where it ended.
struct Segment {
  Vec3 from, to;
  const RayNode* ray;
};

// Shadow rays are drawn a short way towards their lights, which may be far
// or infinitely far; rays that hit nothing as far as the farthest hit.
std::vector<Segment> segmentsOf(const std::vector<RayTree>& trees, float extent) {
  std::vector<Segment> segments;
  for (const RayTree& tree : trees) {
    for (const RayNode& ray : tree.rays) {
      float length = ray.hit ? ray.distance : extent;
      if (ray.kind == RayKind::Shadow) length = std::min(ray.distance, 0.15f * extent);
      segments.push_back({ray.origin, ray.origin + length * ray.direction, &ray});
    }
  }
  return segments;
}

// How far the rays reach, for the length of those that end nowhere.
float extentOf(const std::vector<RayTree>& trees, const Vec3& eye) {
  float extent = 1.0f;
  for (const RayTree& tree : trees)
    for (const RayNode& ray : tree.rays)
      if (ray.hit) extent = std::max(extent, glm::distance(eye, ray.point));
  return extent;
}

// A point of the world on a view's image, in pixels; none behind the eye.
std::optional<Vec2> project(const ViewFrame& view, const Vec3& point) {
  const Vec3 offset = point - view.eye();
  const float ahead = glm::dot(offset, view.forward());
  if (ahead <= 1e-4f) return std::nullopt;
  const float x = glm::dot(offset, view.right()) / (ahead * view.halfWidth());
  const float y = glm::dot(offset, view.up()) / (ahead * view.halfHeight());
  return Vec2((x + 1.0f) * 0.5f * view.width(), (1.0f - y) * 0.5f * view.height());
}

// The segment's part in front of the eye, on the view's image.
std::optional<std::pair<Vec2, Vec2>> projectSegment(const ViewFrame& view, Segment segment) {
  const float near = 1e-3f;
  const float a = glm::dot(segment.from - view.eye(), view.forward()) - near;
  const float b = glm::dot(segment.to - view.eye(), view.forward()) - near;
  if (a <= 0.0f && b <= 0.0f) return std::nullopt;
  if (a <= 0.0f) segment.from += (a / (a - b)) * (segment.to - segment.from);
  if (b <= 0.0f) segment.to += (b / (b - a)) * (segment.from - segment.to);
  const std::optional<Vec2> from = project(view, segment.from);
  const std::optional<Vec2> to = project(view, segment.to);
  if (!from || !to) return std::nullopt;
  return std::pair{*from, *to};
}

const char* strokeOf(const RayNode& ray) {
  switch (ray.kind) {
    case RayKind::Primary:
      return "#ffffff";
    case RayKind::Shadow:
      return ray.transmittance == Color(0.0f) ? "#ff3d00" : "#ffd600";
    case RayKind::Reflection:
      return "#00e5ff";
    case RayKind::Refraction:
      return "#e040fb";
  }
  return "#ffffff";
}

void drawView(std::ostringstream& svg, const ViewFrame& view, const std::string& image, float left,
              const std::vector<Segment>& segments) {
  svg << "<image x=\"" << left << "\" y=\"0\" width=\"" << view.width() << "\" height=\""
      << view.height() << "\" href=\"" << image << "\"/>\n";
  for (const Segment& segment : segments) {
    const auto line = projectSegment(view, segment);
    if (!line) continue;
    svg << "<line x1=\"" << left + line->first.x << "\" y1=\"" << line->first.y << "\" x2=\""
        << left + line->second.x << "\" y2=\"" << line->second.y << "\" stroke=\""
        << strokeOf(*segment.ray) << "\" stroke-width=\"1.5\""
        << (segment.ray->kind == RayKind::Shadow ? " stroke-dasharray=\"4 3\"" : "") << "/>\n";
    if (segment.ray->hit)
      svg << "<circle cx=\"" << left + line->second.x << "\" cy=\"" << line->second.y
          << "\" r=\"2.5\" fill=\"" << strokeOf(*segment.ray) << "\"/>\n";
  }
}

// A camera beside the rays: it looks at the middle of the eye and the hits
// from the side of the main camera's right, a little above, far enough to
// see them all.
Camera sideCamera(const Camera& camera, const std::vector<RayTree>& trees) {
  Vec3 low = camera.position, high = camera.position;
  for (const RayTree& tree : trees) {
    for (const RayNode& ray : tree.rays) {
      if (!ray.hit) continue;
      low = glm::min(low, ray.point);
      high = glm::max(high, ray.point);
    }
  }
  const ViewFrame view(camera, kSideWidth, kSideHeight);
  const Vec3 middle = 0.5f * (low + high);
  const float size = std::max(glm::length(high - low), 1e-3f);
  Camera side = camera;
  side.position = middle + 1.1f * size * glm::normalize(view.right() + 0.35f * view.up());
  side.lookAt = middle;
  side.up = view.up();
  side.fovDegrees = 50.0f;
  side.aperture = 0.0f;
  return side;
}

}  // namespace

void writeRayTreePicture(const std::filesystem::path& svg, Scene& scene,
                         const RenderSettings& settings, const Image& image,
                         const std::vector<RayTree>& trees) {
  const std::string stem = svg.stem().string();
  const std::string cameraImage = stem + ".camera.png";
  const std::string sideImage = stem + ".side.png";
  writeImage(image, svg.parent_path() / cameraImage);

  const ViewFrame view(scene.camera, settings.width, settings.height);
  const std::vector<Segment> segments = segmentsOf(trees, extentOf(trees, scene.camera.position));
  const Camera besideRays = sideCamera(scene.camera, trees);
  const ViewFrame sideView(besideRays, kSideWidth, kSideHeight);
  RenderSettings sideSettings = settings;
  sideSettings.width = kSideWidth;
  sideSettings.height = kSideHeight;
  sideSettings.sampling = {};
  const Camera camera = std::exchange(scene.camera, besideRays);
  RenderObserver nobody;
  const RenderResult side = findRenderer("z-buffer")->render(scene, sideSettings, nobody);
  scene.camera = camera;
  writeImage(side.image, svg.parent_path() / sideImage);

  std::ostringstream out;
  const int gap = 12;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << settings.width + gap + kSideWidth
      << "\" height=\"" << std::max(settings.height, kSideHeight) << "\">\n";
  drawView(out, view, cameraImage, 0.0f, segments);
  drawView(out, sideView, sideImage, static_cast<float>(settings.width + gap), segments);
  if (const auto eye = project(sideView, scene.camera.position))
    out << "<circle cx=\"" << settings.width + gap + eye->x << "\" cy=\"" << eye->y
        << "\" r=\"4\" fill=\"none\" stroke=\"#ffffff\"/>\n";
  out << "</svg>\n";
  std::ofstream file(svg);
  file << out.str();
  file.close();
  if (!file)
    throw std::runtime_error(svg.string() + ": cannot write (" + std::strerror(errno) + ")");
}

}  // namespace rise
