// How to render, whatever the algorithm: the settings every Renderer is
// given. The image size and its sampling come from the scene unless a front
// end overrides them (algorithms/render_settings_builder.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/image.hpp"
#include "core/sampling.hpp"
#include "scene/tessellation.hpp"

namespace rise {

// How rays find what they hit (ray/accelerator.hpp): every ray against every
// shape, Ritter's bounding spheres, a bounding volume hierarchy, or Intel's
// Embree where the build has it.
enum class Accel { None, Spheres, Bvh, Embree };
inline constexpr Accel kAllAccels[] = {Accel::None, Accel::Spheres, Accel::Bvh, Accel::Embree};
std::string_view accelName(Accel accel);  // as on the command line: "bvh"

// How the visible-surface algorithms apply the Phong model to their polygons:
// once per face, at the vertices with the colours interpolated (Gouraud), or
// at every pixel with the normals interpolated (Phong).
enum class Shading { Flat, Gouraud, Phong };
inline constexpr Shading kAllShadings[] = {Shading::Flat, Shading::Gouraud, Shading::Phong};
std::string_view shadingName(Shading shading);  // as on the command line: "gouraud"

// How the visible-surface algorithms find shadows: not at all (every light
// reaches every surface facing it), by Williams' shadow maps
// (raster/shadow_map.cpp), or by Crow's shadow volumes, which the scanline
// algorithm alone counts (raster/shadow_volumes.cpp).
enum class ShadowMethod { None, Map, Volume };
inline constexpr ShadowMethod kAllShadowMethods[] = {ShadowMethod::None, ShadowMethod::Map,
                                                     ShadowMethod::Volume};
std::string_view shadowMethodName(ShadowMethod method);  // as on the command line: "volume"

// How the z-buffer draws transparent surfaces: sorted back to front after the
// opaque ones (raster/transparency.hpp), or by Carpenter's A-buffer, a list
// of fragments at each pixel resolved by depth at the end, in any order
// (raster/a_buffer.hpp).
enum class Transparency { Sorted, ABuffer };
inline constexpr Transparency kAllTransparencies[] = {Transparency::Sorted, Transparency::ABuffer};
std::string_view transparencyName(Transparency transparency);  // as on the command line: "a-buffer"

// How the path tracer finds the light at each vertex of a path: by shadow
// rays to points chosen on the lights (next-event estimation), by the
// directions its BRDF samples happening to reach one, or by both, weighted by
// multiple importance sampling's power heuristic (Veach and Guibas 1995).
enum class LightSampling { Lights, Brdf, Both };
inline constexpr LightSampling kAllLightSamplings[] = {LightSampling::Lights, LightSampling::Brdf,
                                                       LightSampling::Both};
std::string_view lightSamplingName(LightSampling sampling);  // as on the command line: "mis"

// How radiosity solves the light between its elements: by progressive
// refinement, shooting the light of one element at a time (Cohen, Chen,
// Wallace and Greenberg 1988), or by Gauss-Seidel's sweeps over all of them
// (Cohen and Greenberg 1985).
enum class RadiositySolver { Progressive, GaussSeidel };
inline constexpr RadiositySolver kAllRadiositySolvers[] = {RadiositySolver::Progressive,
                                                           RadiositySolver::GaussSeidel};
std::string_view radiositySolverName(RadiositySolver solver);  // "progressive"

// How radiosity finds its form factors: from each patch's centre to each
// other patch in closed form, with a ray for their visibility (Wallace,
// Elmquist and Haines 1989), or by drawing every patch onto a hemicube
// around it (Cohen and Greenberg 1985).
enum class FormFactorMethod { Rays, Hemicube };
inline constexpr FormFactorMethod kAllFormFactorMethods[] = {FormFactorMethod::Rays,
                                                             FormFactorMethod::Hemicube};
std::string_view formFactorMethodName(FormFactorMethod method);  // "rays"

// The visible-surface algorithm that draws radiosity's solution.
enum class RadiosityDisplay { ZBuffer, Scanline, DepthSort, AreaSubdivision };
inline constexpr RadiosityDisplay kAllRadiosityDisplays[] = {
    RadiosityDisplay::ZBuffer, RadiosityDisplay::Scanline, RadiosityDisplay::DepthSort,
    RadiosityDisplay::AreaSubdivision};
std::string_view radiosityDisplayName(RadiosityDisplay display);  // its -a name: "z-buffer"

// Radiosity's: the side of a patch (0: a 24th of the scene's size, or more
// where that makes more than 3,000 patches), the residual it solves to (the
// light not yet passed on, over the light the sources give), how, the
// hemicube's texels a side, and what draws the solution.
struct RadiositySettings {
  float patchSize = 0.0f;
  double residual = 0.01;
  RadiositySolver solver = RadiositySolver::Progressive;
  FormFactorMethod formFactors = FormFactorMethod::Rays;
  int hemicubeSize = 128;
  RadiosityDisplay display = RadiosityDisplay::ZBuffer;
};

// How long a progressive algorithm (the path tracer) refines its image, pass
// after pass: up to `samples` a pixel, for at most `timeLimit` seconds of
// passes (0: no limit), or until the estimated noise falls to `noiseTarget`
// (0: no target), whichever comes first.
struct Progression {
  int samples = 64;
  double timeLimit = 0.0;
  double noiseTarget = 0.0;
};

// How to render, whatever the algorithm. The image size comes from the scene
// unless the command line overrides it.
struct RenderSettings {
  int width = 640;
  int height = 480;
  int maxDepth = 5;          // longest path of a ray tracer: the primary ray is level 1
  int threads = 0;           // 0: one per hardware thread
  PixelSampling sampling;    // samples per pixel, their pattern, the reconstruction filter
  std::uint64_t seed = 0;    // the same seed gives the same image; another, other noise
  Accel accel = Accel::Bvh;  // the acceleration structure of the ray tracers
  // The visible-surface algorithms (raster/): their shading, whether they
  // drop the back faces of solids, how finely they cut curved surfaces into
  // polygons (a circle into 4 * tessellation segments), and the side of the
  // square that stands in for an infinite plane.
  Shading shading = Shading::Phong;
  bool backfaceCulling = true;
  int tessellation = kDefaultTessellationLevel;
  float planeSize = kDefaultPlaneSize;
  // Their shadows, and the shadow maps': texels a side, bias in texels, and
  // the radius in texels of percentage-closer filtering (0: none).
  ShadowMethod shadows = ShadowMethod::None;
  int shadowMapSize = 1024;
  float shadowBias = 1.5f;
  int shadowFilter = 1;
  // How the z-buffer orders its transparent surfaces.
  Transparency transparency = Transparency::Sorted;
  // The path tracer's: how it finds the light, whether Russian roulette ends
  // its paths (Arvo and Kirk 1990), and how long it refines.
  LightSampling lightSampling = LightSampling::Both;
  bool russianRoulette = true;
  Progression progression;
  RadiositySettings radiosity;

  // Only this part of the image, for renders split among processes: the
  // result holds its pixels alone, each the value it has in the whole image
  // (the random numbers of a pixel depend on the pixel, not on the part).
  std::optional<PixelRect> region;

  // The auxiliary buffers to fill beside the image ("depth", "normal",
  // "face", "cost"): every one the algorithm has, or only those named, for a
  // front end that writes a few and need not pay for the others. The shadow
  // map, a picture of the maps made anyway, is always there.
  std::optional<std::vector<std::string>> buffers;

  // The pixels rendered: the region, or the whole image.
  PixelRect area() const { return region.value_or(PixelRect{0, 0, width, height}); }
  bool wantsBuffer(std::string_view name) const {
    return !buffers || std::find(buffers->begin(), buffers->end(), name) != buffers->end();
  }
};

}  // namespace rise
