// `rise-studio [SCENE] [--script FILE]`, also started as `rise studio`: RISE
// Studio, the interactive window over the same library as the command line.
//
// Exit status: 0 done; 1 a scripted session failed; 2 bad arguments or no
// window could be opened.
#include <imgui.h>

#include <cstring>
#include <iostream>
#include <memory>

#include "core/process_memory.hpp"
#include "script.hpp"
#include "studio.hpp"
#include "window.hpp"

namespace {

constexpr int kExitScriptFailed = 1;
constexpr int kExitBadInput = 2;
constexpr const char* kUsage =
    "usage: rise-studio [SCENE] [--script FILE]\n"
    "  SCENE          a scene file to open (YAML or JSON)\n"
    "  --script FILE  run a scripted session (see apps/studio/script.hpp) and quit\n";

}  // namespace

int main(int argc, char** argv) {
  rise::setUpProcessMemory();
  std::filesystem::path scene, scriptPath;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--script") == 0 && i + 1 < argc) {
      scriptPath = argv[++i];
    } else if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
      std::cout << kUsage;
      return 0;
    } else if (argv[i][0] == '-' || !scene.empty()) {
      std::cerr << "rise-studio: unexpected argument '" << argv[i] << "'\n" << kUsage;
      return kExitBadInput;
    } else {
      scene = argv[i];
    }
  }
  try {
    std::unique_ptr<rise::studio::Script> script;
    if (!scriptPath.empty()) script = std::make_unique<rise::studio::Script>(scriptPath);
    rise::studio::Window window(static_cast<int>(rise::studio::kLaidOutWidth),
                                static_cast<int>(rise::studio::kLaidOutHeight), "RISE Studio");
    // A scripted session lays the panels out afresh, whatever a user left.
    if (script) ImGui::GetIO().IniFilename = nullptr;
    rise::studio::Studio studio(scene);
    rise::Image screenshot;
    for (;;) {
      window.waitForInput(script ? 0.005 : studio.rendering() ? 1.0 / 30.0 : 0.1);
      window.beginFrame([&] {
        if (script) script->feedInput();
      });
      const bool going = studio.frame(window.closeRequested());
      window.setCloseRequested(false);
      window.endFrame(script && script->wantsScreenshot() ? &screenshot : nullptr);
      if (script) {
        script->afterFrame(studio, screenshot);
        if (script->done()) return script->failed() ? kExitScriptFailed : 0;
      }
      if (!going) return 0;
    }
  } catch (const std::exception& error) {
    std::cerr << "rise-studio: " << error.what() << "\n";
    return kExitBadInput;
  }
}
