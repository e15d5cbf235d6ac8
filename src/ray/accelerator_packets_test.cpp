// Every acceleration structure finds, for each ray of a packet, what it finds
// for the ray alone, to the bit: the nearest hit of a packet of primary rays,
// the light a packet of shadow rays lets through.
#include <gtest/gtest.h>

#include <array>
#include <limits>

#include "ray/accelerator.hpp"
#include "ray/scene_intersector.hpp"
#include "support/random_scene_testing.hpp"

namespace rise {
namespace {

using namespace random_scene_testing;

// How the packets of the two tests below are made: of every size in turn,
// every other one coherent, every third from a tMin above zero.
struct PacketPlan {
  int size;
  bool coherent;
  float tMin;
};
PacketPlan packetPlan(int packet, RandomScene& rays, float largestTMin) {
  return {1 + packet % kPacketSize, packet % 2 == 0,
          packet % 3 == 0 ? rays.uniform(0.0f, largestTMin) : 0.0f};
}

// Packets of every size: coherent ones (rays from one point to neighbouring
// points, as a row of pixels' primary rays) and scattered ones, with rays
// ended early and rays of non-finite components among them. Each ray of a
// packet finds what it finds alone, to the bit: what brute force finds
// (above).
TEST(Accelerators, FindEachRayOfAPacketsNearestHit) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  forEachSceneAndStructure(3000, [&](const Scene& scene, int seed, Accel accel, RandomScene& rays) {
    const auto structure = buildAccelerator(accel, scene.shapes);
    int hits = 0;
    for (int i = 0; i < kRaysPerScene / kPacketSize; ++i) {
      const PacketPlan plan = packetPlan(i, rays, 0.3f);
      const Vec3 eye = rays.point(7.0f), aim = rays.point(4.0f);
      RayPacket packet;
      packet.size = plan.size;
      for (int lane = 0; lane < packet.size; ++lane) {
        packet.rays[lane] = plan.coherent
                                ? Ray{eye, aim + 0.05f * Vec3(lane % 4, lane / 4, 0) - eye, 0.5f}
                                : rays.ray();
        if (i % 7 == 0 && lane == 2) packet.rays[lane].direction.y = nan;
        packet.hits[lane].t = lane % 3 == 1 ? rays.uniform(0.2f, 1.0f) : kInfinity;
      }
      const RayPacket given = packet;
      structure->nearestOfPacket(packet, plan.tMin);
      for (int lane = 0; lane < packet.size; ++lane) {
        Hit expected = given.hits[lane];
        IntersectionCounters counters;
        const bool found = structure->nearest(given.rays[lane], plan.tMin, expected, counters);
        ASSERT_EQ(packet.found[lane], found)
            << accelName(accel) << ", scene " << seed << ", packet " << i << ", lane " << lane;
        if (!found) continue;
        ++hits;
        const Hit& actual = packet.hits[lane];
        ASSERT_EQ(actual.t, expected.t) << accelName(accel) << ", packet " << i;
        ASSERT_EQ(actual.shape, expected.shape) << accelName(accel) << ", packet " << i;
        // A shape records only what it needs (a sphere leaves the rest as it found it).
        if (expected.shape->primitiveCount() > 1) {
          EXPECT_EQ(actual.primitive, expected.primitive) << accelName(accel) << ", packet " << i;
          EXPECT_EQ(actual.barycentric, expected.barycentric) << accelName(accel);
        }
      }
    }
    EXPECT_GT(hits, kRaysPerScene / 6) << accelName(accel);
  });
}

// Packets of shadow rays of every size: coherent ones (from neighbouring
// points towards one light) and scattered ones, of different lengths, with
// rays of non-finite components among them. Each ray of a packet lets
// through what it lets through alone, to the bit, and its tests are its own.
TEST(Accelerators, LetThroughEachRayOfAPacketsLightAsAlone) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  forEachSceneAndStructure(4000, [&](const Scene& scene, int seed, Accel accel, RandomScene& rays) {
    const SceneIntersector intersector(scene, accel);
    int shadowed = 0;
    int filtered = 0;
    for (int i = 0; i < kRaysPerScene / kPacketSize; ++i) {
      const PacketPlan plan = packetPlan(i, rays, 0.1f);
      const Vec3 start = rays.point(4.0f), light = rays.point(7.0f);
      ShadowRayPacket packet;
      packet.size = plan.size;
      for (int lane = 0; lane < packet.size; ++lane) {
        const Vec3 from = start + 0.05f * Vec3(lane % 4, lane / 4, 0);
        packet.rays[lane] = plan.coherent ? Ray{from, light - from, 0.5f} : rays.ray();
        if (i % 7 == 0 && lane == 2) packet.rays[lane].origin.x = nan;
        packet.tMax[lane] = plan.coherent && lane % 3 != 1 ? 1.0f : rays.uniform(0.2f, 1.2f);
      }
      const ShadowRayPacket given = packet;
      const std::array<Color, kPacketSize> through =
          intersector.transmittanceOfPacket(packet, plan.tMin);
      for (int lane = 0; lane < packet.size; ++lane) {
        IntersectionCounters alone;
        const Color expected =
            intersector.transmittance(given.rays[lane], plan.tMin, given.tMax[lane], alone);
        ASSERT_EQ(through[lane], expected)
            << accelName(accel) << ", scene " << seed << ", packet " << i << ", lane " << lane;
        EXPECT_EQ(packet.costs[lane].tests > 0, alone.tests > 0) << accelName(accel);
        if (expected == Color(0.0f)) ++shadowed;
        if (expected != Color(0.0f) && expected != Color(1.0f)) ++filtered;
      }
    }
    EXPECT_GT(shadowed, kRaysPerScene / 10) << accelName(accel);
    EXPECT_GT(filtered, kRaysPerScene / 40) << accelName(accel);
  });
}

}  // namespace
}  // namespace rise
