#include "reports/ray_tree_text.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "core/text.hpp"
#include "reports/step_json.hpp"

namespace rise {
namespace {

std::string numbers(std::initializer_list<float> values) {
  std::ostringstream out;
  out << std::setprecision(4) << "(";
  const char* separator = "";
  for (float value : values) {
    // What rounding leaves of a zero (1e-43) reads as a zero.
    out << separator << (std::abs(value) < 1e-7f ? 0.0f : value);
    separator = ", ";
  }
  out << ")";
  return out.str();
}

std::string text(const Vec2& v) { return numbers({v.x, v.y}); }
std::string text(const Vec3& v) { return numbers({v.x, v.y, v.z}); }

// How a path tracer's path went on from a vertex, and whether the roulette
// ended it.
void printPathOnward(std::ostream& out, const PathVertex& vertex, const std::string& indent) {
  if (vertex.density <= 0.0f) return;
  out << indent << "  goes on "
      << (vertex.singular ? "by the mirror or the glass, chance "
                          : "by the BRDF's sample, density ")
      << vertex.density;
  if (vertex.endedByRoulette)
    out << "; roulette ends it (it would go on with chance " << vertex.survival << ")";
  else if (vertex.survival < 1.0f)
    out << "; roulette lets it go on (chance " << vertex.survival << ", its weight divided by it)";
  out << "\n";
}

void printRayAndItsOwn(std::ostream& out, const Scene& scene, const RayTree& tree, int index,
                       const std::string& indent) {
  const RayNode& ray = tree.rays[static_cast<std::size_t>(index)];
  printRay(out, scene, ray, indent);
  for (int child : ray.children) printRayAndItsOwn(out, scene, tree, child, indent + "  ");
}

}  // namespace

void printRay(std::ostream& out, const Scene& scene, const RayNode& ray,
              const std::string& indent) {
  out << indent << toString(ray.kind) << " ray from " << text(ray.origin) << " along "
      << text(ray.direction);
  if (ray.kind == RayKind::Shadow && ray.light < 0) {
    out << " to a point of an emitter (" << ray.distance
        << " away): " << (ray.transmittance == Color(0.0f) ? "blocked" : "reaches it") << "\n"
        << indent << "  f Le cos / p " << text(ray.diffuse) << ", weight " << ray.misWeight
        << "; adds " << text(ray.contribution) << "\n";
    return;
  }
  if (ray.kind == RayKind::Shadow) {
    out << " to light " << ray.light << " (" << ray.distance << " away): "
        << (ray.transmittance == Color(0.0f)   ? "blocked"
            : ray.transmittance == Color(1.0f) ? "reaches it"
                                               : "filtered to " + text(ray.transmittance))
        << "\n"
        << indent << "  diffuse " << text(ray.diffuse) << ", specular " << text(ray.specular)
        << "; adds " << text(ray.contribution) << "\n";
    return;
  }
  out << ", weight " << text(ray.weight) << "\n";
  if (!ray.hit) {
    out << indent << "  hits nothing: background " << text(ray.color) << "; adds "
        << text(ray.contribution) << "\n";
    return;
  }
  out << indent << "  hits " << objectName(scene, ray.object) << " at " << text(ray.point) << ", "
      << ray.distance << " away, normal " << text(ray.normal) << ", uv " << text(ray.uv) << "\n"
      << indent << "  ";
  if (ray.path) {
    out << "emits " << text(ray.path->emitted);
    if (ray.path->emittedWeight < 1.0f) out << " (weight " << ray.path->emittedWeight << ")";
  } else {
    out << "ambient " << text(ray.ambient);
  }
  out << "; adds " << text(ray.contribution) << "; brings back " << text(ray.color) << "\n";
  if (ray.path) printPathOnward(out, *ray.path, indent);
}

void printRayTrees(std::ostream& out, const Scene& scene, const std::vector<RayTree>& trees,
                   const Color& pixelColor) {
  if (trees.empty()) return;
  out << "pixel " << trees[0].pixel.x << "," << trees[0].pixel.y << ": " << text(pixelColor)
      << " from " << counted(trees.size(), "sample") << "\n";
  for (const RayTree& tree : trees) {
    out << "sample " << tree.sample << " at " << text(tree.raster) << ": " << text(tree.color);
    if (tree.dimensions)
      out << " (lens " << text(tree.dimensions->lens) << ", time " << tree.dimensions->time
          << ", light " << text(tree.dimensions->light) << ", gloss "
          << text(tree.dimensions->gloss) << ")";
    out << "\n";
    printRayAndItsOwn(out, scene, tree, 0, "  ");
  }
}

}  // namespace rise
