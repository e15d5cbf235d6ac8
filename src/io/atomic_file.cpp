#include "io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "io/interrupted_writes.hpp"

namespace rise {
namespace {

OutputFileError cannotWrite(const std::filesystem::path& path, const std::string& reason) {
  return OutputFileError(path.string() + ": cannot write (" + reason + ")");
}

// A name unique to this process and call, in the target's folder, and
// short whatever the target's length, so that a name the file system takes
// for the target it takes for the temporary too.
std::filesystem::path uniqueNameBeside(const std::filesystem::path& target) {
  static std::atomic<unsigned> writesStarted{0};
  return target.parent_path() /
         (".rise-" + std::to_string(getpid()) + "-" + std::to_string(writesStarted++) + ".tmp");
}

// A target written where it is, not renamed over: standard output ("-") and
// what is not a regular file (a terminal, a pipe, /dev/null, /dev/stdout),
// which a rename would replace with a regular file.
bool writtenInPlace(const std::filesystem::path& target) {
  if (target == "-") return true;
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(target, error);
  return !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
}

std::FILE* openInPlace(const std::filesystem::path& target) {
  if (target != "-") return std::fopen(target.c_str(), "wb");
  const int output = dup(STDOUT_FILENO);
  return output < 0 ? nullptr : fdopen(output, "wb");
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  if (writtenInPlace(target_)) {
    file_ = openInPlace(target_);
  } else {
    temporary_ = uniqueNameBeside(target_);
    file_ = std::fopen(temporary_.c_str(), "wb");
    if (file_ != nullptr) registerTemporary(temporary_);
  }
  if (file_ == nullptr) throw cannotWrite(target_, std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!temporary_.empty() && !committed_) {
    forgetTemporary(temporary_);
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicFile::write(const void* data, std::size_t size) {
  if (error_ == 0 && std::fwrite(data, 1, size, file_) != size) error_ = errno;
}

std::uint64_t AtomicFile::position() const { return static_cast<std::uint64_t>(ftello(file_)); }

void AtomicFile::seek(std::uint64_t position) {
  if (error_ == 0 && fseeko(file_, static_cast<off_t>(position), SEEK_SET) != 0) error_ = errno;
}

void AtomicFile::commit() {
  if (std::fclose(file_) != 0 && error_ == 0) error_ = errno;
  file_ = nullptr;
  if (error_ != 0) throw cannotWrite(target_, std::strerror(error_));
  if (temporary_.empty()) {
    committed_ = true;
    return;
  }
  std::error_code renameError;
  std::filesystem::rename(temporary_, target_, renameError);
  if (renameError) throw cannotWrite(target_, renameError.message());
  forgetTemporary(temporary_);
  committed_ = true;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace rise
