#include "file_browser.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

namespace rise::studio {
namespace {

constexpr std::size_t kRecentFiles = 10;

std::filesystem::path configFolder() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config != nullptr && *config != '\0')
    return std::filesystem::path(config) / "rise-studio";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return std::filesystem::path(home) / ".config" / "rise-studio";
  return {};
}

bool isSceneFile(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".yaml" || extension == ".yml" || extension == ".json";
}

}  // namespace

RecentFiles::RecentFiles() {
  const std::filesystem::path folder = configFolder();
  if (folder.empty()) return;
  file_ = folder / "recent";
  std::ifstream in(file_);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) paths_.emplace_back(line);
}

void RecentFiles::add(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  std::erase(paths_, absolute);
  paths_.insert(paths_.begin(), absolute);
  if (paths_.size() > kRecentFiles) paths_.resize(kRecentFiles);
  if (file_.empty()) return;
  std::filesystem::create_directories(file_.parent_path(), error);
  std::ofstream out(file_);
  for (const std::filesystem::path& recent : paths_) out << recent.string() << "\n";
}

void FileBrowser::show(Purpose purpose, std::string title, const std::filesystem::path& start,
                       std::function<void(const std::filesystem::path&)> chosen) {
  purpose_ = purpose;
  title_ = std::move(title);
  std::error_code error;
  const bool isFolder = std::filesystem::is_directory(start, error);
  folder_ =
      std::filesystem::absolute(isFolder || start.empty() ? start : start.parent_path(), error);
  if (folder_.empty()) folder_ = std::filesystem::current_path(error);
  name_ = isFolder || purpose == Purpose::Folder ? "" : start.filename().string();
  chosen_ = std::move(chosen);
  opening_ = true;
  problem_.clear();
}

void FileBrowser::drawEntries() {
  std::vector<std::filesystem::directory_entry> folders, files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
    if (entry.path().filename().string().starts_with(".")) continue;
    if (entry.is_directory(error))
      folders.push_back(entry);
    else if (purpose_ != Purpose::Open || isSceneFile(entry.path()))
      files.push_back(entry);
  }
  if (error) problem_ = folder_.string() + ": " + error.message();
  std::ranges::sort(folders);
  std::ranges::sort(files);
  ImGui::BeginChild("entries", {0, -ImGui::GetFrameHeightWithSpacing() * 3}, true);
  if (ImGui::Selectable("..", false, ImGuiSelectableFlags_AllowDoubleClick) &&
      ImGui::IsMouseDoubleClicked(0))
    folder_ = folder_.parent_path();
  for (const auto& entry : folders) {
    const std::string label = entry.path().filename().string() + "/";
    if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) {
      if (purpose_ == Purpose::Folder) name_ = entry.path().filename().string();
      if (ImGui::IsMouseDoubleClicked(0)) folder_ = entry.path();
    }
  }
  for (const auto& entry : files) {
    const std::string name = entry.path().filename().string();
    if (ImGui::Selectable(name.c_str(), name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
      name_ = name;
      if (ImGui::IsMouseDoubleClicked(0) && purpose_ == Purpose::Open) {
        chosen_(folder_ / name_);
        ImGui::CloseCurrentPopup();
      }
    }
  }
  ImGui::EndChild();
}

void FileBrowser::draw(const RecentFiles& recent) {
  if (opening_) {
    ImGui::OpenPopup("Files");
    opening_ = false;
  }
  ImGui::SetNextWindowSize({640, 460}, ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal("Files")) return;
  ImGui::TextUnformatted(title_.c_str());
  std::string folder = folder_.string();
  if (ImGui::InputText("Folder", &folder, ImGuiInputTextFlags_EnterReturnsTrue)) folder_ = folder;
  if (purpose_ == Purpose::Open && !recent.paths().empty()) {
    if (ImGui::BeginCombo("Recent", "recently opened scenes")) {
      for (const std::filesystem::path& path : recent.paths())
        if (ImGui::Selectable(path.string().c_str())) {
          folder_ = path.parent_path();
          name_ = path.filename().string();
        }
      ImGui::EndCombo();
    }
  }
  drawEntries();
  const char* nameLabel = purpose_ == Purpose::Folder ? "Folder name" : "File name";
  ImGui::InputText(nameLabel, &name_);
  const bool confirm = ImGui::Button(purpose_ == Purpose::Open ? "Open" : "Save");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  if (!problem_.empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", problem_.c_str());
  if (confirm && (!name_.empty() || purpose_ == Purpose::Folder)) {
    chosen_(name_.empty() ? folder_ : folder_ / name_);
    ImGui::CloseCurrentPopup();
  }
  if (cancel) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace rise::studio
