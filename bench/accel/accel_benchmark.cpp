// How the cost of a ray grows with the size of the mesh, for each
// acceleration structure; how long the BVH (the whole tree, every subtree a
// render leaves to its rays built too) and Embree take to build; and how
// RISE's BVH compares with Embree on the same mesh, camera and rays.
//
// Every ray is traced on one thread, so that rays per second compare the
// structures, not the cores. Run through bench/accel/run.sh, which prints
// the tables of bench/README.md.
#include <benchmark/benchmark.h>

#include <map>
#include <thread>

#include "bench_meshes.hpp"
#include "ray/accelerator.hpp"
#include "ray/bvh.hpp"

namespace rise::bench {
namespace {

constexpr int kImageSize = 256;  // 65,536 primary rays
// Brute force tests every triangle for every ray, and so does a bounding
// sphere around the one mesh for every ray that meets it: beyond this many
// triangles, one pass over the rays takes minutes.
constexpr int kBruteForceLimit = 6000;

struct TestMesh {
  std::string name;
  std::vector<std::unique_ptr<Shape>> shapes;  // the mesh alone
  std::vector<Ray> rays;
  int triangles = 0;
};

TestMesh makeTestMesh(std::string name, std::unique_ptr<Shape> mesh) {
  TestMesh test{
      std::move(name), {}, cameraRays(*mesh, kImageSize, kImageSize), mesh->primitiveCount()};
  test.shapes.push_back(std::move(mesh));
  return test;
}

// Made once, the first time a benchmark asks: the largest take seconds.
const TestMesh& testMesh(const std::string& name) {
  static std::map<std::string, TestMesh> meshes;
  if (auto found = meshes.find(name); found != meshes.end()) return found->second;
  std::unique_ptr<Shape> mesh = name == "bunny"
                                    ? stanfordBunny()
                                    : bumpyIcosphere(std::stoi(name.substr(name.find('_') + 1)));
  return meshes.emplace(name, makeTestMesh(name, std::move(mesh))).first->second;
}

void tracePrimaryRays(benchmark::State& state, Accel accel, const std::string& meshName) {
  const TestMesh& mesh = testMesh(meshName);
  const auto structure = buildAccelerator(accel, mesh.shapes);
  IntersectionCounters counters;
  // A pass untimed, so that the rays are timed, not the BVH's subtrees that
  // the first of them build.
  for (const Ray& ray : mesh.rays) {
    Hit hit;
    structure->nearest(ray, 0.0f, hit, counters);
  }
  counters = {};
  std::int64_t hits = 0;
  for (auto _ : state) {
    for (const Ray& ray : mesh.rays) {
      Hit hit;
      hits += structure->nearest(ray, 0.0f, hit, counters) ? 1 : 0;
    }
  }
  const auto rays = static_cast<double>(state.iterations()) * static_cast<double>(mesh.rays.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(rays));
  state.counters["triangles"] = mesh.triangles;
  state.counters["rays_per_second"] = benchmark::Counter(rays, benchmark::Counter::kIsRate);
  state.counters["tests_per_ray"] = static_cast<double>(counters.tests) / rays;
  state.counters["nodes_per_ray"] = static_cast<double>(counters.nodesVisited) / rays;
  state.counters["hit_fraction"] = static_cast<double>(hits) / rays;
}

void buildStructure(benchmark::State& state, Accel accel, const std::string& meshName,
                    int threads) {
  const TestMesh& mesh = testMesh(meshName);
  for (auto _ : state) {
    if (accel == Accel::Bvh)
      Bvh(mesh.shapes, threads).buildEverySubtree(threads);
    else
      benchmark::DoNotOptimize(buildAccelerator(accel, mesh.shapes));
  }
  state.counters["triangles"] = mesh.triangles;
  state.counters["threads"] = threads;
}

// icosphere_3 has 1,280 triangles, each level four times more, up to
// icosphere_8's 1,310,720; the bunny has 69,451.
void registerBenchmarks() {
  std::vector<std::string> meshes;
  for (int subdivisions = 3; subdivisions <= 8; ++subdivisions)
    meshes.push_back("icosphere_" + std::to_string(subdivisions));
  meshes.push_back("bunny");
  for (const std::string& mesh : meshes) {
    const int triangles = mesh == "bunny" ? 69451 : 20 << (2 * std::stoi(mesh.substr(10)));
    for (Accel accel : availableAccels()) {
      const bool testsEveryTriangle = accel == Accel::None || accel == Accel::Spheres;
      if (testsEveryTriangle && triangles > kBruteForceLimit) continue;
      benchmark::RegisterBenchmark(
          ("primary_rays/" + std::string(accelName(accel)) + "/" + mesh).c_str(),
          [accel, mesh](benchmark::State& state) { tracePrimaryRays(state, accel, mesh); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (const std::string mesh : {"bunny", "icosphere_8"}) {
    for (int threads : {1, cores}) {
      benchmark::RegisterBenchmark(
          ("build/bvh/" + mesh + "/threads:" + std::to_string(threads)).c_str(),
          [mesh, threads](benchmark::State& state) {
            buildStructure(state, Accel::Bvh, mesh, threads);
          })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
    if (isAvailable(Accel::Embree)) {
      benchmark::RegisterBenchmark(("build/embree/" + mesh).c_str(),
                                   [mesh, cores](benchmark::State& state) {
                                     buildStructure(state, Accel::Embree, mesh, cores);
                                   })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
}

}  // namespace
}  // namespace rise::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  rise::bench::registerBenchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
