#include "ray/bvh.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <thread>

#include "ray/brute_force.hpp"
#include "scene/shapes/plane.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/triangle_mesh.hpp"

namespace rise {
namespace {

std::unique_ptr<Shape> randomTriangles(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
  std::uniform_real_distribution<float> offset(-0.5f, 0.5f);
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < count; ++i) {
    const Vec3 centre(coordinate(random), coordinate(random), coordinate(random));
    for (int corner = 0; corner < 3; ++corner)
      vertices.push_back(centre + Vec3(offset(random), offset(random), offset(random)));
    faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return std::make_unique<TriangleMesh>(std::move(vertices), std::move(faces), 0);
}

bool contains(const Bounds3& outer, const Bounds3& inner) {
  return glm::all(glm::lessThanEqual(outer.min, inner.min)) &&
         glm::all(glm::lessThanEqual(inner.max, outer.max));
}

using Appearances = std::map<std::pair<std::uint32_t, std::uint32_t>, int>;

void checkLeaf(const Bvh& bvh, const Bounds3& box, std::uint32_t first, std::uint32_t count,
               const std::vector<std::unique_ptr<Shape>>& shapes, Appearances& appearances) {
  EXPECT_LE(count, 8u) << "a leaf of more primitives than kMaxLeafSize";
  ASSERT_LE(first + count, bvh.primitives().size());
  for (std::uint32_t i = first; i < first + count; ++i) {
    const PrimitiveRef& ref = bvh.primitives()[i].ref;
    ++appearances[{ref.shape, ref.primitive}];
    EXPECT_TRUE(contains(box, shapes[ref.shape]->primitiveBounds(ref.primitive)));
  }
}

// Walks the tree from the root, building the subtrees left unbuilt,
// checking every node's children against theirs and counting how often each
// primitive appears in a leaf. Only a root, the tree's or a subtree's, may
// have fewer than two children (one, a leaf, for a tiny scene or subtree),
// and the filled slots come first.
void checkSubtree(const Bvh& bvh, std::uint32_t index, bool isRoot, int depth,
                  const std::vector<std::unique_ptr<Shape>>& shapes, Appearances& appearances) {
  ASSERT_LE(depth, kMaxBvhDepth);
  ASSERT_LT(index, bvh.nodes().size());
  const WideBvhNode& node = bvh.nodes()[index];
  const int children = node.childCount();
  EXPECT_GE(children, isRoot ? 1 : 2);
  for (int child = 0; child < kWideBvhWidth; ++child) {
    const Bounds3 box = node.childBox(child);
    if (child >= children) {
      EXPECT_TRUE(box.isEmpty());
      continue;
    }
    if (node.primitiveCount[child] > 0 && node.primitiveCount[child] != kUnbuiltSubtree) {
      checkLeaf(bvh, box, node.offset[child], node.primitiveCount[child], shapes, appearances);
      continue;
    }
    const bool unbuilt = node.primitiveCount[child] == kUnbuiltSubtree;
    const std::uint32_t childIndex =
        unbuilt ? bvh.subtreeRoot(node.offset[child]) : node.offset[child];
    ASSERT_LT(childIndex, bvh.nodes().size());
    const WideBvhNode& inner = bvh.nodes()[childIndex];
    for (int grandchild = 0; grandchild < inner.childCount(); ++grandchild)
      EXPECT_TRUE(contains(box, inner.childBox(grandchild)));
    checkSubtree(bvh, childIndex, unbuilt, depth + 1, shapes, appearances);
  }
}

void checkInvariants(const std::vector<std::unique_ptr<Shape>>& shapes, int threads) {
  const Bvh bvh(shapes, threads);
  Appearances appearances;
  checkSubtree(bvh, 0, true, 1, shapes, appearances);
  int bounded = 0;
  for (std::size_t shape = 0; shape < shapes.size(); ++shape) {
    if (!shapes[shape]->bounds().isFinite()) continue;
    for (int primitive = 0; primitive < shapes[shape]->primitiveCount(); ++primitive) {
      ++bounded;
      EXPECT_EQ(
          (appearances[{static_cast<std::uint32_t>(shape), static_cast<std::uint32_t>(primitive)}]),
          1)
          << "shape " << shape << " primitive " << primitive;
    }
  }
  EXPECT_EQ(appearances.size(), static_cast<std::size_t>(bounded));
  EXPECT_EQ(bvh.primitives().size(), static_cast<std::size_t>(bounded));
}

TEST(Bvh, HoldsEveryPrimitiveInExactlyOneLeafInsideEveryBoxAbove) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 0));
  shapes.push_back(randomTriangles(5000, 1));
  shapes.push_back(std::make_unique<Sphere>(Vec3(1.0f, 2.0f, 3.0f), 0.5f, 0));
  shapes.push_back(randomTriangles(100, 2));
  checkInvariants(shapes, 1);
}

TEST(Bvh, BuiltOnManyThreadsKeepsItsInvariants) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(randomTriangles(100000, 3));
  checkInvariants(shapes, 4);
}

// Triangles whose boxes all have the same centre give the bins nothing to
// separate: they are split in halves, down to small leaves (which
// checkInvariants checks).
TEST(Bvh, SplitsPrimitivesThatShareOneCentre) {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < 100; ++i) {
    const float size = 1.0f + 0.01f * static_cast<float>(i);
    vertices.insert(
        vertices.end(),
        {{-size, -size, 0.0f}, {size, -size, 0.0f}, {size, size, 0.0f}, {-size, size, 0.0f}});
    faces.push_back({4 * i, 4 * i + 1, 4 * i + 2});
    faces.push_back({4 * i + 2, 4 * i + 3, 4 * i});
  }
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::make_unique<TriangleMesh>(std::move(vertices), std::move(faces), 0));
  checkInvariants(shapes, 1);
}

TEST(Bvh, OfOnlyUnboundedShapesIsEmpty) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::make_unique<Plane>(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 0));
  const Bvh bvh(shapes);
  EXPECT_TRUE(bvh.nodes().empty());
  Hit hit;
  IntersectionCounters counters;
  ASSERT_TRUE(bvh.nearest(Ray{{0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, 0.0f, hit, counters));
  EXPECT_EQ(hit.t, 1.0f);
}

// The tree's point: a ray through 5000 scattered triangles tests a few of
// them, not all.
TEST(Bvh, TestsFewPrimitivesAndCountsTheBoxes) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(randomTriangles(5000, 4));
  const Bvh bvh(shapes);
  IntersectionCounters counters;
  Hit hit;
  bvh.nearest(Ray{{-20.0f, 0.3f, 0.2f}, {1.0f, 0.0f, 0.0f}}, 0.0f, hit, counters);
  EXPECT_LT(counters.tests, 200u);
  EXPECT_GT(counters.nodesVisited, 0u);
}

Stats statsOf(const Bvh& bvh) {
  Stats stats;
  bvh.addStats(stats);
  return stats;
}

// A ray from a random point of a cube of side 40 about the triangles, towards
// another.
Ray randomRay(std::mt19937& random) {
  std::uniform_real_distribution<float> coordinate(-20.0f, 20.0f);
  const Vec3 from(coordinate(random), coordinate(random), coordinate(random));
  const Vec3 to(coordinate(random), coordinate(random), coordinate(random));
  return Ray{from, glm::normalize(to - from)};
}

// A square of side 20 in the plane y = 0, centred on the origin, cut into
// cells of two triangles, `cells` a side.
std::unique_ptr<Shape> floorGrid(int cells) {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  const float side = 20.0f / static_cast<float>(cells);
  for (int row = 0; row <= cells; ++row)
    for (int column = 0; column <= cells; ++column)
      vertices.emplace_back(side * static_cast<float>(column) - 10.0f, 0.0f,
                            side * static_cast<float>(row) - 10.0f);
  for (int row = 0; row < cells; ++row)
    for (int column = 0; column < cells; ++column) {
      const int corner = row * (cells + 1) + column;
      faces.push_back({corner, corner + cells + 1, corner + 1});
      faces.push_back({corner + 1, corner + cells + 1, corner + cells + 2});
    }
  return std::make_unique<TriangleMesh>(std::move(vertices), std::move(faces), 0);
}

// The point of leaving subtrees unbuilt: a ray builds those it enters, a
// few of many, and finds what brute force finds.
TEST(Bvh, BuildsOnlyTheSubtreesItsRaysEnter) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(floorGrid(224));  // 100,352 triangles
  const Bvh bvh(shapes, 2);
  const double deferred = statsOf(bvh).value("bvh_subtrees_deferred");
  EXPECT_GT(deferred, 10.0);
  EXPECT_EQ(statsOf(bvh).value("bvh_subtrees_built"), 0.0);

  const Ray ray{{0.3f, 5.0f, 0.2f}, {0.0f, -1.0f, 0.0f}};
  Hit hit, expected;
  IntersectionCounters counters;
  ASSERT_TRUE(bvh.nearest(ray, 0.0f, hit, counters));
  ASSERT_TRUE(BruteForce(shapes).nearest(ray, 0.0f, expected, counters));
  EXPECT_EQ(hit.t, expected.t);
  EXPECT_EQ(hit.primitive, expected.primitive);
  const double built = statsOf(bvh).value("bvh_subtrees_built");
  EXPECT_GE(built, 1.0);
  EXPECT_LE(built, 2.0);

  bvh.buildEverySubtree(3);
  EXPECT_EQ(statsOf(bvh).value("bvh_subtrees_built"), deferred);
}

// Rays on many threads reach the same unbuilt subtrees at once: one thread
// builds each, and every ray, alone or in a packet, finds what brute force
// finds.
TEST(Bvh, RaysOnManyThreadsBuildItAsTheyGo) {
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(randomTriangles(50000, 6));
  const Bvh bvh(shapes, 2);
  const BruteForce bruteForce(shapes);
  constexpr int kThreads = 8;
  constexpr int kPackets = 100;
  std::vector<int> mismatches(kThreads, 0);
  std::vector<std::thread> threads;
  for (int thread = 0; thread < kThreads; ++thread)
    threads.emplace_back([&, thread] {
      std::mt19937 random(static_cast<unsigned>(thread));
      for (int packetIndex = 0; packetIndex < kPackets; ++packetIndex) {
        RayPacket packet;
        packet.size = kPacketSize;
        for (Ray& ray : packet.rays) ray = randomRay(random);
        bvh.nearestOfPacket(packet, 0.0f);
        for (int lane = 0; lane < kPacketSize; ++lane) {
          Hit alone, expected;
          IntersectionCounters counters;
          const bool found = bvh.nearest(packet.rays[lane], 0.0f, alone, counters);
          const bool expectedFound =
              bruteForce.nearest(packet.rays[lane], 0.0f, expected, counters);
          if (found != expectedFound || packet.found[lane] != expectedFound ||
              alone.t != expected.t || packet.hits[lane].t != expected.t)
            ++mismatches[thread];
        }
      }
    });
  for (std::thread& thread : threads) thread.join();
  for (int thread = 0; thread < kThreads; ++thread)
    EXPECT_EQ(mismatches[thread], 0) << "thread " << thread;
  EXPECT_GT(statsOf(bvh).value("bvh_subtrees_built"), 0.0);
}

}  // namespace
}  // namespace rise
