#include "io/file_limits.hpp"

#include <system_error>
#include <vector>

namespace rise {

std::string megabytes(std::uintmax_t bytes) {
  return std::to_string((bytes + 500'000) / 1'000'000) + " MB";
}

std::optional<std::string> fileKindOrSizeProblem(const std::filesystem::path& path,
                                                 std::uintmax_t limit) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error == std::errc::too_many_symbolic_link_levels)
    return "cannot open the file: its symbolic links lead round in a loop";
  if (error || status.type() == std::filesystem::file_type::not_found) return std::nullopt;
  if (std::filesystem::is_directory(status))
    return "cannot open the file (" + std::make_error_code(std::errc::is_a_directory).message() +
           ")";
  if (!std::filesystem::is_regular_file(status))
    return "not a regular file (a device or a pipe); expected a file on disk";
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return "cannot read the file (" + error.message() + ")";
  if (size > limit)
    return "the file is " + megabytes(size) + ", larger than the " + megabytes(limit) +
           " that RISE reads";
  return std::nullopt;
}

std::optional<std::string> readAtMost(std::istream& in, std::uintmax_t limit) {
  constexpr std::size_t kChunk = 1 << 16;
  std::string text;
  std::vector<char> chunk(kChunk);
  while (in && text.size() <= limit) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (text.size() > limit) return std::nullopt;
  return text;
}

}  // namespace rise
