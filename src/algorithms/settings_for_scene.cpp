#include "algorithms/settings_for_scene.hpp"

#include <cmath>
#include <string>

#include "core/parallel.hpp"
#include "core/text.hpp"
#include "ray/accelerator.hpp"

namespace rise {
namespace {

// The image size: the scene's, unless overridden; a single dimension keeps
// the scene's aspect ratio.
std::pair<int, int> imageSize(const ImageOverrides& image, const ImageSpec& scene) {
  const double aspect = static_cast<double>(scene.width) / scene.height;
  if (image.width && image.height) return {*image.width, *image.height};
  if (image.width)
    return {*image.width, std::max(1, static_cast<int>(std::lround(*image.width / aspect)))};
  if (image.height)
    return {std::max(1, static_cast<int>(std::lround(*image.height * aspect))), *image.height};
  return {scene.width, scene.height};
}

PixelSampling pixelSampling(const ImageOverrides& image, const PixelSampling& scene) {
  PixelSampling sampling = chooseSampling(scene, image.samples, image.pattern);
  if (image.filter) sampling.filter = *image.filter;
  if (image.adaptiveThreshold) sampling.adaptiveThreshold = *image.adaptiveThreshold;
  return sampling;
}

std::string availableAccelNames() {
  std::string names;
  for (Accel accel : availableAccels()) appendListed(names, ", ", accelName(accel));
  return names;
}

}  // namespace

RenderSettings settingsFor(const Scene& scene, const RenderRequest& request) {
  RenderSettings settings = request.settings;
  if (!isAvailable(settings.accel))
    throw SettingsError("--accel " + std::string(accelName(settings.accel)) +
                        ": this build has no such structure (Embree was not found when it was "
                        "built); available: " +
                        availableAccelNames());
  std::tie(settings.width, settings.height) = imageSize(request.image, scene.image);
  if (settings.width > kLargestImageSide || settings.height > kLargestImageSide)
    throw SettingsError("an image of " + std::to_string(settings.width) + " x " +
                        std::to_string(settings.height) + " pixels; expected at most " +
                        std::to_string(kLargestImageSide) + " pixels a side (--width, --height)");
  settings.sampling = pixelSampling(request.image, scene.image.sampling);
  // A path tracer's single sample is noise: it takes the samples asked for,
  // or its own count but no fewer than the scene's.
  settings.progression.samples = request.image.samples.value_or(
      std::max(settings.progression.samples, scene.image.sampling.samples));
  if (std::string problem = samplingProblem(settings.sampling); !problem.empty())
    throw SettingsError(problem);
  if (const std::optional<PixelRect>& region = settings.region;
      region && (region->isEmpty() || region->x0 < 0 || region->y0 < 0 ||
                 region->x1 > settings.width || region->y1 > settings.height))
    throw SettingsError("--tile " + std::to_string(region->x0) + "," + std::to_string(region->y0) +
                        "," + std::to_string(region->width()) + "," +
                        std::to_string(region->height()) +
                        ": expected a region X,Y,W,H of at least one pixel within the " +
                        std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                        " image: W, H >= 1, X + W <= " + std::to_string(settings.width) +
                        ", Y + H <= " + std::to_string(settings.height));
  settings.threads = resolveThreadCount(settings.threads);
  return settings;
}

}  // namespace rise
