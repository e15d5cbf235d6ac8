#include "io/checked_model_files.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "io/file_limits.hpp"

namespace rise {

namespace {

std::FILE* fileOf(aiFile* file) { return reinterpret_cast<std::FILE*>(file->UserData); }

std::size_t read(aiFile* file, char* buffer, std::size_t size, std::size_t count) {
  return std::fread(buffer, size, count, fileOf(file));
}

// Models are only read.
std::size_t write(aiFile*, const char*, std::size_t, std::size_t) { return 0; }

std::size_t tell(aiFile* file) {
  const long position = std::ftell(fileOf(file));
  return position < 0 ? 0 : static_cast<std::size_t>(position);
}

std::size_t size(aiFile* file) {
  std::FILE* stream = fileOf(file);
  const long position = std::ftell(stream);
  std::fseek(stream, 0, SEEK_END);
  const long end = std::ftell(stream);
  std::fseek(stream, position, SEEK_SET);
  return end < 0 ? 0 : static_cast<std::size_t>(end);
}

aiReturn seek(aiFile* file, std::size_t offset, aiOrigin origin) {
  const int whence = origin == aiOrigin_CUR   ? SEEK_CUR
                     : origin == aiOrigin_END ? SEEK_END
                                              : SEEK_SET;
  return std::fseek(fileOf(file), static_cast<long>(offset), whence) == 0 ? aiReturn_SUCCESS
                                                                          : aiReturn_FAILURE;
}

void flush(aiFile*) {}

}  // namespace

CheckedModelFiles::CheckedModelFiles()
    : io_{&CheckedModelFiles::open, &CheckedModelFiles::close, reinterpret_cast<char*>(this)} {}

aiFile* CheckedModelFiles::open(aiFileIO* io, const char* path, const char* mode) {
  auto& files = *reinterpret_cast<CheckedModelFiles*>(io->UserData);
  if (mode == nullptr || mode[0] != 'r') return nullptr;
  if (const std::optional<std::string> problem = fileKindOrSizeProblem(path, kLargestModelFile)) {
    if (!files.refused_)
      files.refused_ = std::filesystem::path(path).filename().string() + ": " + *problem;
    return nullptr;
  }
  std::FILE* stream = std::fopen(path, "rb");
  if (stream == nullptr) return nullptr;
  return new aiFile{&read, &write, &tell, &size, &seek, &flush, reinterpret_cast<char*>(stream)};
}

void CheckedModelFiles::close(aiFileIO*, aiFile* file) {
  if (file == nullptr) return;
  std::fclose(fileOf(file));
  delete file;
}

}  // namespace rise
