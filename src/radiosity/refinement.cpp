#include "radiosity/refinement.hpp"

#include <algorithm>
#include <unordered_map>

#include "scene/mesh_geometry.hpp"

namespace rise {

namespace {

constexpr int kDeepestCut = 5;  // elements a 32nd of the patch size
constexpr float kChangeOfTheShare = 0.2f;
constexpr float kChangeOfTheBrightest = 0.02f;
constexpr std::size_t kMostElements = 200'000;

std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

SurfaceVertex midway(const SurfaceVertex& a, const SurfaceVertex& b) {
  SurfaceVertex vertex;
  vertex.position = 0.5f * (a.position + b.position);
  vertex.normal = normalizedOrZero(a.normal + b.normal);
  vertex.uv = 0.5f * (a.uv + b.uv);
  return vertex;
}

class Refiner {
 public:
  Refiner(RadiosityMesh& mesh, const DirectLight& light, const Workers& workers)
      : mesh_(mesh.elementMesh),
        patches_(mesh.patchMesh),
        light_(light),
        workers_(workers),
        smallestSide_(mesh.patchSide / static_cast<float>(1 << kDeepestCut)),
        faces_(mesh_.triangles.faces) {
    std::vector<Vec3> positions;
    for (const SurfaceVertex& vertex : mesh_.triangles.vertices)
      positions.push_back(vertex.position);
    pointOf_ = weldedIndices(positions);
    points_ = pointOf_.empty() ? 0 : *std::max_element(pointOf_.begin(), pointOf_.end()) + 1;
    for (std::size_t e = 0; e < mesh_.elements.size(); ++e)
      nodes_.push_back({mesh_.elements[e], static_cast<int>(e), 0, patches_.patchOf[e], false});
  }

  RefinementCounts refine() {
    for (int depth = 0; depth < kDeepestCut; ++depth) cutWhereTheLightChanges(depth);
    cutWhereNeighboursAreFiner();
    keepTheLeaves();
    return counts_;
  }

 private:
  struct Node {
    Element element;
    int face;  // the face it was cut from
    int depth;
    int patch;
    bool cut;
  };

  std::uint32_t midpointOfPoints(std::uint32_t a, std::uint32_t b) {
    const auto [found, isNew] = pointBetween_.try_emplace(pairKey(a, b), points_);
    if (isNew) ++points_;
    return found->second;
  }
  bool hasMidpoint(std::uint32_t a, std::uint32_t b) const {
    return pointBetween_.contains(pairKey(a, b));
  }

  // The vertex halfway along a side of elements, made once.
  int midpointOfVertices(int a, int b) {
    const auto key = pairKey(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b));
    if (const auto found = vertexBetween_.find(key); found != vertexBetween_.end())
      return found->second;
    std::vector<SurfaceVertex>& vertices = mesh_.triangles.vertices;
    const int made = static_cast<int>(vertices.size());
    vertices.push_back(midway(vertices[a], vertices[b]));
    pointOf_.push_back(midpointOfPoints(pointOf_[a], pointOf_[b]));
    vertexBetween_.emplace(key, made);
    return made;
  }

  void cut(std::size_t n) {
    const Node parent = nodes_[n];
    nodes_[n].cut = true;
    const auto [a, b, c] = parent.element.vertices;
    const int ab = midpointOfVertices(a, b), bc = midpointOfVertices(b, c),
              ca = midpointOfVertices(c, a);
    for (const std::array<int, 3>& corners : {std::array{a, ab, ca}, std::array{ab, b, bc},
                                              std::array{ca, bc, c}, std::array{ab, bc, ca}}) {
      Element child = parent.element;
      child.vertices = corners;
      const std::array<Vec3, 3> at = cornersOf(mesh_.triangles.vertices, corners);
      child.centre = (at[0] + at[1] + at[2]) / 3.0f;
      child.area = parent.element.area / 4.0f;
      nodes_.push_back({child, parent.face, parent.depth + 1, parent.patch, false});
    }
    ++counts_.elementsCut;
  }

  // At the element's corners (each a hundredth of the way in, off the edges
  // where surfaces meet) and centre, the direct light and the share of it
  // that shadows leave: the least and most of each.
  struct Range {
    float leastLight = kInfinity, mostLight = 0.0f;
    float leastShare = 1.0f, mostShare = 0.0f;
  };
  Range lightRange(const Element& element, std::uint64_t& rays) const {
    const std::array<Vec3, 3> corners = cornersOf(mesh_.triangles.vertices, element.vertices);
    const auto seen = [](const TwoSides& light) {
      return luminance(light[kFrontSide]) + luminance(light[kBackSide]);
    };
    Range range;
    for (const Vec3& point : {corners[0], corners[1], corners[2], element.centre}) {
      const Vec3 inside = point + 0.01f * (element.centre - point);
      const float lit =
          seen(light_.reflected(inside, element.normal, element.twoSided, Color(1.0f), rays));
      const float open =
          seen(light_.reflectedUnblocked(inside, element.normal, element.twoSided, Color(1.0f)));
      const float share = open > 0.0f ? lit / open : 1.0f;
      range = {std::min(range.leastLight, lit), std::max(range.mostLight, lit),
               std::min(range.leastShare, share), std::max(range.mostShare, share)};
    }
    return range;
  }

  void cutWhereTheLightChanges(int depth) {
    std::vector<std::size_t> candidates;
    for (std::size_t n = 0; n < nodes_.size(); ++n)
      if (!nodes_[n].cut && nodes_[n].depth == depth &&
          longestSide(cornersOf(mesh_.triangles.vertices, nodes_[n].element.vertices)) >=
              2.0f * smallestSide_)
        candidates.push_back(n);
    if (candidates.empty() || nodes_.size() + 4 * candidates.size() > kMostElements) return;
    std::vector<Range> ranges(candidates.size());
    std::vector<std::uint64_t> rays(candidates.size(), 0);
    workers_.forEachTask(static_cast<int>(candidates.size()), [&](int task) {
      ranges[task] = lightRange(nodes_[candidates[task]].element, rays[task]);
    });
    for (const std::uint64_t count : rays) counts_.shadowRays += count;
    if (depth == 0)
      for (const Range& range : ranges) brightest_ = std::max(brightest_, range.mostLight);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const Range& range = ranges[i];
      if (range.mostShare - range.leastShare > kChangeOfTheShare &&
          range.mostLight - range.leastLight > kChangeOfTheBrightest * brightest_)
        cut(candidates[i]);
    }
  }

  // Whether an element must be cut so that no side of it meets more than
  // one new corner: a neighbour two cuts finer, or new corners on all three.
  bool meetsTooFine(const Element& element) {
    int sidesWithCorners = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = pointOf_[element.vertices[k]],
                          b = pointOf_[element.vertices[(k + 1) % 3]];
      if (!hasMidpoint(a, b)) continue;
      ++sidesWithCorners;
      const std::uint32_t middle = midpointOfPoints(a, b);
      if (hasMidpoint(a, middle) || hasMidpoint(middle, b)) return true;
    }
    return sidesWithCorners == 3;
  }

  void cutWhereNeighboursAreFiner() {
    for (bool cutAny = true; cutAny;) {
      cutAny = false;
      for (std::size_t n = 0; n < nodes_.size(); ++n)
        if (!nodes_[n].cut && meetsTooFine(nodes_[n].element)) {
          cut(n);
          cutAny = true;
        }
    }
  }

  // An element's faces: itself, or the triangles ending at the new corners
  // on its sides, turned so that the side without one is the last.
  void addFaces(const Node& node) {
    const std::array<int, 3>& v = node.element.vertices;
    std::array<bool, 3> cornered{};
    for (int k = 0; k < 3; ++k) cornered[k] = hasMidpoint(pointOf_[v[k]], pointOf_[v[(k + 1) % 3]]);
    const SceneFace& from = faces_[node.face];
    const auto add = [&](int a, int b, int c) {
      mesh_.triangles.faces.push_back(
          {{a, b, c}, from.shape, from.primitive, from.material, false});
    };
    const int count = cornered[0] + cornered[1] + cornered[2];
    if (count == 0) return add(v[0], v[1], v[2]);
    int k = 0;
    if (count == 1)
      while (!cornered[k]) ++k;
    else
      while (cornered[(k + 2) % 3]) ++k;
    const int a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
    const int ab = midpointOfVertices(a, b);
    if (count == 1) {
      add(a, ab, c);
      return add(ab, b, c);
    }
    const int bc = midpointOfVertices(b, c);
    add(ab, b, bc);
    add(a, ab, bc);
    add(a, bc, c);
  }

  void keepTheLeaves() {
    mesh_.elements.clear();
    mesh_.triangles.faces.clear();
    patches_.patchOf.clear();
    for (Patch& patch : patches_.patches) patch.elements.clear();
    for (const Node& node : nodes_) {
      if (node.cut) continue;
      patches_.patches[node.patch].elements.push_back(static_cast<int>(mesh_.elements.size()));
      patches_.patchOf.push_back(node.patch);
      mesh_.elements.push_back(node.element);
      addFaces(node);
    }
  }

  ElementMesh& mesh_;
  PatchMesh& patches_;
  const DirectLight& light_;
  const Workers& workers_;
  float smallestSide_;
  std::vector<SceneFace> faces_;        // the faces the elements were cut from
  std::vector<std::uint32_t> pointOf_;  // by vertex: its point, vertices at one place welded
  std::uint32_t points_ = 0;
  std::unordered_map<std::uint64_t, std::uint32_t> pointBetween_;
  std::unordered_map<std::uint64_t, int> vertexBetween_;
  std::vector<Node> nodes_;
  float brightest_ = 0.0f;
  RefinementCounts counts_;
};

}  // namespace

RefinementCounts refineWhereTheLightChanges(RadiosityMesh& mesh, const DirectLight& light,
                                            const Workers& workers) {
  return Refiner(mesh, light, workers).refine();
}

}  // namespace rise
