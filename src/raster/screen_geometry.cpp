#include "raster/screen_geometry.hpp"

#include <algorithm>

#include "raster/polygon_clipping.hpp"

namespace rise {
namespace {

// How far beyond the image's sides polygons reach after clipping, in pixels.
constexpr float kClipMargin = 1.0f;
constexpr int kFacesPerRange = 4096;

// A vertex in camera coordinates, which of the view volume's planes it lies
// outside of (bit i for plane i), and, when it is in front of the near plane,
// its projection (x, y, w).
struct ViewedVertex {
  Vec3 camera;
  unsigned outside;
  Vec3 screen;
};

Vec3 project(const ViewProjection& view, const Vec3& camera) {
  return Vec3(view.toRaster(camera), 1.0f / camera.z);
}

RasterAffine relativeTo(const glm::dvec3& form, const Vec2& origin) {
  return {Vec3(form.x, form.y, form.x * origin.x + form.y * origin.y + form.z)};
}

// The direction d from the eye meets the plane of the corners c0, c1, c2
// (camera coordinates) where d = sum mu_i c_i with sum mu_i = 1 / n: mu =
// M^-1 d, with M the matrix of columns c_i, and the barycentric coordinates
// there are mu / sum mu. Each mu_i is linear in d, hence affine in raster
// position. The rows of M^-1 are c1 x c2, c2 x c0 and c0 x c1 over the
// determinant c0 . (c1 x c2). Computed in double precision: for a small,
// distant face M is nearly singular.
ScreenFace setUpFace(const ViewProjection& view, int sceneFace, bool frontFacing,
                     const std::array<Vec3, 3>& camera, const Vec2& origin) {
  const std::array<glm::dvec3, 3> c{glm::dvec3(camera[0]), glm::dvec3(camera[1]),
                                    glm::dvec3(camera[2])};
  const glm::dvec3 firstRow = glm::cross(c[1], c[2]);
  const double determinant = glm::dot(c[0], firstRow);
  const std::array<glm::dvec3, 3> rows{firstRow, glm::cross(c[2], c[0]), glm::cross(c[0], c[1])};
  ScreenFace face{sceneFace, frontFacing, origin, {}, {}};
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 form = view.rasterForm(rows[i] / determinant);
    face.weights[i] = relativeTo(form, origin);
    sum += form;
  }
  face.inverseDepth = relativeTo(sum, origin);
  return face;
}

// A face the view keeps, as the first sweep over the faces found it: its
// corners are its vertices' projections or, where the view volume cut it, a
// polygon of its range's own.
struct KeptFace {
  int face;          // into TessellatedScene::faces
  int clippedFirst;  // its first corner in KeptFaces::clippedCorners, or -1: not clipped
  int cornerCount;
  bool frontFacing;
};

// The faces of one range of them that the view keeps, in order.
struct KeptFaces {
  std::vector<KeptFace> faces;
  std::vector<Vec3> clippedCorners;  // projected
  std::size_t corners = 0;
  ProjectionCounters counters;
};

// The pipeline in two sweeps over ranges of faces on the workers: the first
// finds the faces kept (culling and clipping), so that the second can write
// each where it goes in the whole, once.
class FaceProjector {
 public:
  FaceProjector(const TessellatedScene& scene, const ViewProjection& view, bool backfaceCulling)
      : scene_(scene),
        view_(view),
        volume_(view.viewVolume(kNearDistance, kClipMargin)),
        backfaceCulling_(backfaceCulling),
        viewed_(scene.vertices.size()) {}

  void viewVertices(int begin, int end) {
    for (int i = begin; i < end; ++i) {
      ViewedVertex& vertex = viewed_[i];
      vertex.camera = view_.toCamera(scene_.vertices[i].position);
      vertex.outside = 0;
      for (std::size_t plane = 0; plane < volume_.size(); ++plane)
        if (signedDistance(volume_[plane], vertex.camera) < 0.0f) vertex.outside |= 1u << plane;
      if (vertex.camera.z > 0.0f) vertex.screen = project(view_, vertex.camera);
    }
  }

  void findKept(int begin, int end, KeptFaces& out) const {
    std::vector<Vec3> polygon, kept, cutOff;
    out.faces.reserve(static_cast<std::size_t>(end - begin));
    for (int f = begin; f < end; ++f) {
      ++out.counters.polygonsIn;
      const SceneFace& face = scene_.faces[f];
      const ViewedVertex& a = viewed_[face.vertices[0]];
      const ViewedVertex& b = viewed_[face.vertices[1]];
      const ViewedVertex& c = viewed_[face.vertices[2]];
      const std::array<Vec3, 3> camera{a.camera, b.camera, c.camera};
      // The report's test, (P - Obs) . N, with Obs at the origin. Camera
      // coordinates (right, up, forward) are left-handed: they mirror the
      // winding, and so the normal, hence the minus.
      const float awayFromEye =
          -glm::dot(camera[0], glm::cross(camera[1] - camera[0], camera[2] - camera[0]));
      if (awayFromEye == 0.0f || (backfaceCulling_ && face.cullable && awayFromEye > 0.0f)) {
        ++out.counters.culled;
        continue;
      }
      if ((a.outside & b.outside & c.outside) != 0) {
        ++out.counters.outside;
        continue;
      }
      const unsigned crossed = a.outside | b.outside | c.outside;
      KeptFace keptFace{f, -1, 3, awayFromEye < 0.0f};
      if (crossed != 0) {
        polygon.assign(camera.begin(), camera.end());
        for (std::size_t plane = 0; plane < volume_.size() && !polygon.empty(); ++plane) {
          if ((crossed & (1u << plane)) == 0) continue;
          splitPolygon(polygon, volume_[plane], 0.0f, kept, cutOff);
          polygon.swap(kept);
        }
        if (polygon.empty()) {
          ++out.counters.outside;
          continue;
        }
        ++out.counters.clipped;
        keptFace.clippedFirst = static_cast<int>(out.clippedCorners.size());
        keptFace.cornerCount = static_cast<int>(polygon.size());
        for (const Vec3& corner : polygon) out.clippedCorners.push_back(project(view_, corner));
      }
      out.faces.push_back(keptFace);
      out.corners += static_cast<std::size_t>(keptFace.cornerCount);
    }
  }

  // Writes the range's kept faces, their polygons and corners into `screen`
  // from face (and polygon) `firstFace` and corner `firstCorner` on.
  void writeKept(const KeptFaces& range, std::size_t firstFace, std::size_t firstCorner,
                 ScreenGeometry& screen) const {
    for (std::size_t i = 0; i < range.faces.size(); ++i) {
      const KeptFace& kept = range.faces[i];
      const SceneFace& face = scene_.faces[kept.face];
      const std::array<Vec3, 3> projected{viewed_[face.vertices[0]].screen,
                                          viewed_[face.vertices[1]].screen,
                                          viewed_[face.vertices[2]].screen};
      const Vec3* corners =
          kept.clippedFirst < 0 ? projected.data() : &range.clippedCorners[kept.clippedFirst];
      const auto index = static_cast<int>(firstFace + i);
      screen.faces[index] =
          setUpFace(view_, kept.face, kept.frontFacing, cameraCorners(face), Vec2(corners[0]));
      screen.polygons[index] = {index, static_cast<int>(firstCorner), kept.cornerCount};
      std::copy(corners, corners + kept.cornerCount, screen.corners.begin() + firstCorner);
      firstCorner += static_cast<std::size_t>(kept.cornerCount);
    }
  }

 private:
  std::array<Vec3, 3> cameraCorners(const SceneFace& face) const {
    return {viewed_[face.vertices[0]].camera, viewed_[face.vertices[1]].camera,
            viewed_[face.vertices[2]].camera};
  }

  const TessellatedScene& scene_;
  const ViewProjection& view_;
  std::array<glm::vec4, 5> volume_;
  bool backfaceCulling_;
  UnfilledVector<ViewedVertex> viewed_;  // written by viewVertices, on the workers
};

// The ranges' kept faces, one after the other, each range written on a
// thread into its place.
ScreenGeometry written(const FaceProjector& projector, const std::vector<KeptFaces>& ranges,
                       const Workers& workers) {
  std::vector<std::size_t> faceStarts{0}, cornerStarts{0};
  ScreenGeometry screen;
  for (const KeptFaces& range : ranges) {
    faceStarts.push_back(faceStarts.back() + range.faces.size());
    cornerStarts.push_back(cornerStarts.back() + range.corners);
    screen.counters += range.counters;
  }
  screen.faces.resize(faceStarts.back());
  screen.polygons.resize(faceStarts.back());
  screen.corners.resize(cornerStarts.back());
  workers.forEachRange(static_cast<int>(ranges.size()), 1, [&](int range, int, int) {
    projector.writeKept(ranges[range], faceStarts[range], cornerStarts[range], screen);
  });
  return screen;
}

}  // namespace

Vec3 ScreenFace::barycentricAt(const Vec2& raster) const {
  const Vec2 relative = raster - origin;
  const Vec3 weighted(weights[0].at(relative), weights[1].at(relative), weights[2].at(relative));
  return weighted / (weighted.x + weighted.y + weighted.z);
}

glm::vec4 ScreenFace::plane() const {
  // w - (a (x - x0) + b (y - y0) + c).
  const Vec3& form = inverseDepth.coefficients;
  return {-form.x, -form.y, 1.0f, form.x * origin.x + form.y * origin.y - form.z};
}

int ScreenGeometry::addPolygon(int face, std::span<const Vec3> polygonCorners) {
  polygons.push_back(
      {face, static_cast<int>(corners.size()), static_cast<int>(polygonCorners.size())});
  corners.insert(corners.end(), polygonCorners.begin(), polygonCorners.end());
  return static_cast<int>(polygons.size()) - 1;
}

ScreenGeometry projectScene(const TessellatedScene& scene, const ViewProjection& view,
                            bool backfaceCulling, const Workers& workers) {
  ScreenGeometry screen = projectUnshifted(scene, view, backfaceCulling, workers);
  moveBy(screen, view.shift(), workers);
  return screen;
}

ScreenGeometry projectUnshifted(const TessellatedScene& scene, const ViewProjection& view,
                                bool backfaceCulling, const Workers& workers) {
  const ViewProjection unshifted = view.unshifted();
  FaceProjector projector(scene, unshifted, backfaceCulling);
  const int vertexCount = static_cast<int>(scene.vertices.size());
  workers.forEachRange(vertexCount, kFacesPerRange,
                       [&](int, int begin, int end) { projector.viewVertices(begin, end); });

  const int faceCount = static_cast<int>(scene.faces.size());
  std::vector<KeptFaces> ranges(Workers::rangeCount(faceCount, kFacesPerRange));
  workers.forEachRange(faceCount, kFacesPerRange, [&](int range, int begin, int end) {
    projector.findKept(begin, end, ranges[range]);
  });
  return written(projector, ranges, workers);
}

void moveBy(ScreenGeometry& screen, Vec2 shift, const Workers& workers) {
  if (shift == Vec2(0.0f)) return;
  const auto move = [&](auto& items, auto&& moveOne) {
    workers.forEachRange(static_cast<int>(items.size()), kFacesPerRange,
                         [&](int, int begin, int end) {
                           for (int i = begin; i < end; ++i)
                             moveOne(items[static_cast<std::size_t>(i)]);
                         });
  };
  move(screen.corners, [&](Vec3& corner) { corner = Vec3(Vec2(corner) + shift, corner.z); });
  move(screen.faces, [&](ScreenFace& face) { face.origin += shift; });
}

}  // namespace rise
