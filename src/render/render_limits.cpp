#include "render/render_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/memory_budget.hpp"
#include "core/text.hpp"

namespace rise {
namespace {

// A primitive in the acceleration structure or as polygons on the screen.
constexpr std::uint64_t kBytesPerPrimitive = 256;

// The offsets and the other dimensions of a pixel's samples, in each thread.
std::uint64_t bytesPerSample(const Scene& scene, const RenderSettings& settings) {
  return 64 + 8 * (scene.lights.size() + 2 * static_cast<std::uint64_t>(settings.maxDepth));
}

std::uint64_t pixelsOf(const RenderSettings& settings) {
  return static_cast<std::uint64_t>(settings.width) * static_cast<std::uint64_t>(settings.height);
}

std::uint64_t primitives(const Scene& scene) {
  std::uint64_t count = 0;
  for (const auto& shape : scene.shapes)
    count += static_cast<std::uint64_t>(shape->primitiveCount());
  return count;
}

// The first material that both reflects and refracts: its rays branch in two.
const Material* branchingMaterial(const Scene& scene) {
  const auto branching =
      std::find_if(scene.materials.begin(), scene.materials.end(), [](const Material& material) {
        return material.reflection > 0 && material.transmission > 0;
      });
  return branching == scene.materials.end() ? nullptr : &*branching;
}

double raysPerSample(const Scene& scene, const RenderSettings& settings) {
  const double hits = branchingMaterial(scene) ? std::exp2(settings.maxDepth) - 1.0
                                               : static_cast<double>(settings.maxDepth);
  return hits * (1.0 + static_cast<double>(scene.lights.size()));
}

// "640", "1.8e19".
std::string count(double value) {
  char text[32];
  std::snprintf(text, sizeof text, value < 1e6 ? "%.0f" : "%.2g", value);
  std::string written = text;
  if (const std::size_t plus = written.find("e+"); plus != std::string::npos)
    written.erase(plus + 1, 1);
  return written;
}

std::string samplesAPixel(const RenderSettings& settings) {
  const int samples = settings.sampling.samples;
  return counted(static_cast<std::uint64_t>(samples), "sample") + " a pixel";
}

}  // namespace

RenderNeeds memoryNeeds(const Scene& scene, const RenderSettings& settings,
                        std::uint64_t bytesPerPixel) {
  const auto samples = static_cast<std::uint64_t>(settings.sampling.samples);
  const auto threads = static_cast<std::uint64_t>(std::max(1, settings.threads));
  return {pixelsOf(settings) * bytesPerPixel +
              samples * bytesPerSample(scene, settings) * (threads + 1) +
              primitives(scene) * kBytesPerPrimitive,
          0.0};
}

double recursionRays(const Scene& scene, const RenderSettings& settings) {
  return static_cast<double>(pixelsOf(settings)) * static_cast<double>(settings.sampling.samples) *
         raysPerSample(scene, settings);
}

void checkRenderFits(const Scene& scene, const RenderSettings& settings, const Renderer& renderer) {
  if (settings.threads > kMostThreads)
    throw RenderLimitError("--threads " + std::to_string(settings.threads) + ": expected at most " +
                           std::to_string(kMostThreads) + " threads");
  const RenderNeeds needs = renderer.needs(scene, settings);
  std::string why;
  const std::uint64_t budget = memoryBudget(&why);
  if (needs.bytes > budget)
    throw RenderLimitError(
        "a " + std::to_string(settings.width) + " x " + std::to_string(settings.height) +
        " image with " + samplesAPixel(settings) + " needs about " +
        gigabytes(static_cast<double>(needs.bytes)) + " to render, more than the " +
        gigabytes(static_cast<double>(budget)) + " it may take (" + why + ")" +
        (needs.mostOfTheMemory.empty()
             ? "; expected a smaller image (--width, --height or the scene's 'width' and "
               "'height')"
             : ", most of it for " + needs.mostOfTheMemory + "; expected " + needs.toTakeLess));
  if (needs.rays > kMostRays) {
    const Material* branching = needs.raysBranch ? branchingMaterial(scene) : nullptr;
    throw RenderLimitError(
        "a " + std::to_string(settings.width) + " x " + std::to_string(settings.height) +
        " image with " + samplesAPixel(settings) + " and --max-depth " +
        std::to_string(settings.maxDepth) + " may trace up to " + count(needs.rays) + " rays (" +
        count(needs.rays /
              static_cast<double>(pixelsOf(settings) *
                                  static_cast<std::uint64_t>(settings.sampling.samples))) +
        " a sample" +
        (branching ? ", as material '" + branching->name + "' both reflects and refracts" : "") +
        "); expected at most " + count(kMostRays) +
        " rays: fewer samples, a smaller image or a lower --max-depth");
  }
}

void checkWorkingMemoryFits(std::uint64_t bytes, const std::string& what,
                            const std::string& instead) {
  if (const std::optional<std::string> problem = memoryProblem(bytes, what))
    throw RenderLimitError(*problem + "; expected " + instead);
}

}  // namespace rise
