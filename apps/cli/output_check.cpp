#include "output_check.hpp"

#include <system_error>

namespace rise::cli {
namespace {

// The path as the file system will resolve it, for comparing two names.
std::filesystem::path resolved(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return error ? std::filesystem::absolute(path).lexically_normal() : canonical;
}

// Whether two names are one file: the same path once links are followed,
// or, for files that exist, the same file by other names (hard links).
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  if (resolved(a) == resolved(b)) return true;
  std::error_code error;
  return std::filesystem::equivalent(a, b, error) && !error;
}

// The nearest folder above `path` that exists.
std::filesystem::path existingAncestor(const std::filesystem::path& path) {
  std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  std::error_code error;
  while (!std::filesystem::exists(folder, error) && folder.has_relative_path())
    folder = folder.parent_path();
  return folder;
}

// Why the file system would not take the name at all (longer than it
// allows, a loop of links), or nothing.
std::string nameProblem(const std::filesystem::path& path) {
  std::error_code error;
  (void)std::filesystem::status(path, error);
  // A missing file, or a folder on the way that is missing or a file, is
  // for folderProblem to tell.
  if (!error || error == std::errc::no_such_file_or_directory ||
      error == std::errc::not_a_directory)
    return {};
  return "cannot be written (" + error.message() + ")";
}

// "'name'", built by appending: GCC 12 warns falsely on "'" + string.
std::string quoted(const std::filesystem::path& path) {
  return std::string(1, '\'').append(path.string()).append(1, '\'');
}

std::string folderProblem(const std::filesystem::path& path, bool foldersAreMade) {
  const std::filesystem::path folder =
      path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  if (std::filesystem::is_directory(folder)) return {};
  if (!foldersAreMade) {
    if (std::filesystem::exists(folder)) return quoted(folder).append(" is not a folder");
    return std::string("the folder ").append(quoted(folder)).append(" does not exist");
  }
  const std::filesystem::path ancestor = existingAncestor(path);
  if (std::filesystem::is_directory(ancestor)) return {};
  return quoted(ancestor).append(" is a file, not a folder to write into");
}

}  // namespace

std::string outputsProblem(const std::vector<PlannedOutput>& outputs, const std::string& scenePath,
                           bool foldersAreMade) {
  const bool sceneIsFile = scenePath != "-";
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const PlannedOutput& output = outputs[i];
    const std::string named = output.option + " " + output.path.string() + ": ";
    if (std::string problem = nameProblem(output.path); !problem.empty()) return named + problem;
    if (std::filesystem::is_directory(output.path))
      return named + "is a folder; expected a file to write";
    if (std::string problem = folderProblem(output.path, foldersAreMade); !problem.empty())
      return named + problem;
    if (sceneIsFile && sameFile(output.path, scenePath))
      return named + "is the scene file; RISE never writes over its input";
    for (std::size_t j = 0; j < i; ++j) {
      if (sameFile(outputs[j].path, output.path))
        return named + "is the file " + outputs[j].option + " names too; expected another name";
    }
  }
  return {};
}

}  // namespace rise::cli
