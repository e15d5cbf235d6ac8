// Shadow volumes, after F. C. Crow, "Shadow algorithms for computer
// graphics", SIGGRAPH 1977.
//
// The shadow a polygon casts from a point light is a volume: the part of
// space behind the polygon, seen from the light, bounded by the polygon
// itself and by one face for each of its edges, the quadrilateral swept by
// the edge along the light's rays away from it (along the light's direction
// for a directional light). A point is in shadow when it lies in some
// polygon's volume. Crow's idea is to find that with the very machinery that
// finds visible surfaces: the volumes' faces are polygons like any other,
// invisible, and along the ray from the eye to the surface seen at a pixel,
// each one crossed before the surface is a way into a volume (a face the eye
// sees from outside it: + 1) or out of one (seen from inside: - 1). Starting
// from the number of volumes the eye itself is in, the count at the surface
// is the number of volumes it lies in: 0, lit; more, in shadow.
//
// Where two polygons facing the light share an edge, their faces on that
// edge coincide and run opposite ways: each cancels the other in every count,
// so only the silhouette edges of a mesh, as the light sees it, need a face.
// Here the edges of the faces turned towards the light (both sides of an open
// surface, only the outside of a solid: its back faces lie in the shadow of
// its front) are gathered with their direction, and opposite ones cancelled;
// those left are the silhouette, each giving a face as often as it is left.
// The faces run far beyond the scene instead of to infinity; nothing seen
// lies beyond their ends, so no count there is missed. Transparent surfaces
// cast no volume: a count says in or out, not how much gets through.
//
// On the screen the faces are cut into triangles, clipped and projected as
// the scene's are (raster/screen_geometry.hpp), and, as Crow describes for a
// scanline algorithm, swept down the scanlines with an edge table and an
// active edge list of their own (raster/active_edges.hpp); at each pixel of a
// face's span the face's depth is compared with that of the surface in the
// scanline's depth buffer, and a face in front is counted. A point is found
// in shadow or not exactly, but for pixels on the border of a shadow or on
// the silhouette of a facetted surface, where a face passes through the very
// point seen.
#include "raster/shadow_volumes.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "core/text.hpp"
#include "raster/bands.hpp"

namespace rise {
namespace {

// How far beyond the scene's extent the volumes' faces reach, as a multiple
// of it: far enough that even a face whose edge the light sees at a grazing
// angle passes every point of the scene.
constexpr float kReachPerExtent = 1000.0f;
// The eye may stand on the plane between two faces' volumes, as under the
// middle of a square split into two triangles, and be found in neither; the
// volumes it is in are counted at a point this far from it, as a fraction of
// the scene's extent, in a direction no scene is built along.
constexpr float kEyeNudgePerExtent = 1e-5f;
const Vec3 kEyeNudgeDirection = glm::normalize(Vec3(0.267f, 0.534f, 0.802f));

// A light as its volumes see it: one point, or a direction.
struct LightSource {
  bool directional;
  Vec3 position;   // a point light's, or an area light's centre
  Vec3 direction;  // the way a directional light travels

  explicit LightSource(const Light& light) {
    const LightSample sample = light.illuminate(Vec3(0.0f));
    directional = std::isinf(sample.distance);
    position = directional ? Vec3(0.0f) : sample.toLight * sample.distance;
    direction = -sample.toLight;
  }

  // From `point` towards the light, not normalised.
  Vec3 towards(const Vec3& point) const { return directional ? -direction : position - point; }

  // Where the light's ray through `point` ends `reach` from its start.
  Vec3 extruded(const Vec3& point, float reach) const {
    if (directional) return point + direction * reach;
    return position + normalizedOrZero(point - position) * reach;
  }
};

// An edge as a pair of positions, to be met again from the neighbouring face.
struct EdgeOrder {
  bool operator()(const std::pair<Vec3, Vec3>& a, const std::pair<Vec3, Vec3>& b) const {
    return std::tie(a.first.x, a.first.y, a.first.z, a.second.x, a.second.y, a.second.z) <
           std::tie(b.first.x, b.first.y, b.first.z, b.second.x, b.second.y, b.second.z);
  }
};
// By edge, its endpoints in increasing order: how many more times the faces
// run along it that way than the other way.
using NetEdges = std::map<std::pair<Vec3, Vec3>, int, EdgeOrder>;

void addEdge(NetEdges& edges, const Vec3& from, const Vec3& to) {
  if (EdgeOrder()({from, to}, {to, from}))
    ++edges[{from, to}];
  else
    --edges[{to, from}];
}

// The outward normal of the volume's face on edge from -> to of a triangle
// that winds counter-clockwise seen from the light.
Vec3 outwardNormal(const LightSource& light, const Vec3& from, const Vec3& to) {
  return glm::cross(to - from, light.towards(from));
}

// Whether `point` lies in the volume of the triangle `corners`, which winds
// counter-clockwise seen from the light: beyond its plane and within the
// planes of its three faces.
bool inVolume(const LightSource& light, const std::array<Vec3, 3>& corners, const Vec3& point) {
  const Vec3 normal = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
  if (glm::dot(normal, point - corners[0]) >= 0.0f) return false;
  for (int i = 0; i < 3; ++i) {
    const Vec3& from = corners[i];
    if (glm::dot(outwardNormal(light, from, corners[(i + 1) % 3]), point - from) >= 0.0f)
      return false;
  }
  return true;
}

// The side of the box around the scene's vertices and `eye`, at least 1.
float sceneExtent(const TessellatedScene& tessellated, const Vec3& eye) {
  Vec3 low = eye, high = eye;
  for (const SurfaceVertex& vertex : tessellated.vertices) {
    low = glm::min(low, vertex.position);
    high = glm::max(high, vertex.position);
  }
  return std::max(glm::length(high - low), 1.0f);
}

}  // namespace

bool PixelShadows::any() const {
  return std::any_of(shadowed_.begin(), shadowed_.end(), [](std::uint8_t s) { return s != 0; });
}

ShadowVolumes::ShadowVolumes(const Scene& scene, const TessellatedScene& tessellated,
                             const ViewProjection& view, const Workers& workers)
    : width_(view.width()),
      height_(view.height()),
      lightCount_(static_cast<int>(scene.lights.size())),
      countAtEye_(scene.lights.size(), 0),
      shadowed_(static_cast<std::size_t>(width_) * height_ * scene.lights.size(), 0) {
  buildVolumes(scene, tessellated, view.eye());
  screen_ = projectScene(faces_, view, false, workers);
  polygonsByBand_ = polygonsByBand(screen_, inMadeOrder(screen_), height_);
}

void ShadowVolumes::buildVolumes(const Scene& scene, const TessellatedScene& tessellated,
                                 const Vec3& eye) {
  const float extent = sceneExtent(tessellated, eye);
  const float reach = kReachPerExtent * extent;
  const Vec3 nudgedEye = eye + kEyeNudgePerExtent * extent * kEyeNudgeDirection;
  for (int l = 0; l < lightCount_; ++l) {
    const LightSource light(*scene.lights[static_cast<std::size_t>(l)]);
    NetEdges edges;
    for (const SceneFace& face : tessellated.faces) {
      if (scene.materials[face.material].isTransparent()) continue;
      std::array<Vec3, 3> corners;
      for (int i = 0; i < 3; ++i) corners[i] = tessellated.vertices[face.vertices[i]].position;
      const float facing = glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]),
                                    light.towards(corners[0]));
      if (facing == 0.0f || (facing < 0.0f && face.cullable)) continue;
      if (facing < 0.0f) std::swap(corners[1], corners[2]);
      countAtEye_[l] += inVolume(light, corners, nudgedEye) ? 1 : 0;
      for (int i = 0; i < 3; ++i) addEdge(edges, corners[i], corners[(i + 1) % 3]);
    }
    for (const auto& [edge, net] : edges) {
      const auto [from, to] = net > 0 ? edge : std::pair(edge.second, edge.first);
      if (glm::length(outwardNormal(light, from, to)) == 0.0f) continue;
      for (int copy = 0; copy < std::abs(net); ++copy) {
        // The quadrilateral from, to, to', from' turned so that its
        // counter-clockwise side faces out of the volume.
        const int first = static_cast<int>(faces_.vertices.size());
        for (const Vec3& corner :
             {from, to, light.extruded(from, reach), light.extruded(to, reach)})
          faces_.vertices.push_back({corner, Vec3(0.0f), Vec2(0.0f)});
        faces_.faces.push_back({{first, first + 3, first + 1}, -1, -1, 0, false});
        faces_.faces.push_back({{first, first + 2, first + 3}, -1, -1, 0, false});
        lightOfFace_.insert(lightOfFace_.end(), 2, l);
      }
    }
  }
}

ShadowVolumes::BandCount::BandCount(ShadowVolumes& volumes, const PixelRect& band)
    : volumes_(volumes),
      edges_(volumes.screen_, band, volumes.polygonsByBand_[band.y0 / kBandHeight], edgeCounters_),
      counts_(static_cast<std::size_t>(volumes.width_) * volumes.lightCount_) {}

void ShadowVolumes::BandCount::countScanline(int y, std::span<const float> inverseDepth) {
  const int lights = volumes_.lightCount_;
  for (std::size_t x = 0; x < inverseDepth.size(); ++x)
    std::copy(volumes_.countAtEye_.begin(), volumes_.countAtEye_.end(),
              counts_.begin() + static_cast<std::ptrdiff_t>(x * lights));
  edges_.advanceTo(y);
  std::uint64_t tests = 0, crossings = 0, shadowed = 0;
  const float centreY = static_cast<float>(y) + 0.5f;
  edges_.forEachSpan([&](int order, float left, float right) {
    const ScreenGeometry& screen = volumes_.screen_;
    const ScreenFace& face = screen.faces[screen.polygons[edges_.polygonAt(order)].face];
    const int light = volumes_.lightOfFace_[face.sceneFace];
    const int crossing = face.frontFacing ? 1 : -1;
    const auto [x0, x1] = centresOfSpan(left, right, volumes_.width_);
    for (int x = x0; x < x1; ++x) {
      if (inverseDepth[x] <= 0.0f) continue;  // no surface: nothing to shadow
      ++tests;
      if (face.inverseDepthAt(Vec2(static_cast<float>(x) + 0.5f, centreY)) <= inverseDepth[x])
        continue;
      counts_[static_cast<std::size_t>(x) * lights + light] += crossing;
      ++crossings;
    }
  });
  const std::size_t row = static_cast<std::size_t>(y) * volumes_.width_ * lights;
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    const bool inShadow = counts_[i] != 0 && inverseDepth[i / lights] > 0.0f;
    volumes_.shadowed_[row + i] = inShadow ? 1 : 0;
    shadowed += inShadow ? 1 : 0;
  }
  volumes_.tests_ += tests;
  volumes_.crossings_ += crossings;
  volumes_.shadowedPixels_ += shadowed;
}

StepTable ShadowVolumes::BandCount::countsTable() const {
  StepTable runs{
      "shadow volumes: the count at the surface, by light", {"from x", "to x", "counts"}, {}};
  const std::size_t lights = static_cast<std::size_t>(volumes_.lightCount_);
  const auto countsAt = [&](int x) {
    const auto first = counts_.begin() + static_cast<std::ptrdiff_t>(x * lights);
    return std::vector<int>(first, first + static_cast<std::ptrdiff_t>(lights));
  };
  for (int x = 0; x < volumes_.width_;) {
    const std::vector<int> counts = countsAt(x);
    int end = x + 1;
    while (end < volumes_.width_ && countsAt(end) == counts) ++end;
    std::string text;
    for (int count : counts) appendListed(text, " ", std::to_string(count));
    runs.rows.push_back({static_cast<double>(x), static_cast<double>(end - 1), text});
    x = end;
  }
  return runs;
}

PixelShadows ShadowVolumes::at(int x, int y) const {
  const std::size_t first =
      (static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x)) * lightCount_;
  return PixelShadows(std::span(shadowed_).subspan(first, static_cast<std::size_t>(lightCount_)));
}

void ShadowVolumes::addStats(Stats& stats) const {
  int atEye = 0;
  for (int count : countAtEye_) atEye += count;
  stats.add("shadow_volume_faces", static_cast<double>(faces_.faces.size() / 2));
  stats.add("shadow_volume_polygons", static_cast<double>(screen_.polygons.size()));
  stats.add("eye_in_volumes", atEye);
  stats.add("shadow_volume_tests", static_cast<double>(tests_));
  stats.add("shadow_volume_crossings", static_cast<double>(crossings_));
  stats.add("shadowed_pixel_lights", static_cast<double>(shadowedPixels_));
}

}  // namespace rise
