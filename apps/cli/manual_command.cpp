#include "manual_command.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "job.hpp"

namespace rise::cli {
namespace {

struct ManualOptions {
  std::string language = "en";
  bool printPath = false;
};

// The manual is built beside the program (build/manual next to build/rise);
// the build folder is also remembered, for a program copied elsewhere.
std::vector<std::filesystem::path> manualFolders() {
  std::vector<std::filesystem::path> folders;
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) folders.push_back(program.parent_path() / "manual");
  folders.emplace_back(RISE_MANUAL_DIR);
  return folders;
}

std::optional<std::filesystem::path> firstPage(const std::string& language) {
  for (const std::filesystem::path& folder : manualFolders()) {
    const std::filesystem::path page = folder / language / "index.html";
    if (std::filesystem::is_regular_file(page)) return page;
  }
  return std::nullopt;
}

bool openInBrowser(const std::filesystem::path& page) {
  const std::string command = "xdg-open '" + page.string() + "' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

int showManual(const ManualOptions& options) {
  const std::optional<std::filesystem::path> page = firstPage(options.language);
  if (!page) {
    std::cerr << "rise: the manual is not built; build it with `cmake --build build --target "
                 "manual` (its packages: `scripts/install-deps --manual`)\n";
    return kExitOutputError;
  }
  if (options.printPath || !openInBrowser(*page)) std::cout << page->string() << "\n";
  return 0;
}

}  // namespace

std::function<std::optional<int>()> addManualCommand(CLI::App& app) {
  auto options = std::make_shared<ManualOptions>();
  CLI::App* command =
      app.add_subcommand("manual", "Open the manual in the browser (or print where it is)");
  command->add_option("--language", options->language, "en (English) or pt_BR (Portuguese)")
      ->check(CLI::IsMember({"en", "pt_BR"}));
  command->add_flag("--print-path", options->printPath,
                    "Only print the path of the manual's first page");
  return [=]() -> std::optional<int> {
    if (*command) return showManual(*options);
    return std::nullopt;
  };
}

}  // namespace rise::cli
