// RISE Studio driven by a scripted session (apps/studio/script.hpp), in a
// folder of the test's own, and what the session left read back.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/image.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {

inline const std::string kSourceDir = RISE_SOURCE_DIR;

inline const std::string kClassic = kSourceDir + "/examples/classic.yaml";

// A cancelled render stops within a tenth of a second. With the sanitizers,
// freeing what a render of this size allocated takes longer than that alone.
#ifdef RISE_SANITIZED_BUILD
inline const std::string kSecondsToStop = "1.0";
#else
inline const std::string kSecondsToStop = "0.1";
#endif

class Studio : public TemporaryFolderTest {
 protected:
  // Runs the session `script` (its ${OUT} this test's folder) and returns the
  // studio's exit status; what it printed goes to the test's output.
  int runSession(const std::string& script,
                 const std::string& program = "'" RISE_STUDIO_EXECUTABLE "'") {
    const std::filesystem::path file = directory_ / "session.script";
    std::ofstream(file) << script;
    const std::string command = "OUT='" + directory_.string() + "' RISE_SOURCE_DIR='" + kSourceDir +
                                "' XDG_CONFIG_HOME='" + directory_.string() + "' " + program +
                                " --script '" + file.string() + "'";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  int runCli(const std::string& arguments) {
    const int status =
        std::system((std::string(RISE_EXECUTABLE) + " " + arguments + " 2>/dev/null").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // Where the session's `layout` command that wrote `name` found each widget.
  std::map<std::string, std::array<float, 4>> layout(const std::string& name = "layout.txt") const {
    std::map<std::string, std::array<float, 4>> widgets;
    std::ifstream file(directory_ / name);
    // A line is the widget's name, which may hold spaces, then its four numbers.
    for (std::string line; std::getline(file, line);) {
      std::array<float, 4> box{};
      std::size_t end = line.size();
      for (int i = 3; i >= 0; --i) {
        const std::size_t space = line.rfind(' ', end - 1);
        box[static_cast<std::size_t>(i)] = std::stof(line.substr(space + 1, end - space - 1));
        end = space;
      }
      widgets[line.substr(0, end)] = box;
    }
    return widgets;
  }
};

inline std::string fileText(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The spread of a picture's greys: near 0 for a blank one.
inline double variance(const Image& image) {
  double sum = 0.0, squares = 0.0;
  for (const Color& pixel : image.pixels()) {
    const double grey = (pixel.r + pixel.g + pixel.b) / 3.0;
    sum += grey;
    squares += grey * grey;
  }
  const double n = static_cast<double>(image.pixels().size());
  return squares / n - (sum / n) * (sum / n);
}

}  // namespace rise
