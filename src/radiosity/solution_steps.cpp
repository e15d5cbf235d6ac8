#include "radiosity/solution_steps.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/text.hpp"
#include "radiosity/display.hpp"
#include "radiosity/form_factor_matrix.hpp"

namespace rise {

namespace {

// Before every step of the display, whose steps are numbered from 0.
constexpr std::int64_t kFirstOrder = -(std::int64_t{1} << 40);

// A number as a step says it: 0.02285, 62.55.
std::string fourDigits(double number) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", number);
  return text;
}

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

SolutionSteps::SolutionSteps(StepRecorder& steps, const Scene& scene,
                             const RenderSettings& settings, const RadiosityMesh& mesh,
                             float offset)
    : steps_(steps),
      scene_(scene),
      settings_(settings),
      mesh_(mesh),
      offset_(offset),
      view_(ViewFrame(scene.camera, settings.width, settings.height)) {}

void SolutionSteps::recordMesh(const RefinementCounts& refined) {
  const std::size_t patches = mesh_.patchMesh.patches.size(),
                    elements = mesh_.elementMesh.elements.size();
  Step step{"mesh", "the surfaces cut into " + counted(elements, "element") + ", gathered into " +
                        counted(patches, "patch", "patches") + " of " +
                        fourDigits(mesh_.patchSide) + " a side; " +
                        counted(refined.elementsCut, "element") +
                        " cut where the lights' light changes fast"};
  step.values = {{"patches", static_cast<double>(patches)},
                 {"elements", static_cast<double>(elements)},
                 {"elements_cut", static_cast<double>(refined.elementsCut)},
                 {"patch_size", mesh_.patchSide}};
  steps_.record(std::move(step), kFirstOrder);
}

void SolutionSteps::onIteration(const SolverIteration& iteration,
                                const std::function<std::vector<TwoSides>()>& elementLight) {
  const bool swept = settings_.radiosity.solver == RadiositySolver::GaussSeidel;
  Step step;
  if (swept) {
    step = Step{"sweep", "sweep " + std::to_string(iteration.number) + ": the light of " +
                             counted(iteration.receivers, "patch", "patches") +
                             " computed again; it changed by " + fourDigits(iteration.residual) +
                             " of the sources' light"};
  } else {
    step = Step{"shot", "shot " + std::to_string(iteration.number) + ": patch " +
                            std::to_string(iteration.patch) + " (its " +
                            (iteration.side == kFrontSide ? "front" : "back") + ") passes on " +
                            fourDigits(iteration.power) + " of the sources' light to " +
                            counted(iteration.receivers, "patch", "patches") + "; " +
                            fourDigits(iteration.residual) + " of it was still to pass on"};
    step.values = {{"shooter", static_cast<double>(iteration.patch)}, {"shot", iteration.power}};
    step.shapes = outlineOf(iteration.patch);
  }
  step.values.push_back({"receivers", static_cast<double>(iteration.receivers)});
  step.values.push_back({"residual", iteration.residual});
  if (isPowerOfTwo(iteration.number)) step.writes = imageOf(elementLight());
  if (!swept && iteration.number == 1 &&
      settings_.radiosity.formFactors == FormFactorMethod::Hemicube)
    recordHemicube(iteration.patch, iteration.side);
  steps_.record(std::move(step), kFirstOrder + 1 + iteration.number);
}

// The five faces laid out over the image: the top face on the left, the
// four half sides in a column on its right, each texel in the colour of the
// patch it shows (its material's, lighter or darker by the patch), black
// where it shows none.
void SolutionSteps::recordHemicube(std::size_t patch, int side) {
  const Patch& shooter = mesh_.patchMesh.patches[patch];
  const Vec3 normal = side == kFrontSide ? shooter.normal : -shooter.normal;
  Hemicube hemicube(settings_.radiosity.hemicubeSize);
  std::vector<float> formFactors(mesh_.patchMesh.patches.size(), 0.0f);
  const std::uint64_t covered = hemicube.addFormFactors(
      shooter.centre + offset_ * normal, normal,
      hemicubeTriangles(mesh_.elementMesh, mesh_.patchMesh), static_cast<int>(patch), formFactors);
  const int r = hemicube.resolution();
  // A texel of the layout, 2r x 2r: the top face at (0, r/2), side k at (r, k r/2).
  const auto patchAt = [&](int u, int v) {
    const int face = u < r ? 0 : 1 + v / (r / 2);
    const int x = u % r, y = u < r ? v - r / 2 : v % (r / 2);
    if (face == 0 && (y < 0 || y >= r)) return -1;
    return hemicube.seen(face)[static_cast<std::size_t>(y) * r + x];
  };
  const PixelRect area = settings_.area();
  const float scale = 2.0f * static_cast<float>(r) /
                      static_cast<float>(std::min(settings_.width, settings_.height));
  Step step{"hemicube", "the hemicube over patch " + std::to_string(patch) +
                            ": its top face and four half " + "sides, " + std::to_string(r) +
                            " texels a side, each texel the patch nearest in " +
                            "its direction, which takes its delta form factor; " +
                            counted(covered, "texel") + " show a patch"};
  for (int y = area.y0; y < area.y1; ++y)
    for (int x = area.x0; x < area.x1; ++x) {
      const int u = static_cast<int>(x * scale), v = static_cast<int>(y * scale);
      const int seen = u < 2 * r && v < 2 * r ? patchAt(u, v) : -1;
      Color colour(0.0f);
      if (seen >= 0) {
        const Patch& shown = mesh_.patchMesh.patches[static_cast<std::size_t>(seen)];
        colour = scene_.materials[shown.material].color *
                 (0.6f + 0.4f * static_cast<float>((seen * 37) % 11) / 10.0f);
      }
      step.writes.push_back({x, y, colour, -1});
    }
  double sum = 0.0;
  std::size_t seenPatches = 0;
  for (const float formFactor : formFactors)
    if (formFactor > 0.0f) sum += formFactor, ++seenPatches;
  step.values = {{"shooter", static_cast<double>(patch)},
                 {"hemicube_texels", static_cast<double>(covered)},
                 {"patches_seen", static_cast<double>(seenPatches)},
                 {"form_factors_sum", sum}};
  steps_.record(std::move(step), kFirstOrder + 1);
}

std::vector<StepShape> SolutionSteps::outlineOf(std::size_t patch) const {
  std::vector<StepShape> shapes;
  for (const int e : mesh_.patchMesh.patches[patch].elements) {
    const std::array<Vec3, 3> corners =
        cornersOf(mesh_.elementMesh.triangles.vertices, mesh_.elementMesh.elements[e].vertices);
    StepShape outline{StepShape::Kind::Polygon, "polygon", {}};
    for (const Vec3& corner : corners) {
      const Vec3 seen = view_.toCamera(corner);
      if (seen.z <= 0.0f) break;
      outline.points.push_back(view_.toRaster(seen));
    }
    if (outline.points.size() == corners.size()) shapes.push_back(std::move(outline));
  }
  return shapes;
}

std::vector<PixelWrite> SolutionSteps::imageOf(const std::vector<TwoSides>& elementLight) const {
  TessellatedScene lit = mesh_.elementMesh.triangles;
  lit.vertexRadiance = vertexLight(mesh_.elementMesh, elementLight);
  RenderObserver unwatched;
  const Image image = drawSolution(scene_, settings_, unwatched, lit).image;
  const PixelRect area = settings_.area();
  std::vector<PixelWrite> writes;
  writes.reserve(static_cast<std::size_t>(image.width()) * image.height());
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      writes.push_back({area.x0 + x, area.y0 + y, image.at(x, y), -1});
  return writes;
}

}  // namespace rise
