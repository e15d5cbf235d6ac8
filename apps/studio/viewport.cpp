#include "viewport.hpp"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "raster/tessellated_scene.hpp"
#include "scene/tessellation.hpp"

namespace rise::studio {
namespace {

// The preview's floor: large enough to read as one, small enough for the
// depth buffer's precision.
constexpr float kPreviewPlaneSize = 60.0f;
constexpr int kPreviewTessellation = 12;
constexpr int kMostLights = 8;

struct Vertex {
  Vec3 position;
  Vec3 normal;
  Vec3 colour;
};

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 viewProjection;
out vec3 worldPosition;
out vec3 worldNormal;
out vec3 surfaceColour;
void main() {
  worldPosition = position;
  worldNormal = normal;
  surfaceColour = colour;
  gl_Position = viewProjection * vec4(position, 1.0);
})";

// Lambert's diffuse light from the scene's lights, and a little from the eye
// so that nothing is black; unlit for the gizmos.
const char* kFragmentShader = R"(#version 330 core
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 surfaceColour;
uniform int lightCount;
uniform vec4 lights[8];
uniform vec3 lightColours[8];
uniform vec3 ambient;
uniform vec3 eye;
uniform bool unlit;
out vec4 fragment;
void main() {
  if (unlit) { fragment = vec4(surfaceColour, 1.0); return; }
  vec3 n = normalize(worldNormal);
  vec3 toEye = normalize(eye - worldPosition);
  if (dot(n, toEye) < 0.0) n = -n;
  vec3 light = ambient + 0.15 * vec3(max(dot(n, toEye), 0.0));
  for (int i = 0; i < lightCount; ++i) {
    vec3 l = lights[i].w > 0.5 ? normalize(lights[i].xyz - worldPosition) : lights[i].xyz;
    light += lightColours[i] * max(dot(n, l), 0.0);
  }
  vec3 shaded = surfaceColour * light;
  fragment = vec4(pow(clamp(shaded, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
})";

unsigned compile(GLenum kind, const char* source) {
  const unsigned shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  return shader;
}

void upload(unsigned buffer, const std::vector<Vertex>& vertices) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
}

void bindVertexLayout(unsigned buffer) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  for (int attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexAttribArray(attribute);
    glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(attribute * sizeof(Vec3)));
  }
}

// A light as seen from `point`: its own point when it has one, else far
// along the direction it comes from.
LightSample lightFrom(const Light& light, const Vec3& point) { return light.illuminate(point); }

void addLine(std::vector<Vertex>& lines, const Vec3& a, const Vec3& b, const Vec3& colour) {
  lines.push_back({a, Vec3(0.0f), colour});
  lines.push_back({b, Vec3(0.0f), colour});
}

// A star at each light's point; an arrow towards the scene along each light
// that comes from a direction.
std::vector<Vertex> lightGizmos(const Scene& scene) {
  std::vector<Vertex> lines;
  const Vec3 centre = scene.camera.lookAt;
  const float size = 0.05f * glm::length(scene.camera.position - centre) + 0.05f;
  const Vec3 yellow(1.0f, 0.85f, 0.2f);
  for (const auto& light : scene.lights) {
    const LightSample sample = lightFrom(*light, centre);
    if (std::isfinite(sample.distance)) {
      const Vec3 at = centre + sample.toLight * sample.distance;
      for (const Vec3& axis : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1) * 0.58f,
                               Vec3(1, -1, 1) * 0.58f})
        addLine(lines, at - axis * size, at + axis * size, yellow);
    } else {
      const Vec3 from = centre + sample.toLight * size * 12.0f;
      const Vec3 to = centre + sample.toLight * size * 4.0f;
      addLine(lines, from, to, yellow);
      const Vec3 side = glm::normalize(glm::cross(sample.toLight, Vec3(0.3f, 1.0f, 0.2f))) * size;
      addLine(lines, to, to + sample.toLight * size * 1.5f + side, yellow);
      addLine(lines, to, to + sample.toLight * size * 1.5f - side, yellow);
    }
  }
  return lines;
}

}  // namespace

Vec3 Viewport::Orbit::position() const {
  return target + distance * Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                  std::cos(pitch) * std::cos(yaw));
}

Viewport::~Viewport() {
  if (program_ == 0) return;
  glDeleteProgram(program_);
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(1, &triangles_);
  glDeleteBuffers(1, &lines_);
  glDeleteBuffers(1, &extraLines_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
}

void Viewport::prepare() {
  if (program_ != 0) return;
  program_ = glCreateProgram();
  const unsigned vertex = compile(GL_VERTEX_SHADER, kVertexShader);
  const unsigned fragment = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  glGenVertexArrays(1, &vertexArray_);
  glGenBuffers(1, &triangles_);
  glGenBuffers(1, &lines_);
  glGenBuffers(1, &extraLines_);
  glGenFramebuffers(1, &framebuffer_);
  glGenTextures(1, &colour_);
  glGenRenderbuffers(1, &depth_);
}

void Viewport::rebuild(const Scene& scene) {
  TessellationSettings settings;
  settings.level = kPreviewTessellation;
  settings.planeSize = kPreviewPlaneSize;
  settings.viewpoint = scene.camera.lookAt;
  const TessellatedScene tessellated = tessellateScene(scene, settings, Workers(0));
  std::vector<Vertex> vertices;
  shapeVertices_.assign(scene.shapes.size(), {0, 0});
  for (const SceneFace& face : tessellated.faces) {
    const Color colour = scene.materials[static_cast<std::size_t>(face.material)].color;
    auto& [first, count] = shapeVertices_[static_cast<std::size_t>(face.shape)];
    if (count == 0) first = static_cast<int>(vertices.size());
    count += 3;
    for (int corner : face.vertices) {
      const SurfaceVertex& vertex = tessellated.vertices[static_cast<std::size_t>(corner)];
      vertices.push_back({vertex.position, vertex.normal, colour});
    }
  }
  triangleVertices_ = static_cast<int>(vertices.size());
  upload(triangles_, vertices);
  const std::vector<Vertex> lines = lightGizmos(scene);
  lineVertices_ = static_cast<int>(lines.size());
  upload(lines_, lines);

  const Vec3 offset = scene.camera.position - scene.camera.lookAt;
  orbit_.target = scene.camera.lookAt;
  orbit_.distance = std::max(glm::length(offset), 1e-3f);
  orbit_.pitch = std::asin(std::clamp(offset.y / orbit_.distance, -1.0f, 1.0f));
  orbit_.yaw = std::atan2(offset.x, offset.z);
}

void Viewport::resizeTarget(int width, int height) {
  if (width == targetWidth_ && height == targetHeight_) return;
  targetWidth_ = width;
  targetHeight_ = height;
  glBindTexture(GL_TEXTURE_2D, colour_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Returns whether the user let go of the camera this frame after moving it.
bool Viewport::handleInput(const Vec3& up) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    orbit_.distance *= std::pow(0.85f, io.MouseWheel);
    moved_ = true;
  }
  const bool panning = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) ||
                       (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f));
  if (ImGui::IsItemActive() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    if (panning) {
      const Vec3 forward = glm::normalize(orbit_.target - orbit_.position());
      const Vec3 right = glm::normalize(glm::cross(forward, up));
      const Vec3 upward = glm::cross(right, forward);
      const float step = orbit_.distance * 0.002f;
      orbit_.target += (-io.MouseDelta.x * right + io.MouseDelta.y * upward) * step;
    } else {
      orbit_.yaw -= io.MouseDelta.x * 0.01f;
      orbit_.pitch = std::clamp(orbit_.pitch + io.MouseDelta.y * 0.01f, -1.55f, 1.55f);
    }
    moved_ = true;
  }
  const bool released = !ImGui::IsItemActive() && !ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
                        !ImGui::IsMouseDown(ImGuiMouseButton_Right);
  if (moved_ && released) {
    moved_ = false;
    return true;
  }
  return false;
}

void Viewport::renderScene(const Scene& scene, int selected, int width, int height) {
  const Vec3 eye = orbit_.position();
  const glm::mat4 viewProjection =
      glm::perspective(glm::radians(scene.camera.fovDegrees),
                       static_cast<float>(width) / static_cast<float>(height), 0.05f, 500.0f) *
      glm::lookAt(eye, orbit_.target, scene.camera.up);
  std::array<glm::vec4, kMostLights> lights{};
  std::array<Vec3, kMostLights> colours{};
  const int lightCount = std::min(static_cast<int>(scene.lights.size()), kMostLights);
  for (int i = 0; i < lightCount; ++i) {
    const LightSample sample =
        lightFrom(*scene.lights[static_cast<std::size_t>(i)], scene.camera.lookAt);
    lights[static_cast<std::size_t>(i)] =
        std::isfinite(sample.distance)
            ? glm::vec4(scene.camera.lookAt + sample.toLight * sample.distance, 1.0f)
            : glm::vec4(sample.toLight, 0.0f);
    colours[static_cast<std::size_t>(i)] = sample.color;
  }

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
  const Color& background = scene.image.background;
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(program_);
  glUniformMatrix4fv(glGetUniformLocation(program_, "viewProjection"), 1, GL_FALSE,
                     glm::value_ptr(viewProjection));
  glUniform1i(glGetUniformLocation(program_, "lightCount"), lightCount);
  glUniform4fv(glGetUniformLocation(program_, "lights"), kMostLights, glm::value_ptr(lights[0]));
  glUniform3fv(glGetUniformLocation(program_, "lightColours"), kMostLights,
               glm::value_ptr(colours[0]));
  glUniform3fv(glGetUniformLocation(program_, "ambient"), 1, glm::value_ptr(scene.ambient));
  glUniform3fv(glGetUniformLocation(program_, "eye"), 1, glm::value_ptr(eye));
  glBindVertexArray(vertexArray_);

  glUniform1i(glGetUniformLocation(program_, "unlit"), 0);
  bindVertexLayout(triangles_);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glDrawArrays(GL_TRIANGLES, 0, triangleVertices_);
  glDisable(GL_POLYGON_OFFSET_FILL);

  glUniform1i(glGetUniformLocation(program_, "unlit"), 1);
  glDisableVertexAttribArray(2);
  glVertexAttrib3f(2, 1.0f, 0.55f, 0.1f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  for (int shape = 0; shape < static_cast<int>(shapeVertices_.size()); ++shape) {
    if (scene.objectOf(shape) != selected) continue;
    const auto [first, count] = shapeVertices_[static_cast<std::size_t>(shape)];
    glDrawArrays(GL_TRIANGLES, first, count);
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  bindVertexLayout(extraLines_);
  glDrawArrays(GL_LINES, 0, extraLineVertices_);
  bindVertexLayout(lines_);
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_LINES, 0, lineVertices_);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Viewport::showLines(const std::vector<SceneLine>& lines) {
  prepare();
  std::vector<Vertex> vertices;
  for (const SceneLine& line : lines) addLine(vertices, line.from, line.to, line.colour);
  extraLineVertices_ = static_cast<int>(vertices.size());
  upload(extraLines_, vertices);
}

std::optional<CameraPlacement> Viewport::draw(const Scene& scene, int revision, int selected,
                                              ImVec2 size) {
  prepare();
  const int width = std::max(16, static_cast<int>(size.x));
  const int height = std::max(16, static_cast<int>(size.y));
  if (revision != revision_) {
    glBindVertexArray(vertexArray_);
    rebuild(scene);
    glBindVertexArray(0);
    revision_ = revision;
  }
  resizeTarget(width, height);
  renderScene(scene, selected, width, height);
  ImGui::Image(reinterpret_cast<void*>(static_cast<std::uintptr_t>(colour_)),
               {static_cast<float>(width), static_cast<float>(height)}, {0, 1}, {1, 0});
  // The image takes no input of its own: an invisible button over it does.
  ImGui::SetCursorScreenPos(ImGui::GetItemRectMin());
  ImGui::InvisibleButton("camera", {static_cast<float>(width), static_cast<float>(height)},
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  if (!handleInput(scene.camera.up)) return std::nullopt;
  return CameraPlacement{orbit_.position(), orbit_.target};
}

}  // namespace rise::studio
