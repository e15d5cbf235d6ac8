// The studio's own file browser, a modal window: folders and files of the
// current folder (scene files only when opening a scene), a name to type,
// and the recently opened scenes, kept between sessions in
// $XDG_CONFIG_HOME/rise-studio/recent (or ~/.config/...).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rise::studio {

class RecentFiles {
 public:
  RecentFiles();
  const std::vector<std::filesystem::path>& paths() const { return paths_; }
  void add(const std::filesystem::path& path);

 private:
  std::filesystem::path file_;
  std::vector<std::filesystem::path> paths_;
};

class FileBrowser {
 public:
  enum class Purpose { Open, Save, Folder };

  // Opens the browser; `chosen` is called with the path the user picks.
  void show(Purpose purpose, std::string title, const std::filesystem::path& start,
            std::function<void(const std::filesystem::path&)> chosen);
  void draw(const RecentFiles& recent);

 private:
  void drawEntries();

  Purpose purpose_ = Purpose::Open;
  std::string title_;
  std::filesystem::path folder_;
  std::string name_;
  std::function<void(const std::filesystem::path&)> chosen_;
  bool opening_ = false;
  std::string problem_;
};

}  // namespace rise::studio
