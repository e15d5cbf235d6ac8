#include "script.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "io/image_io.hpp"

namespace rise::studio {
namespace {

constexpr double kLongestWait = 300.0;  // seconds, for a render to finish

std::string expandVariables(const std::string& line) {
  static const std::regex variable(R"(\$\{([A-Za-z_][A-Za-z0-9_]*)\})");
  std::string expanded;
  auto last = line.cbegin();
  for (std::sregex_iterator match(line.begin(), line.end(), variable), end; match != end; ++match) {
    expanded.append(last, line.cbegin() + match->position());
    const char* value = std::getenv((*match)[1].str().c_str());
    expanded += value != nullptr ? value : "";
    last = line.cbegin() + match->position() + match->length();
  }
  expanded.append(last, line.cend());
  return expanded;
}

int keyNamed(const std::string& name) {
  if (name == "enter") return GLFW_KEY_ENTER;
  if (name == "escape") return GLFW_KEY_ESCAPE;
  if (name == "tab") return GLFW_KEY_TAB;
  return -1;
}

std::string trimmed(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  const std::size_t end = text.find_last_not_of(" \t\r");
  return begin == std::string::npos ? "" : text.substr(begin, end - begin + 1);
}

}  // namespace

Script::Script(const std::filesystem::path& path) : path_(path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path.string() + ": cannot read the script");
  int number = 0;
  for (std::string line; std::getline(file, line);) {
    ++number;
    line = trimmed(expandVariables(line));
    if (line.empty() || line.starts_with("#")) continue;
    Command command{number, {}, {}, {}};
    std::istringstream words(line);
    words >> command.name;
    for (std::string word; words >> word;) command.words.push_back(word);
    command.rest = trimmed(line.substr(command.name.size()));
    commands_.push_back(std::move(command));
  }
}

void Script::fail(const Command& command, const std::string& why) {
  std::cerr << path_.string() << ":" << command.line << ": " << command.name << ": " << why << "\n";
  failed_ = true;
}

void Script::feedInput() {
  ImGuiIO& io = ImGui::GetIO();
  // Frames drawn in software take longer than a person's double click: the
  // session's clock ticks a sixtieth of a second a frame, whatever they take.
  io.DeltaTime = 1.0f / 60.0f;
  if (heldKey_ >= 0) {
    io.KeysDown[heldKey_] = false;
    heldKey_ = -1;
  }
  InputFrame frame;
  if (!input_.empty()) {
    frame = input_.back();
    input_.pop_back();
  }
  if (frame.pointer) pointer_ = *frame.pointer;
  io.MousePos = pointer_;
  io.MouseDown[0] = frame.pressed;
  for (char c : frame.characters) io.AddInputCharacter(static_cast<unsigned char>(c));
  if (frame.key >= 0) {
    io.KeysDown[frame.key] = true;
    heldKey_ = frame.key;
  }
}

bool Script::wantsScreenshot() const {
  return next_ < commands_.size() && commands_[next_].name == "screenshot" && input_.empty();
}

void Script::afterFrame(Studio& studio, const Image& screenshot) {
  const auto now = std::chrono::steady_clock::now();
  longestGap_ = std::max(longestGap_, std::chrono::duration<double>(now - lastFrame_).count());
  lastFrame_ = now;
  if (done() || !input_.empty()) return;
  if (run(commands_[next_], studio, screenshot)) {
    ++next_;
    waitingSince_.reset();
  }
}

bool Script::clickOn(const Command& command, Studio& studio, int clicks) {
  // "click NAME 0.1" clicks a tenth of the way across the widget.
  std::string name = command.rest;
  float across = 0.5f;
  if (const std::size_t space = name.rfind(' '); space != std::string::npos) {
    char* end = nullptr;
    const float fraction = std::strtof(name.c_str() + space + 1, &end);
    if (*end == '\0' && fraction >= 0.0f && fraction <= 1.0f) {
      across = fraction;
      name.resize(space);
    }
  }
  const std::optional<ImVec4> widget = studio.widget(name);
  if (!widget) {
    fail(command, "no widget '" + name + "' is shown");
    return true;
  }
  return clickAt({widget->x + (widget->z - widget->x) * across, (widget->y + widget->w) * 0.5f},
                 clicks);
}

bool Script::clickAt(const ImVec2& centre, int clicks) {
  const auto at = [&](bool pressed) {
    InputFrame frame;
    frame.pointer = centre;
    frame.pressed = pressed;
    return frame;
  };
  // Fed last first: point, then press and release as often as asked.
  std::vector<InputFrame> frames{at(false)};
  for (int i = 0; i < clicks; ++i) {
    frames.push_back(at(true));
    frames.push_back(at(false));
  }
  frames.push_back(at(false));
  input_.assign(frames.rbegin(), frames.rend());
  return true;
}

bool Script::run(const Command& command, Studio& studio, const Image& screenshot) {
  const std::string& name = command.name;
  const auto needWords = [&](std::size_t count) {
    if (command.words.size() >= count) return true;
    fail(command, "expected " + std::to_string(count) + " words after it");
    return false;
  };
  if (name == "open" && needWords(1)) {
    studio.open(command.rest);
  } else if (name == "select" && needWords(1)) {
    studio.select(command.rest);
  } else if (name == "set" && needWords(2)) {
    studio.editValue(command.words[0], trimmed(command.rest.substr(command.words[0].size())));
  } else if (name == "click" || name == "double-click") {
    return clickOn(command, studio, name == "click" ? 1 : 2);
  } else if (name == "type") {
    InputFrame typing;
    typing.characters = command.rest;
    input_.push_back(typing);
  } else if (name == "key" && needWords(1)) {
    if (keyNamed(command.words[0]) < 0)
      fail(command, "no key is called '" + command.words[0] + "'");
    InputFrame press;
    press.key = keyNamed(command.words[0]);
    input_ = {InputFrame(), press};
  } else if (name == "replace-text" && command.rest.find('|') != std::string::npos) {
    const std::size_t bar = command.rest.find('|');
    const std::string from = command.rest.substr(0, bar);
    if (!studio.replaceInText(from, command.rest.substr(bar + 1)))
      fail(command, "the text pane has no '" + from + "'");
  } else if (name == "record-steps" && needWords(1)) {
    studio.setRecordingSteps(command.words[0] == "on");
  } else if (name == "click-pixel" && needWords(2)) {
    const ImageViewShown& shown = studio.renderView().shownAt;
    const Vec2 pixel(std::atof(command.words[0].c_str()) + 0.5f,
                     std::atof(command.words[1].c_str()) + 0.5f);
    return clickAt(shown.onScreen(pixel), 1);
  } else if (name == "save-tree" && needWords(1)) {
    if (studio.inspection().trees.empty())
      fail(command, "no pixel's rays are shown");
    else if (!studio.saveRayTree(command.rest))
      fail(command, studio.status());
  } else if (name == "step" && needWords(1)) {
    const int count = static_cast<int>(studio.player().steps.size());
    if (count == 0) fail(command, "no steps were recorded");
    studio.showStep(command.words[0] == "last" ? count - 1 : std::atoi(command.words[0].c_str()));
  } else if (name == "save-step-image" && needWords(1)) {
    if (!studio.player().replay)
      fail(command, "no steps were recorded");
    else
      writeImage(studio.player().replay->image(), command.rest);
  } else if (name == "algorithm" && needWords(1)) {
    if (!studio.chooseAlgorithm(command.words[0])) fail(command, studio.status());
  } else if (name == "setting" && needWords(2)) {
    ImageOverrides& image = studio.request().image;
    const int value = std::atoi(command.words[1].c_str());
    if (command.words[0] == "width")
      image.width = value;
    else if (command.words[0] == "height")
      image.height = value;
    else if (command.words[0] == "samples")
      image.samples = value;
    else if (command.words[0] == "threads")
      studio.request().settings.threads = value;
    else
      fail(command, "no setting is called '" + command.words[0] + "'");
  } else if (name == "wait") {
    if (!waitingSince_) waitingSince_ = std::chrono::steady_clock::now();
    if (std::chrono::steady_clock::now() - *waitingSince_ >
        std::chrono::duration<double>(kLongestWait))
      fail(command, "the renders did not finish in time");
    return !studio.rendering();
  } else if (name == "frames" && needWords(1)) {
    if (framesLeft_ < 0) framesLeft_ = std::atoi(command.words[0].c_str());
    if (framesLeft_-- > 0) return false;
  } else if (name == "save-scene" && needWords(1)) {
    if (!studio.saveScene(command.rest)) fail(command, studio.status());
  } else if (name == "save-image" && needWords(1)) {
    if (!studio.saveImage(command.rest)) fail(command, studio.status());
  } else if (name == "save-buffer" && needWords(2)) {
    if (!studio.saveBuffer(command.words[0], command.words[1])) fail(command, studio.status());
  } else if (name == "write-page" && needWords(1)) {
    if (!studio.writeComparisonPage(command.rest)) fail(command, studio.status());
  } else if (name == "screenshot" && needWords(1)) {
    writeImage(screenshot, command.rest, Encoding::Linear);
  } else if (name == "layout" && needWords(1)) {
    std::ofstream layout(command.rest);
    for (const auto& [widget, box] : studio.widgets())
      layout << widget << " " << box.x << " " << box.y << " " << box.z << " " << box.w << "\n";
  } else if (name == "expect-refused") {
    const std::optional<Problem>& problem = studio.session().problem();
    if (!problem || problem->message.find(command.rest) == std::string::npos)
      fail(command, "expected a refusal saying '" + command.rest + "'; the studio says: " +
                        (problem ? problem->message : "nothing was refused"));
  } else if (name == "expect-status") {
    if (studio.status().find(command.rest) == std::string::npos)
      fail(command,
           "expected the status bar to say '" + command.rest + "'; it says: " + studio.status());
  } else if (name == "expect-value" && needWords(2)) {
    const SceneDocument* document = studio.session().document();
    const std::string expected = trimmed(command.rest.substr(command.words[0].size()));
    const std::string actual = document ? document->value(command.words[0]) : "(no scene)";
    if (actual != expected) fail(command, "expected '" + expected + "', found '" + actual + "'");
  } else if (name == "expect-problem" && needWords(2)) {
    const std::optional<Problem>& problem = studio.session().problem();
    if (!problem || std::to_string(problem->line) != command.words[0] ||
        std::to_string(problem->column) != command.words[1])
      fail(command, "expected a problem at " + command.words[0] + ":" + command.words[1] +
                        "; the studio says: " + (problem ? problem->message : "no problem"));
  } else if (name == "expect-frames" && needWords(2)) {
    if (!waitingSince_) {
      waitingSince_ = std::chrono::steady_clock::now();
      longestGap_ = 0.0;
    }
    if (!studio.rendering()) fail(command, "no render is running");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - *waitingSince_).count();
    if (seconds < std::atof(command.words[0].c_str())) return false;
    if (longestGap_ > std::atof(command.words[1].c_str()))
      fail(command, "a frame took " + std::to_string(longestGap_) + " s while rendering");
  } else if (name == "expect-stopped-within" && needWords(1)) {
    if (!studio.lastCancelSeconds()) return false;
    if (*studio.lastCancelSeconds() > std::atof(command.words[0].c_str()))
      fail(command,
           "the render took " + std::to_string(*studio.lastCancelSeconds()) + " s to stop");
  } else if (!failed_ && name != "frames") {
    fail(command, "no such command");
  }
  framesLeft_ = -1;
  return true;
}

}  // namespace rise::studio
