// Times a frame of RISE's visible-surface algorithms as the OSMesa program
// times OpenGL's: the scene's shapes are tessellated once, as OpenGL is given
// its vertex buffers once, and each frame then transforms, culls, clips and
// projects them, resolves visibility, and shades every pixel (with the
// depth, normal, face and cost buffers filled as well).
//
// usage: rise_raster_bench SCENE.yaml ALGORITHM SHADING THREADS FRAMES
// Prints the tessellation's time and the best and mean frame times.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include "algorithms/registry.hpp"
#include "io/scene_file.hpp"
#include "raster/visible_surface_renderer.hpp"

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rise;
  if (argc != 6) {
    std::cerr << "usage: rise_raster_bench SCENE.yaml ALGORITHM SHADING THREADS FRAMES\n";
    return 2;
  }
  const std::map<std::string, Shading> shadings = {
      {"flat", Shading::Flat}, {"gouraud", Shading::Gouraud}, {"phong", Shading::Phong}};
  const auto* renderer = dynamic_cast<const VisibleSurfaceRenderer*>(findRenderer(argv[2]));
  if (renderer == nullptr || !shadings.contains(argv[3])) {
    std::cerr << "rise_raster_bench: no visible-surface algorithm '" << argv[2]
              << "' or no shading '" << argv[3] << "'\n";
    return 2;
  }
  const Scene scene = loadSceneFile(argv[1]);
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.shading = shadings.at(argv[3]);
  settings.threads = std::atoi(argv[4]);
  const int frames = std::atoi(argv[5]);

  const auto start = std::chrono::steady_clock::now();
  const TessellatedScene tessellated = tessellateForRaster(scene, settings);
  std::cout << "tessellation_seconds " << secondsSince(start) << "\n";
  RenderObserver observer;
  double best = 1e30, total = 0.0;
  for (int frame = 0; frame < frames; ++frame) {
    const auto frameStart = std::chrono::steady_clock::now();
    renderer->renderSample(scene, tessellated, settings, AccumulationPass{}, observer);
    const double seconds = secondsSince(frameStart);
    best = std::min(best, seconds);
    total += seconds;
  }
  std::cout << "best_seconds " << best << "\nmean_seconds " << total / frames << "\n";
  return 0;
}
