#include "radiosity/solution_steps.hpp"

#include <cstdio>
#include <string>

#include "core/text.hpp"
#include "radiosity/display.hpp"

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
                             const RenderSettings& settings, const RadiosityMesh& mesh)
    : steps_(steps),
      scene_(scene),
      settings_(settings),
      mesh_(mesh),
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
  steps_.record(std::move(step), kFirstOrder + iteration.number);
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
