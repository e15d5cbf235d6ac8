// The render panel: the algorithm, every setting a render takes (those of
// RenderRequest, and of the algorithm's own options those its description
// says it reads), the image as it is made with a progress bar, the elapsed
// time and a cancel button, the buffers, and the values under the pointer.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "algorithms/registry.hpp"
#include "ray/accelerator.hpp"
#include "render/buffer_images.hpp"
#include "studio.hpp"

namespace rise::studio {
namespace {

// An override of the scene's own value: unticked, the scene's is used.
template <typename T, typename Edit>
void overridable(const char* label, std::optional<T>& value, const T& scenes, const Edit& edit) {
  bool on = value.has_value();
  ImGui::PushID(label);
  if (ImGui::Checkbox("##override", &on)) value = on ? std::optional<T>(scenes) : std::nullopt;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Tick to override the scene's value");
  ImGui::SameLine();
  ImGui::BeginDisabled(!on);
  T shown = value.value_or(scenes);
  if (edit(label, shown) && on) value = shown;
  ImGui::EndDisabled();
  ImGui::PopID();
}

template <typename Choice, typename Choices, typename Name>
bool choiceCombo(const char* label, Choice& value, const Choices& choices, const Name& name) {
  bool changed = false;
  if (ImGui::BeginCombo(label, std::string(name(value)).c_str())) {
    for (const Choice choice : choices)
      if (ImGui::Selectable(std::string(name(choice)).c_str(), choice == value)) {
        value = choice;
        changed = true;
      }
    ImGui::EndCombo();
  }
  return changed;
}

const auto kPatternName = [](SamplePattern pattern) { return toString(pattern); };
const auto kFilterName = [](FilterKind filter) { return toString(filter); };

// The shadows the algorithm draws (none, or one of its methods), and for
// shadow maps the command line's ranges for their map, bias and filter. A
// method the algorithm lacks, left from another algorithm, becomes none.
void drawShadowSettings(RenderSettings& settings, const AlgorithmDescription& algorithm) {
  std::vector<ShadowMethod> methods{ShadowMethod::None};
  methods.insert(methods.end(), algorithm.shadowMethods.begin(), algorithm.shadowMethods.end());
  if (std::find(methods.begin(), methods.end(), settings.shadows) == methods.end())
    settings.shadows = ShadowMethod::None;
  choiceCombo("Shadows", settings.shadows, methods, shadowMethodName);
  if (settings.shadows != ShadowMethod::Map) return;
  ImGui::SliderInt("Shadow map size", &settings.shadowMapSize, 16, 8192);
  ImGui::SliderFloat("Shadow bias (texels)", &settings.shadowBias, 0.0f, 1000.0f, "%g",
                     ImGuiSliderFlags_Logarithmic);
  ImGui::SliderInt("Shadow filter radius", &settings.shadowFilter, 0, 16);
}

// The command line's ranges: a patch size of 0 leaves the size to RISE.
void drawRadiositySettings(RadiositySettings& settings) {
  ImGui::DragFloat("Patch size (0: chosen)", &settings.patchSize, 1.0f, 0.0f, 1e6f, "%g");
  settings.patchSize = std::max(settings.patchSize, 0.0f);
  float residual = static_cast<float>(settings.residual);
  if (ImGui::SliderFloat("Residual", &residual, 1e-6f, 1.0f, "%g", ImGuiSliderFlags_Logarithmic))
    settings.residual = residual;
  choiceCombo("Solver", settings.solver, kAllRadiositySolvers, radiositySolverName);
  choiceCombo("Form factors", settings.formFactors, kAllFormFactorMethods, formFactorMethodName);
  if (settings.formFactors == FormFactorMethod::Hemicube)
    ImGui::SliderInt("Hemicube size", &settings.hemicubeSize, 8, 1024);
  choiceCombo("Drawn by", settings.display, kAllRadiosityDisplays, radiosityDisplayName);
}

}  // namespace

void Studio::drawRenderPanel() {
  placeAtFirst({960, 20}, {640, 560});
  ImGui::Begin("Render");
  trackPanel("render");
  const Renderer& renderer = *findRenderer(algorithm_);
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("Algorithm", algorithm_.c_str())) {
    for (const Renderer* each : allRenderers()) {
      const std::string name(each->name());
      if (ImGui::Selectable(name.c_str(), name == algorithm_)) algorithm_ = name;
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", std::string(each->description().summary).c_str());
    }
    ImGui::EndCombo();
  }
  track("algorithm");
  ImGui::SameLine();
  ImGui::BeginDisabled(!session_.scene());
  if (ImGui::Button("Render")) startRender();
  track("Render");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!render_.job);
  if (ImGui::Button("Cancel")) cancelRender();
  track("Cancel");
  ImGui::EndDisabled();

  const double fraction = render_.job ? render_.job->fractionDone() : (render_.result ? 1.0 : 0.0);
  const double seconds =
      render_.job ? render_.job->seconds()
                  : (render_.result ? render_.result->stats.value("render_seconds") : 0.0);
  char label[64];
  std::snprintf(label, sizeof label, "%.0f%%   %.2f s", fraction * 100.0, seconds);
  ImGui::ProgressBar(static_cast<float>(fraction), {-1, 0}, label);
  track("progress");
  ImGui::Checkbox("Record the steps", &recordSteps_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The next render records what the algorithm does, for the step player");
  track("Record the steps");
  ImGui::SameLine();
  ImGui::Checkbox("Follow the scene", &followScene_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Render again at each change to the scene: orbit a radiosity solution in the viewport");
  track("Follow the scene");
  ImGui::TextDisabled("Click a pixel of a ray-traced image to see its rays.");
  if (ImGui::CollapsingHeader("Settings")) drawRenderSettings(renderer.description());
  drawRenderImage();
  ImGui::End();
}

void Studio::drawRenderSettings(const AlgorithmDescription& algorithm) {
  const std::shared_ptr<const Scene> scene = session_.scene();
  const ImageSpec image = scene ? scene->image : ImageSpec{};
  ImageOverrides& overrides = request_.image;
  RenderSettings& settings = request_.settings;
  ImGui::PushItemWidth(160);
  const auto positive = [](const char* label, int& value) {
    const bool changed = ImGui::InputInt(label, &value);
    value = std::max(value, 1);
    return changed;
  };
  overridable("Width", overrides.width, image.width, positive);
  overridable("Height", overrides.height, image.height, positive);
  overridable("Samples", overrides.samples, image.sampling.samples, positive);
  overridable("Pattern", overrides.pattern, image.sampling.pattern,
              [](const char* label, SamplePattern& value) {
                return choiceCombo(label, value, kAllPatterns, kPatternName);
              });
  overridable("Filter", overrides.filter, image.sampling.filter,
              [](const char* label, FilterKind& value) {
                return choiceCombo(label, value, kAllFilters, kFilterName);
              });
  overridable("Adaptive threshold", overrides.adaptiveThreshold, image.sampling.adaptiveThreshold,
              [](const char* label, float& value) {
                return ImGui::DragFloat(label, &value, 0.005f, 0.001f, 1.0f, "%g");
              });
  ImGui::InputScalar("Seed", ImGuiDataType_U64, &settings.seed);
  ImGui::InputInt("Threads (0: one per core)", &settings.threads);
  settings.threads = std::max(settings.threads, 0);
  for (const Option option : algorithm.options) {
    switch (option) {
      case Option::Shading:
        choiceCombo("Shading", settings.shading, kAllShadings, shadingName);
        break;
      case Option::Culling:
        ImGui::Checkbox("Cull back faces", &settings.backfaceCulling);
        break;
      case Option::Tessellation:
        ImGui::SliderInt("Tessellation", &settings.tessellation, 1, 256);
        break;
      case Option::PlaneSize:
        ImGui::DragFloat("Plane size", &settings.planeSize, 100.0f, 1.0f, 1e7f, "%g");
        break;
      case Option::Shadows:
        drawShadowSettings(settings, algorithm);
        break;
      case Option::Transparency:
        choiceCombo("Transparency", settings.transparency, kAllTransparencies, transparencyName);
        break;
      case Option::Accel:
        choiceCombo("Acceleration", settings.accel, availableAccels(), accelName);
        break;
      case Option::MaxDepth:
        ImGui::SliderInt("Max depth", &settings.maxDepth, 1, 64);
        break;
      case Option::LightSampling:
        choiceCombo("Light sampling", settings.lightSampling, kAllLightSamplings,
                    lightSamplingName);
        ImGui::Checkbox("Russian roulette", &settings.russianRoulette);
        break;
      case Option::Progression:
        ImGui::SliderInt("Path samples", &settings.progression.samples, 1, 4096);
        ImGui::InputDouble("Time limit (s, 0: none)", &settings.progression.timeLimit);
        settings.progression.timeLimit = std::max(settings.progression.timeLimit, 0.0);
        break;
      case Option::Radiosity:
        drawRadiositySettings(settings.radiosity);
        break;
    }
  }
  ImGui::PopItemWidth();
  ImGui::TextDisabled(
      "The lens and the shutter are the camera's: aperture, focal_distance, shutter.");
}

void Studio::drawRenderImage() {
  const AlgorithmDescription* algorithm =
      render_.result ? &findRenderer(render_.algorithm)->description() : nullptr;
  if (ImGui::RadioButton("image", render_.buffer.empty())) render_.buffer.clear();
  if (algorithm != nullptr) {
    for (const std::string_view buffer : algorithm->buffers) {
      ImGui::SameLine();
      const std::string name(buffer);
      if (ImGui::RadioButton(name.c_str(), render_.buffer == name)) {
        render_.buffer = name;
        render_.bufferTexture.upload(visualizeBuffer(name, render_.result->buffers.at(name)),
                                     false);
      }
      track("buffer/" + name);
    }
  }
  const float readout = ImGui::GetTextLineHeightWithSpacing() * 2.5f;
  ImVec2 size = ImGui::GetContentRegionAvail();
  size.y -= readout;
  const bool showBuffer = !render_.buffer.empty() && !render_.job && render_.result;
  render_.shownAt = drawImageView(
      "render image", showBuffer ? render_.bufferTexture : render_.texture, render_.view, size);
  track("render image");
  drawPixelValues();
}

void Studio::drawPixelValues() {
  if (render_.shownAt.clicked && render_.result && !render_.job &&
      findRenderer(render_.algorithm)->description().offers(Look::RayTrees))
    inspectPixel(*render_.shownAt.hovered);
  if (!render_.shownAt.hovered || !render_.result || render_.job) {
    ImGui::TextDisabled(
        "Point at a pixel to read its values; wheel: zoom, drag: pan, double-click: fit.");
    return;
  }
  const int x = render_.shownAt.hovered->x, y = render_.shownAt.hovered->y;
  const RenderResult& result = *render_.result;
  if (x >= result.image.width() || y >= result.image.height()) return;
  const Color& colour = result.image.at(x, y);
  ImGui::Text("pixel %d, %d   colour %.4g %.4g %.4g", x, y, colour.r, colour.g, colour.b);
  std::string values;
  char text[96];
  for (const auto& [name, buffer] : result.buffers) {
    const Color& value = buffer.at(x, y);
    if (name == "normal")
      std::snprintf(text, sizeof text, "normal %.3f %.3f %.3f   ", value.r, value.g, value.b);
    else if (name == "depth")
      std::snprintf(text, sizeof text,
                    std::isinf(value.r) ? "depth: nothing hit   " : "depth %.4g   ", value.r);
    else if (name == "face")
      std::snprintf(text, sizeof text, value.r < 0 ? "face: none   " : "face %.0f   ", value.r);
    else
      std::snprintf(text, sizeof text, "%s %.4g   ", name.c_str(), value.r);
    values += text;
  }
  ImGui::TextUnformatted(values.c_str());
}

}  // namespace rise::studio
