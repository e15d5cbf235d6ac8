// The studio's one window: GLFW makes it with an OpenGL 3.3 context, Dear
// ImGui draws into it. Frames are begun and ended here; between them the
// studio declares its widgets.
#pragma once

#include <filesystem>
#include <functional>

#include "core/image.hpp"

struct GLFWwindow;

namespace rise::studio {

class Window {
 public:
  // Throws std::runtime_error when no window can be made (no display).
  Window(int width, int height, const char* title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Waits for input, at most `timeout` seconds (0: only what is there).
  void waitForInput(double timeout) const;
  // Starts a frame; `input` may then set Dear ImGui's input state over what
  // the user gave (a scripted session).
  void beginFrame(const std::function<void()>& input);
  // Shows the frame; with `capture`, first copies it there as a display
  // image (values already encoded for the screen).
  void endFrame(Image* capture = nullptr);

  bool closeRequested() const;
  void setCloseRequested(bool requested);

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace rise::studio
