// The texture filters of the visible-surface algorithms against a reference
// that filters by brute force: the ray tracer with 64 samples a pixel, each
// reading the texture bilinearly, averaged over the pixel. Where the
// coordinates turn fast (the centre of a cylinder's cap, where u converges)
// or jump (the seam where u runs from 1 back to 0), the footprint must follow
// them; where the footprint is long and thin (a floor at a grazing angle),
// the summed-area table and the elliptical average must stay closer to the
// reference than the trilinear mipmap, which blurs across it.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "scene/shapes/convex_polygon.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/mapped_shape.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/transform.hpp"
#include "support/image_agreement_testing.hpp"

namespace rise {
namespace {

using namespace image_agreement_testing;

constexpr TextureFilter kFootprintFilters[] = {TextureFilter::Trilinear, TextureFilter::SummedArea,
                                               TextureFilter::EllipticalAverage};

std::string nameOf(TextureFilter filter) {
  return filter == TextureFilter::Trilinear    ? "trilinear"
         : filter == TextureFilter::SummedArea ? "summed-area"
                                               : "elliptical";
}

// A globe's worth of texture, 256 x 128: white polar bands 16 texels deep
// at the top and bottom, between them stripes of three colours 16 texels
// wide (16 of them, so that u = 0 and 1 meet at a seam of colour) crossed by
// darker rows: a level too coarse, or a footprint too long, mixes colours a
// pixel should not show.
std::shared_ptr<const Image> bandedStripes() {
  auto image = std::make_shared<Image>(256, 128);
  const Color stripes[] = {
      {0.9f, 0.2f, 0.1f}, {0.1f, 0.6f, 0.2f}, {0.1f, 0.2f, 0.8f}, {0.9f, 0.8f, 0.1f}};
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x)
      image->at(x, y) =
          y < 16 || y >= 112 ? Color(1.0f) : stripes[(x / 8) % 4] * ((y / 4) % 2 ? 1.0f : 0.4f);
  return image;
}

// One textured shape under ambient light alone, so that each pixel is the
// texture filtered over it.
Scene sceneOf(std::unique_ptr<Shape> shape, TextureFilter filter, const Vec3& eye,
              const Vec3& target, int width, int height) {
  Scene scene;
  scene.image.width = width;
  scene.image.height = height;
  scene.camera.position = eye;
  scene.camera.lookAt = target;
  scene.camera.fovDegrees = 40.0f;
  scene.ambient = Color(1.0f);
  Material material;
  material.ka = 1.0f;
  material.kd = 0.0f;
  material.texture = std::make_shared<ImageTexture>(bandedStripes(), filter);
  scene.materials.push_back(material);
  scene.shapes.push_back(std::move(shape));
  return scene;
}

RenderSettings settingsFor(const Scene& scene, int samples) {
  RenderSettings settings;
  settings.width = scene.image.width;
  settings.height = scene.image.height;
  settings.threads = 2;
  settings.sampling.samples = samples;
  settings.sampling.pattern = samples > 1 ? SamplePattern::Jittered : SamplePattern::None;
  return settings;
}

// The mean and the largest difference, in levels, over the pixels where the
// primary ray meets the surface where `inRegion` says (by its texture
// coordinates and normal there).
struct RegionError {
  double meanLevels = 0.0;
  int worstLevels = 0;
  int pixels = 0;
};

// The surface the primary ray through a raster point meets, if any.
std::optional<SurfacePoint> surfaceSeen(const Scene& scene, const ViewFrame& view, float x,
                                        float y) {
  const Ray ray = view.primaryRay(x, y);
  Hit hit;
  IntersectionCounters counters;
  if (!scene.shapes[0]->intersect(ray, 0.0f, hit, counters)) return std::nullopt;
  return scene.shapes[0]->surfaceAt(ray, hit);
}

// Over the pixels whose centres, and their neighbours' a pixel away, all
// see the region: away from its edges, where a pixel may see the region in
// one image and not in the other.
RegionError errorOver(const Scene& scene, const Image& drawn, const Image& reference,
                      const std::function<bool(const SurfacePoint&)>& inRegion) {
  const ViewFrame view(scene.camera, drawn.width(), drawn.height());
  RegionError error;
  for (int y = 0; y < drawn.height(); ++y)
    for (int x = 0; x < drawn.width(); ++x) {
      bool inside = true;
      for (const Vec2 offset : {Vec2(0, 0), Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)}) {
        const auto surface = surfaceSeen(scene, view, static_cast<float>(x) + 0.5f + offset.x,
                                         static_cast<float>(y) + 0.5f + offset.y);
        inside = inside && surface && inRegion(*surface);
      }
      if (!inside) continue;
      const int difference = levelDifference(drawn.at(x, y), reference.at(x, y));
      error.meanLevels += difference;
      error.worstLevels = std::max(error.worstLevels, difference);
      ++error.pixels;
    }
  if (error.pixels > 0) error.meanLevels /= error.pixels;
  return error;
}

std::string text(const RegionError& error) {
  std::ostringstream out;
  out << "mean " << error.meanLevels << " levels, worst " << error.worstLevels << " over "
      << error.pixels << " pixels";
  return out.str();
}

std::ostream& operator<<(std::ostream& out, const RegionError& error) { return out << text(error); }

// A cylinder wearing the texture by the cylindrical projection, turned so
// that its seam (u = 0 on its +x side) faces the eye, seen from above.
std::unique_ptr<Shape> seamFacingCylinder() {
  TransformSpec turn;
  turn.rotateDegrees = Vec3(0.0f, 80.0f, 0.0f);
  return std::make_unique<TransformedShape>(
      std::make_unique<MappedShape>(
          std::make_unique<Cylinder>(Vec3(0.0f, -1.0f, 0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0),
          Mapping{Projection::Cylindrical, Vec3(0, 1, 0)}),
      worldFromObject(turn));
}

void expectTheSeamAndTheCapFollowed(int width, int height) {
  const Vec3 eye(0.4f, 3.2f, -3.4f), target(0.0f, 0.3f, 0.0f);
  const Scene referenceScene =
      sceneOf(seamFacingCylinder(), TextureFilter::Bilinear, eye, target, width, height);
  const Image reference =
      renderWith("ray-tracing", referenceScene, settingsFor(referenceScene, 64)).image;
  // Object space: the cylinder turns about y, whose heights and distances
  // from the axis the world keeps.
  const auto capCentre = [](const SurfacePoint& surface) {
    return surface.normal.y > 0.99f && std::hypot(surface.position.x, surface.position.z) < 0.3f;
  };
  // Strips of the side, by u: either side of the seam, and a strip as wide
  // beside them, as squarely in view.
  const auto strip = [](float from, float to) {
    return [from, to](const SurfacePoint& surface) {
      const float fromSeam = std::min(surface.uv.x, 1.0f - surface.uv.x);
      return std::abs(surface.normal.y) < 0.5f && std::abs(surface.position.y) < 0.6f &&
             fromSeam >= from && fromSeam < to;
    };
  };
  const auto nearTheSeam = strip(0.0f, 0.03f);
  const auto awayFromTheSeam = strip(0.04f, 0.07f);
  for (TextureFilter filter : kFootprintFilters) {
    const Scene scene = sceneOf(seamFacingCylinder(), filter, eye, target, width, height);
    const Image drawn = renderWith("z-buffer", scene, settingsFor(scene, 1)).image;
    const RegionError centre = errorOver(scene, drawn, reference, capCentre);
    const RegionError seam = errorOver(scene, drawn, reference, nearTheSeam);
    const RegionError elsewhere = errorOver(scene, drawn, reference, awayFromTheSeam);
    const std::string what = std::to_string(width) + "x" + std::to_string(height) + ", " +
                             nameOf(filter) + ": cap centre " + text(centre) + "; seam " +
                             text(seam) + "; beside it " + text(elsewhere);
    EXPECT_GT(centre.pixels, 100) << what;
    EXPECT_GT(seam.pixels, 100) << what;
    EXPECT_GT(elsewhere.pixels, 100) << what;
    // The seam is no harder to filter than the stripes beside it.
    EXPECT_LE(seam.meanLevels, elsewhere.meanLevels + 2.0) << what;
    EXPECT_LE(seam.worstLevels, elsewhere.worstLevels + 8) << what;
    // At the cap's centre u turns all the way around within a few pixels
    // while v stays at 1: the footprint is a line along the top row. The
    // rectangle and the ellipse follow it; the trilinear square blurs the
    // rows below into a spot a few pixels across.
    if (filter == TextureFilter::Trilinear) {
      EXPECT_LE(centre.meanLevels, 4.0) << what;
    } else {
      EXPECT_LE(centre.worstLevels, 4) << what;
    }
  }
}

// At a square image and a tall one, whose pixels' footprints differ.
TEST(TextureFiltering, FollowsTheCoordinatesAcrossACylindersSeamAndOverItsCap) {
  expectTheSeamAndTheCapFollowed(160, 160);
  expectTheSeamAndTheCapFollowed(120, 300);
}

// A floor seen at a grazing angle, the texture repeated along it. The
// mipmap's square blurs the far floor to a mean (3.7 levels from the
// reference on average); the rectangle, around a footprint that runs along
// v, follows it better (1.8); the ellipse best (0.9).
TEST(TextureFiltering, FollowsLongFootprintsBetterThanTheMipmap) {
  const std::map<TextureFilter, double> kMeanLevels = {{TextureFilter::Trilinear, 4.5},
                                                       {TextureFilter::SummedArea, 2.2},
                                                       {TextureFilter::EllipticalAverage, 1.2}};
  const auto floor = [] {
    return std::make_unique<ConvexPolygon>(
        std::vector<Vec3>{{-6, 0, -4}, {6, 0, -4}, {6, 0, 60}, {-6, 0, 60}}, 0);
  };
  const Vec3 eye(0.0f, 1.0f, -4.0f), target(0.0f, 0.2f, 10.0f);
  Scene referenceScene = sceneOf(floor(), TextureFilter::Bilinear, eye, target, 160, 120);
  const Image reference =
      renderWith("ray-tracing", referenceScene, settingsFor(referenceScene, 64)).image;
  const auto everywhere = [](const SurfacePoint&) { return true; };
  for (TextureFilter filter : kFootprintFilters) {
    const Scene scene = sceneOf(floor(), filter, eye, target, 160, 120);
    const Image drawn = renderWith("z-buffer", scene, settingsFor(scene, 1)).image;
    const RegionError floor = errorOver(scene, drawn, reference, everywhere);
    EXPECT_GT(floor.pixels, 160 * 120 / 3);
    EXPECT_LE(floor.meanLevels, kMeanLevels.at(filter)) << nameOf(filter) << ": " << floor;
  }
}

}  // namespace
}  // namespace rise
