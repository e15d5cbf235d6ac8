#include "window.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace rise::studio {
namespace {

std::string glfwProblem() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description != nullptr ? description : "unknown reason";
}

Image framebufferImage(int width, int height) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = &pixels[(static_cast<std::size_t>(height - 1 - y) * width + x) * 4];
      image.at(x, y) = Color(p[0], p[1], p[2]) / 255.0f;
    }
  return image;
}

}  // namespace

Window::Window(int width, int height, const char* title) {
  if (glfwInit() == GLFW_FALSE) throw std::runtime_error("cannot open a window: " + glfwProblem());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  // No larger than the screen, where the panels would lie beyond its edge.
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor())
    if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) {
      width = std::min(width, mode->width);
      height = std::min(height, mode->height);
    }
  window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string problem = glfwProblem();
    glfwTerminate();
    throw std::runtime_error("cannot open a window: " + problem);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

Window::~Window() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void Window::waitForInput(double timeout) const {
  if (timeout > 0.0)
    glfwWaitEventsTimeout(timeout);
  else
    glfwPollEvents();
}

void Window::beginFrame(const std::function<void()>& input) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (input) input();
  ImGui::NewFrame();
}

void Window::endFrame(Image* capture) {
  ImGui::Render();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  glViewport(0, 0, width, height);
  glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (capture != nullptr) *capture = framebufferImage(width, height);
  glfwSwapBuffers(window_);
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_) != 0; }

void Window::setCloseRequested(bool requested) {
  glfwSetWindowShouldClose(window_, requested ? GLFW_TRUE : GLFW_FALSE);
}

}  // namespace rise::studio
