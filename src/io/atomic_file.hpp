// Output files that are whole or absent: a file appears under its name only
// once it is completely written, so that a viewer, a later run or a full
// disk never leaves half an image, an empty table or a cut JSON file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace rise {

// A file that cannot be written; the message names it and the cause.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file written under a name unique to this process and call, in the
// target's own folder, so that the final rename stays on one file system and
// is atomic. Destroyed without commit(), or when the process is interrupted
// (interrupted_writes.hpp), it deletes itself. Standard output ("-") and a
// target that is not a regular file (a pipe, a device) are written in place.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Failures are remembered and reported by commit() rather than thrown:
  // OpenEXR writes its final offsets from a destructor, which cannot throw.
  void write(const void* data, std::size_t size);
  std::uint64_t position() const;
  void seek(std::uint64_t position);

  // Puts the file in place of the target. Throws OutputFileError when any
  // write failed (a full disk) or the rename does.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;  // empty for a target written in place
  std::FILE* file_ = nullptr;
  int error_ = 0;
  bool committed_ = false;
};

// Writes `text` to `path` whole or not at all. Throws OutputFileError.
void writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace rise
