// The two families draw a projected texture in the same place (Bier and
// Sloan's two-part mappings, scene/projected_mapping.hpp): the texture's
// texels, and the seams where the projection jumps from one face of its box
// to the next or from u = 1 back to 0, fall on the same pixels, but where the
// tessellated surface and the exact one are apart: by two pixels at most
// where the texels crowd (near a pole, on a side seen edge-on). Drawn
// from the corners' coordinates interpolated, the seams followed the
// polygons' edges, up to nine pixels away.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "scene/shapes/box.hpp"
#include "scene/shapes/cylinder.hpp"
#include "scene/shapes/mapped_shape.hpp"
#include "scene/shapes/sphere.hpp"
#include "scene/shapes/transformed_shape.hpp"
#include "scene/textures/image_texture.hpp"
#include "scene/transform.hpp"
#include "support/image_agreement_testing.hpp"

namespace rise {
namespace {

using namespace image_agreement_testing;

// Texels of 16 x 8 colours, each its own, read nearest: every texel edge
// and every seam is an edge of colour in the image.
std::shared_ptr<const Texture> texels() {
  auto image = std::make_shared<Image>(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      image->at(x, y) = Color(static_cast<float>(x) / 15.0f, static_cast<float>(y) / 7.0f,
                              static_cast<float>((x + y) % 3) / 2.0f);
  return std::make_shared<ImageTexture>(image, TextureFilter::Nearest);
}

// The shape, wearing the projection and turned, seen from above and in
// front under ambient light alone: each pixel shows its texel's colour.
Scene sceneOf(std::unique_ptr<Shape> shape, Projection projection, int width, int height) {
  Scene scene;
  scene.image.width = width;
  scene.image.height = height;
  scene.camera.position = Vec3(1.5f, 2.5f, -4.0f);
  scene.camera.lookAt = Vec3(0.0f, 0.2f, 0.0f);
  scene.camera.fovDegrees = 40.0f;
  scene.ambient = Color(1.0f);
  Material material;
  material.ka = 1.0f;
  material.kd = 0.0f;
  material.texture = texels();
  scene.materials.push_back(material);
  TransformSpec turn;
  turn.rotateDegrees = Vec3(10.0f, 200.0f, 0.0f);
  scene.shapes.push_back(std::make_unique<TransformedShape>(
      std::make_unique<MappedShape>(std::move(shape), Mapping{projection, Vec3(0, 1, 0)}),
      worldFromObject(turn)));
  return scene;
}

struct MappingCase {
  std::string name;
  Projection projection;
  std::function<std::unique_ptr<Shape>()> shape;
};

std::vector<MappingCase> mappingCases() {
  const auto sphere = [] { return std::make_unique<Sphere>(Vec3(0.0f), 1.2f, 0); };
  const auto box = [] { return std::make_unique<Box>(Vec3(-1.0f, -0.8f, -0.9f), Vec3(1.0f), 0); };
  const auto cylinder = [] {
    return std::make_unique<Cylinder>(Vec3(0.0f, -1.0f, 0.0f), Vec3(0, 1, 0), 1.0f, 2.0f, 0);
  };
  return {{"box on a sphere", Projection::Box, sphere},
          {"box on a cylinder", Projection::Box, cylinder},
          {"spherical on a box", Projection::Spherical, box},
          {"spherical on a sphere", Projection::Spherical, sphere},
          {"cylindrical on a cylinder", Projection::Cylindrical, cylinder},
          {"cylindrical on a box", Projection::Cylindrical, box}};
}

TEST(TexturePlacement, BothFamiliesDrawProjectedTexturesInTheSamePlace) {
  for (const MappingCase& mapping : mappingCases())
    for (const auto& [width, height] : {std::pair{160, 120}, std::pair{121, 160}}) {
      const Scene scene = sceneOf(mapping.shape(), mapping.projection, width, height);
      RenderSettings settings;
      settings.width = width;
      settings.height = height;
      settings.threads = 2;
      const RenderResult traced = renderWith("ray-tracing", scene, settings);
      for (std::string_view algorithm : {"z-buffer", "scanline"}) {
        const RenderResult drawn = renderWith(algorithm, scene, settings);
        const Agreement offset = offsetInside(scene, drawn, traced);
        EXPECT_GT(offset.pixelsCompared, width * height / 10) << mapping.name;
        EXPECT_LE(offset.worst, 2) << algorithm << ", " << mapping.name << ", " << width << " x "
                                   << height << ": texels " << offset;
      }
    }
}

}  // namespace
}  // namespace rise
