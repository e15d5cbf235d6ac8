#include "render/render_settings.hpp"

namespace rise {

std::string_view shadingName(Shading shading) {
  switch (shading) {
    case Shading::Flat:
      return "flat";
    case Shading::Gouraud:
      return "gouraud";
    case Shading::Phong:
      return "phong";
  }
  return "?";
}

std::string_view shadowMethodName(ShadowMethod method) {
  switch (method) {
    case ShadowMethod::None:
      return "none";
    case ShadowMethod::Map:
      return "map";
    case ShadowMethod::Volume:
      return "volume";
  }
  return "?";
}

std::string_view accelName(Accel accel) {
  switch (accel) {
    case Accel::None:
      return "none";
    case Accel::Spheres:
      return "spheres";
    case Accel::Bvh:
      return "bvh";
    case Accel::Embree:
      return "embree";
  }
  return "?";
}

std::string_view transparencyName(Transparency transparency) {
  switch (transparency) {
    case Transparency::Sorted:
      return "sorted";
    case Transparency::ABuffer:
      return "a-buffer";
  }
  return "?";
}

std::string_view lightSamplingName(LightSampling sampling) {
  switch (sampling) {
    case LightSampling::Lights:
      return "nee";
    case LightSampling::Brdf:
      return "brdf";
    case LightSampling::Both:
      return "mis";
  }
  return "?";
}

std::string_view radiositySolverName(RadiositySolver solver) {
  switch (solver) {
    case RadiositySolver::Progressive:
      return "progressive";
    case RadiositySolver::GaussSeidel:
      return "gauss-seidel";
  }
  return "?";
}

std::string_view formFactorMethodName(FormFactorMethod method) {
  switch (method) {
    case FormFactorMethod::Rays:
      return "rays";
    case FormFactorMethod::Hemicube:
      return "hemicube";
  }
  return "?";
}

std::string_view radiosityDisplayName(RadiosityDisplay display) {
  switch (display) {
    case RadiosityDisplay::ZBuffer:
      return "z-buffer";
    case RadiosityDisplay::Scanline:
      return "scanline";
    case RadiosityDisplay::DepthSort:
      return "depth-sort";
    case RadiosityDisplay::AreaSubdivision:
      return "area-subdivision";
  }
  return "?";
}

}  // namespace rise
