#include "scene/vertex_normals.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <tuple>

namespace rise {

namespace {

// Each triangle's normal twice: weighted by its area (the cross product of two
// edges is the normal times twice the area) and of unit length. A triangle
// without area, or whose area a float cannot hold, has zero for both.
struct TriangleNormals {
  std::vector<Vec3> weighted;
  std::vector<Vec3> unit;

  explicit TriangleNormals(const MeshGeometry& mesh) {
    weighted.reserve(mesh.triangles.size());
    unit.reserve(mesh.triangles.size());
    for (const auto& [a, b, c] : mesh.triangles) {
      const Vec3 cross =
          glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
      const float length = glm::length(cross);
      const bool usable = length > 0.0f && std::isfinite(length);
      weighted.push_back(usable ? cross : Vec3(0.0f));
      unit.push_back(usable ? cross / length : Vec3(0.0f));
    }
  }
};

// A corner is numbered 3 * its triangle + its place in the triangle.
int triangleOf(int corner) { return corner / 3; }

// The corners at each point, in the mesh's order, as one list cut into runs:
// corners[first[p] .. first[p + 1]) are point p's.
struct CornersAtPoints {
  std::vector<int> first;
  std::vector<int> corners;

  CornersAtPoints(const MeshGeometry& mesh, const std::vector<std::uint32_t>& pointOf,
                  std::size_t pointCount)
      : first(pointCount + 1, 0), corners(3 * mesh.triangles.size()) {
    for (const auto& triangle : mesh.triangles)
      for (int vertex : triangle) ++first[pointOf[vertex] + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<int> next(first.begin(), first.end() - 1);
    for (std::size_t triangle = 0; triangle < mesh.triangles.size(); ++triangle)
      for (int place = 0; place < 3; ++place)
        corners[next[pointOf[mesh.triangles[triangle][place]]]++] =
            static_cast<int>(3 * triangle) + place;
  }

  std::span<int> at(std::size_t point) {
    return std::span(corners).subspan(first[point], first[point + 1] - first[point]);
  }
};

// The sums of weighted normals that smooth the corners at one point. A corner
// takes the triangles at its point whose unit normals are within the crease
// angle of its own triangle's: those on one side of a plane, where their dot
// product with it is at least the angle's cosine. The triangles are kept in
// a tree of boxes around their unit normals (a k-d tree: Bentley,
// "Multidimensional Binary Search Trees Used for Associative Searching",
// CACM 18(9), 1975), each box with the sum of its triangles' weighted normals:
// a box wholly on the plane's side adds its sum at once, one wholly off it is
// passed by, and only the triangles of boxes the plane cuts are tested one by
// one. Where a few triangles meet, as at most points, the tree is one box and
// the sum is the plain loop in the mesh's order; where thousands meet (the
// apex of a cone, the centre of a fan) the time grows with their number and
// not with its square.
class CreaseSums {
 public:
  CreaseSums(const TriangleNormals& normals, float smoothCosine)
      : normals_(normals), smoothCosine_(smoothCosine) {}

  // Builds the tree over these corners' triangles, reordering them.
  void arrange(std::span<int> corners) {
    corners_ = corners;
    boxes_.clear();
    addBox(0, static_cast<int>(corners.size()));
  }

  // The sum over the arranged triangles that smooth with a triangle of this
  // unit normal.
  Vec3 smoothingWith(const Vec3& unitNormal) const {
    Vec3 sum(0.0f);
    if (!boxes_.empty()) addSmoothing(0, unitNormal, sum);
    return sum;
  }

 private:
  static constexpr int kLargestLeaf = 16;

  struct Box {
    Vec3 low, high;
    Vec3 weightedSum{0.0f};
    int begin, end;
    int lower = -1, upper = -1;  // the boxes it is split into, or none for a leaf
  };

  const Vec3& unitOf(int corner) const { return normals_.unit[triangleOf(corner)]; }
  const Vec3& weightedOf(int corner) const { return normals_.weighted[triangleOf(corner)]; }

  int addBox(int begin, int end) {
    Box box{.low = Vec3(std::numeric_limits<float>::max()),
            .high = Vec3(-std::numeric_limits<float>::max()),
            .begin = begin,
            .end = end};
    for (int i = begin; i < end; ++i) {
      box.low = glm::min(box.low, unitOf(corners_[i]));
      box.high = glm::max(box.high, unitOf(corners_[i]));
    }
    const int index = static_cast<int>(boxes_.size());
    boxes_.push_back(box);
    if (end - begin <= kLargestLeaf) {
      for (int i = begin; i < end; ++i) boxes_[index].weightedSum += weightedOf(corners_[i]);
      return index;
    }
    const Vec3 extent = box.high - box.low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const int middle = begin + (end - begin) / 2;
    std::nth_element(corners_.begin() + begin, corners_.begin() + middle, corners_.begin() + end,
                     [&](int a, int b) { return unitOf(a)[axis] < unitOf(b)[axis]; });
    const int lower = addBox(begin, middle);
    const int upper = addBox(middle, end);
    boxes_[index].lower = lower;
    boxes_[index].upper = upper;
    boxes_[index].weightedSum = boxes_[lower].weightedSum + boxes_[upper].weightedSum;
    return index;
  }

  void addSmoothing(int index, const Vec3& unitNormal, Vec3& sum) const {
    const Box& box = boxes_[index];
    // The box's corners farthest along the normal and nearest.
    const glm::bvec3 negative = glm::lessThan(unitNormal, Vec3(0.0f));
    const Vec3 farthest = glm::mix(box.high, box.low, negative);
    const Vec3 nearest = glm::mix(box.low, box.high, negative);
    if (glm::dot(unitNormal, farthest) < smoothCosine_) return;
    if (glm::dot(unitNormal, nearest) >= smoothCosine_) {
      sum += box.weightedSum;
    } else if (box.lower < 0) {
      for (int i = box.begin; i < box.end; ++i)
        if (glm::dot(unitNormal, unitOf(corners_[i])) >= smoothCosine_)
          sum += weightedOf(corners_[i]);
    } else {
      addSmoothing(box.lower, unitNormal, sum);
      addSmoothing(box.upper, unitNormal, sum);
    }
  }

  const TriangleNormals& normals_;
  const float smoothCosine_;
  std::span<int> corners_;
  std::vector<Box> boxes_;
};

// A normal's bits, -0 made +0: normals equal as numbers are equal as bits,
// and any two, those that are not numbers too, sort.
std::array<std::uint32_t, 3> bitsOf(const Vec3& normal) {
  return {std::bit_cast<std::uint32_t>(normal.x + 0.0f),
          std::bit_cast<std::uint32_t>(normal.y + 0.0f),
          std::bit_cast<std::uint32_t>(normal.z + 0.0f)};
}

struct CornerNormal {
  int corner;
  Vec3 normal;
};

// The smooth mesh's vertices before they are numbered: one for each of the
// mesh's vertices and normal that its corners get, and which one each corner
// has.
class SmoothVertices {
 public:
  explicit SmoothVertices(const MeshGeometry& mesh)
      : mesh_(mesh), ofCorner_(3 * mesh.triangles.size()) {}

  // Adds the vertices of the corners at one point (all of them are there).
  void addAt(std::vector<CornerNormal>& corners) {
    const auto key = [&](const CornerNormal& at) {
      return std::tuple(vertexOf(at.corner), bitsOf(at.normal));
    };
    std::ranges::sort(corners, [&](const auto& a, const auto& b) { return key(a) < key(b); });
    for (std::size_t i = 0; i < corners.size(); ++i) {
      if (i == 0 || key(corners[i]) != key(corners[i - 1])) {
        vertices_.push_back(vertexOf(corners[i].corner));
        normals_.push_back(corners[i].normal);
      }
      ofCorner_[corners[i].corner] = static_cast<int>(vertices_.size()) - 1;
    }
  }

  // The mesh of these vertices, numbered in the order in which the corners
  // first ask for them.
  MeshGeometry mesh() const {
    MeshGeometry smooth;
    smooth.positions.reserve(vertices_.size());
    smooth.normals.reserve(vertices_.size());
    smooth.triangles.resize(mesh_.triangles.size());
    std::vector<int> number(vertices_.size(), -1);
    for (std::size_t corner = 0; corner < ofCorner_.size(); ++corner) {
      const int added = ofCorner_[corner];
      if (number[added] < 0) {
        number[added] = static_cast<int>(smooth.positions.size());
        smooth.positions.push_back(mesh_.positions[vertices_[added]]);
        smooth.normals.push_back(normals_[added]);
        if (!mesh_.uvs.empty()) smooth.uvs.push_back(mesh_.uvs[vertices_[added]]);
      }
      smooth.triangles[triangleOf(static_cast<int>(corner))][corner % 3] = number[added];
    }
    return smooth;
  }

 private:
  int vertexOf(int corner) const { return mesh_.triangles[triangleOf(corner)][corner % 3]; }

  const MeshGeometry& mesh_;
  std::vector<int> vertices_;  // the mesh's vertex of each
  std::vector<Vec3> normals_;
  std::vector<int> ofCorner_;
};

}  // namespace

MeshGeometry withVertexNormals(const MeshGeometry& mesh, float creaseAngleDegrees) {
  const TriangleNormals triangleNormals(mesh);
  const std::vector<std::uint32_t> pointOf = weldedIndices(mesh.positions);
  const std::size_t pointCount =
      pointOf.empty() ? 0 : *std::max_element(pointOf.begin(), pointOf.end()) + 1;
  CornersAtPoints atPoints(mesh, pointOf, pointCount);

  CreaseSums sums(triangleNormals, std::cos(radians(creaseAngleDegrees)));
  SmoothVertices smooth(mesh);
  std::vector<CornerNormal> here;
  for (std::size_t point = 0; point < pointCount; ++point) {
    const std::span<int> corners = atPoints.at(point);
    sums.arrange(corners);
    here.clear();
    for (int corner : corners) {
      const Vec3& own = triangleNormals.unit[triangleOf(corner)];
      const Vec3 sum = sums.smoothingWith(own);
      const float length = glm::length(sum);
      here.push_back({corner, length > 0.0f ? sum / length : own});
    }
    smooth.addAt(here);
  }
  return smooth.mesh();
}

}  // namespace rise
