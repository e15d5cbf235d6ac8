#include "radiosity/display.hpp"

#include "raster/area_subdivision.hpp"
#include "raster/depth_sort.hpp"
#include "raster/scanline.hpp"
#include "raster/z_buffer.hpp"

namespace rise {

namespace {

const VisibleSurfaceRenderer& displayOf(RadiosityDisplay display) {
  static const ZBufferRenderer zBuffer;
  static const ScanlineRenderer scanline;
  static const DepthSortRenderer depthSort;
  static const AreaSubdivisionRenderer areaSubdivision;
  switch (display) {
    case RadiosityDisplay::Scanline:
      return scanline;
    case RadiosityDisplay::DepthSort:
      return depthSort;
    case RadiosityDisplay::AreaSubdivision:
      return areaSubdivision;
    case RadiosityDisplay::ZBuffer:
      break;
  }
  return zBuffer;
}

}  // namespace

RenderResult drawSolution(const Scene& scene, const RenderSettings& settings,
                          RenderObserver& observer, const TessellatedScene& lit) {
  RenderSettings display = settings;
  display.shadows = ShadowMethod::None;
  display.shading = Shading::Gouraud;
  return displayOf(settings.radiosity.display)
      .renderTessellated(scene, display, observer, [&](float) { return lit; });
}

}  // namespace rise
