// A scripted session, `rise studio --script FILE`: the studio driven frame by
// frame as a user would drive it, for the tests and for making screenshots.
// Each line of the file is one command (# starts a comment; ${NAME} is the
// environment variable NAME):
//
//   open FILE                  the File menu's Open
//   select PATH                pick an entry of the scene tree: objects/1
//   set PATH VALUE             what the field editor does: set PATH to VALUE
//   click WIDGET [AT]          press and release the left button on a widget, at
//                              its middle or the fraction AT of its width
//   double-click WIDGET        twice, quickly: a number field then takes typing
//   type TEXT                  type characters into the focused widget
//   key enter|escape|tab       press and release a key
//   replace-text OLD|NEW       change the text pane's text (then click Apply)
//   algorithm NAME             choose the render panel's algorithm
//   record-steps on|off        the render panel's "Record the steps"
//   click-pixel X Y            click pixel (X, Y) of the render panel's image
//   save-tree FILE             the pixel clicked's ray trees, as rise inspect prints them
//   step N|last                show step N (from 0) in the step player
//   save-step-image FILE       the step player's image after its step
//   setting NAME VALUE         a render setting: width, height, samples, threads
//   wait                       until every render has finished
//   frames N                   let N frames pass
//   save-scene FILE            the File menu's Save as
//   save-image FILE            the File menu's Save image
//   save-buffer NAME FILE      the File menu's Save buffer
//   write-page FOLDER          the compare panel's Write page
//   screenshot FILE            the window as it is now, as PNG
//   layout FILE                where each named widget is: "NAME X0 Y0 X1 Y1"
//   expect-refused TEXT        the last edit was refused, saying TEXT
//   expect-status TEXT         the status bar says TEXT
//   expect-value PATH VALUE    the scene's PATH holds VALUE
//   expect-problem LINE COLUMN the text does not load, for a problem there
//   expect-frames SECONDS GAP  for SECONDS while rendering, no frame takes
//                              longer than GAP seconds
//   expect-stopped-within S    the render cancelled last stopped within S seconds
//
// Widgets are named by their labels (Render, Cancel, Apply, Compare) or by
// what they show (tree/objects/1, objects/1/sphere/radius, compared/z-buffer).
// A command that fails stops the session with status 1, saying why.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "studio.hpp"

namespace rise::studio {

class Script {
 public:
  // Throws std::runtime_error when the file cannot be read.
  explicit Script(const std::filesystem::path& path);

  // Sets Dear ImGui's input for this frame, before it starts.
  void feedInput();
  // Runs commands after a frame was drawn; `screenshot` holds the frame
  // when wantsScreenshot() was true for it.
  void afterFrame(Studio& studio, const Image& screenshot);
  bool wantsScreenshot() const;
  bool done() const { return next_ >= commands_.size() || failed_; }
  bool failed() const { return failed_; }

 private:
  struct Command {
    int line;
    std::string name;
    std::vector<std::string> words;  // after the name
    std::string rest;                // the line after the name, as written
  };
  struct InputFrame {
    std::optional<ImVec2> pointer;
    bool pressed = false;
    std::string characters;
    int key = -1;
  };

  // Runs `command`; false while it is waiting for the studio.
  bool run(const Command& command, Studio& studio, const Image& screenshot);
  bool clickOn(const Command& command, Studio& studio, int clicks);
  bool clickAt(const ImVec2& point, int clicks);
  void fail(const Command& command, const std::string& why);

  std::filesystem::path path_;
  std::vector<Command> commands_;
  std::size_t next_ = 0;
  bool failed_ = false;
  std::vector<InputFrame> input_;  // the frames still to feed, the next last
  ImVec2 pointer_{-1.0f, -1.0f};
  int heldKey_ = -1;
  std::optional<std::chrono::steady_clock::time_point> waitingSince_;
  std::chrono::steady_clock::time_point lastFrame_;
  double longestGap_ = 0.0;
  int framesLeft_ = -1;
};

}  // namespace rise::studio
