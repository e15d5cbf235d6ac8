#include "io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

namespace rise {
namespace {

OutputFileError cannotWrite(const std::filesystem::path& path, const std::string& reason) {
  return OutputFileError(path.string() + ": cannot write (" + reason + ")");
}

std::filesystem::path uniqueNameBeside(const std::filesystem::path& target) {
  static std::atomic<unsigned> writesStarted{0};
  std::filesystem::path name = target;
  name += ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(writesStarted++);
  return name;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(uniqueNameBeside(target_)) {
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (file_ == nullptr) throw cannotWrite(target_, std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_) {
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
  std::error_code renameError;
  std::filesystem::rename(temporary_, target_, renameError);
  if (renameError) throw cannotWrite(target_, renameError.message());
  committed_ = true;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view text) {
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace rise
