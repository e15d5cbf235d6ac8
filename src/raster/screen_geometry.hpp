// The projective pipeline that the four visible-surface algorithms share: the
// tessellated scene, in the world, becomes convex polygons on the screen.
//
//  1. Matriz3D and Transforma3D (the original RISE report): every vertex into
//     the camera's coordinates (ViewProjection).
//  2. Back-face culling, the report's test: a face whose normal N points away
//     from the eye, (P - Obs) . N >= 0 for a point P of it, shows its back.
//     On a solid seen from outside such a face is always hidden behind the
//     solid's front, so it is dropped; the faces of open surfaces (planes,
//     polygons, open meshes) are seen from both sides and kept.
//  3. Clipping (Sutherland and Hodgman) against the near plane and the sides
//     of the image plus a pixel of margin, so that every corner projects to
//     a finite position near the image.
//  4. Perspective projection: each corner to its raster position (x, y) and
//     its inverse depth w = 1 / n.
//
// The projection maps planes to planes, so over a face w is an affine
// function of (x, y), and so is each of its vertices' barycentric weight
// divided by n (perspective-correct interpolation). Depth comparisons and the
// shading of a pixel use these functions, evaluated at the pixel's centre,
// whatever the polygon the algorithm holds: the face's whole clipped
// polygon, or a piece of it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/left_unfilled.hpp"
#include "core/parallel.hpp"
#include "raster/tessellated_scene.hpp"
#include "raster/view_projection.hpp"

namespace rise {

// The distance of the near clipping plane from the eye.
inline constexpr float kNearDistance = 1e-3f;

// An affine function of raster position, a (x - x0) + b (y - y0) + c, kept
// relative to a point (x0, y0) of its face so that evaluating it near the
// face does not subtract large numbers.
struct RasterAffine {
  Vec3 coefficients;  // (a, b, c)

  float at(const Vec2& relative) const {
    return coefficients.x * relative.x + coefficients.y * relative.y + coefficients.z;
  }
};

// A scene face seen from the eye.
struct ScreenFace {
  int sceneFace;     // into TessellatedScene::faces: the face number of the "face" buffer
  bool frontFacing;  // the eye sees the side its corners wind counter-clockwise around
  Vec2 origin;       // the raster point the affine functions are relative to
  std::array<RasterAffine, 3> weights;  // vertex i's barycentric weight divided by n
  RasterAffine inverseDepth;            // their sum: w = 1 / n on the face's plane

  float inverseDepthAt(const Vec2& raster) const { return inverseDepth.at(raster - origin); }
  // The barycentric coordinates, in the world, of the point seen at `raster`.
  Vec3 barycentricAt(const Vec2& raster) const;
  // The face's plane in screen space (x, y, w): signedDistance (from
  // polygon_clipping.hpp) is w minus the plane's w at (x, y), positive for a
  // point in front of the plane (on the eye's side), negative behind it.
  glm::vec4 plane() const;
};

// A convex polygon on the screen, all or part of one face. Its corners are
// (x, y, w): raster position and inverse depth.
struct ScreenPolygon {
  int face;  // into ScreenGeometry::faces
  int firstCorner;
  int cornerCount;
};

struct ProjectionCounters {
  std::uint64_t polygonsIn = 0;
  std::uint64_t culled = 0;   // back faces of solids, and faces seen exactly edge-on
  std::uint64_t outside = 0;  // wholly outside the view volume
  std::uint64_t clipped = 0;  // cut by its planes

  ProjectionCounters& operator+=(const ProjectionCounters& other) {
    polygonsIn += other.polygonsIn;
    culled += other.culled;
    outside += other.outside;
    clipped += other.clipped;
    return *this;
  }
};

// Its arrays are made at their full sizes unfilled, and written on the
// workers: filling them first on one thread took about a tenth of the
// hybrid's pass 1 on a million triangles.
struct ScreenGeometry {
  UnfilledVector<Vec3> corners;
  UnfilledVector<ScreenFace> faces;
  UnfilledVector<ScreenPolygon> polygons;
  ProjectionCounters counters;

  std::span<const Vec3> cornersOf(const ScreenPolygon& polygon) const {
    return {corners.data() + polygon.firstCorner, static_cast<std::size_t>(polygon.cornerCount)};
  }
  int addPolygon(int face, std::span<const Vec3> polygonCorners);
};

// Runs the pipeline on the workers; the result does not depend on their
// number. It is the projection from the view's point of the lens, not moved
// (projectUnshifted), then moved by the view's shift in the pixel (moveBy),
// so that the passes of an accumulation buffer that see the scene from one
// point of the lens may share the first part.
ScreenGeometry projectScene(const TessellatedScene& scene, const ViewProjection& view,
                            bool backfaceCulling, const Workers& workers);
ScreenGeometry projectUnshifted(const TessellatedScene& scene, const ViewProjection& view,
                                bool backfaceCulling, const Workers& workers);

// Moves the polygons by `shift` in raster coordinates: their corners, and
// their faces' affine functions, which are kept relative to a point of the
// face (RasterAffine) and so need only that point moved.
void moveBy(ScreenGeometry& screen, Vec2 shift, const Workers& workers);

}  // namespace rise
