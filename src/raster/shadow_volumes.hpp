// Shadow volumes, after F. C. Crow, "Shadow algorithms for computer
// graphics", SIGGRAPH 1977, counted along the scanline algorithm's spans; the
// idea is told in shadow_volumes.cpp.
#pragma once

#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "core/parallel.hpp"
#include "core/stats.hpp"
#include "raster/active_edges.hpp"
#include "raster/tessellated_scene.hpp"
#include "render/step_recorder.hpp"
#include "shading/light_visibility.hpp"

namespace rise {

// The lights a pixel's visible point is in the shadow of, by light: what the
// shading model asks at that pixel (raster/surface_shader.hpp).
class PixelShadows final : public LightVisibility {
 public:
  explicit PixelShadows(std::span<const std::uint8_t> shadowed) : shadowed_(shadowed) {}

  Color reaching(int light, const Vec3&, const Vec3&) const override {
    return Color(shadowed_[static_cast<std::size_t>(light)] != 0 ? 0.0f : 1.0f);
  }
  // Whether some light is hidden from the point.
  bool any() const;

 private:
  std::span<const std::uint8_t> shadowed_;
};

// The shadow volumes of the scene's opaque faces from each light (an area
// light from its centre), their faces on the screen, and what the scanline
// finds with them: which lights each pixel's visible point is hidden from.
class ShadowVolumes {
 public:
  ShadowVolumes(const Scene& scene, const TessellatedScene& tessellated, const ViewProjection& view,
                const Workers& workers);

  // Sweeps the volumes' faces down one band of scanlines (an image band of
  // raster/bands.hpp), beside the scanline algorithm's own sweep of it.
  class BandCount {
   public:
    BandCount(ShadowVolumes& volumes, const PixelRect& band);

    // At each pixel of scanline y where a surface is seen, at inverse depth
    // inverseDepth[x] (0: none is), counts for each light the faces of its
    // volumes in front of the surface, from the count at the eye: + 1 for a
    // face the eye sees from outside its volume (going in), - 1 for one seen
    // from inside (going out). The point is in shadow where the count is not 0.
    void countScanline(int y, std::span<const float> inverseDepth);
    // The counts along the last scanline counted, as runs of equal ones, for
    // a step's record.
    StepTable countsTable() const;

   private:
    ShadowVolumes& volumes_;
    EdgeListCounters edgeCounters_;
    ActiveEdgeList edges_;
    std::vector<int> counts_;  // by pixel of the scanline, then by light
  };

  // What pixel (x, y)'s visible point is in the shadow of, once its
  // scanline is counted.
  PixelShadows at(int x, int y) const;

  // "shadow_volume_faces" (the silhouette edges' faces, all lights),
  // "shadow_volume_polygons" (those drawn on the screen), "eye_in_volumes"
  // (the volumes the eye is in, all lights), "shadow_volume_tests" (a face's
  // depth compared with a pixel's surface), "shadow_volume_crossings" (faces
  // found in front of the surface and counted) and "shadowed_pixel_lights"
  // (pixels found in a light's shadow, once a light).
  void addStats(Stats& stats) const;

 private:
  void buildVolumes(const Scene& scene, const TessellatedScene& tessellated, const Vec3& eye);

  int width_, height_, lightCount_;
  TessellatedScene faces_;        // the volumes' faces, each quadrilateral as two triangles
  std::vector<int> lightOfFace_;  // by face of faces_
  std::vector<int> countAtEye_;   // by light: the volumes the eye is in
  ScreenGeometry screen_;         // faces_ on the screen
  std::vector<std::vector<int>> polygonsByBand_;
  std::vector<std::uint8_t> shadowed_;  // by pixel, then by light
  std::atomic<std::uint64_t> tests_{0}, crossings_{0}, shadowedPixels_{0};
};

}  // namespace rise
