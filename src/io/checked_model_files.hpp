// The files Assimp opens while it reads a model: the model's own and the side
// files it names (an OBJ's materials, a glTF's buffers), each asked first
// what every file RISE reads is asked (fileKindOrSizeProblem), so that a
// side file that is a pipe cannot block the load forever, nor a device fill
// the memory. A file refused is not opened, and the load is refused with its
// name and why.
#pragma once

#include <assimp/cfileio.h>

#include <optional>
#include <string>

namespace rise {

class CheckedModelFiles {
 public:
  CheckedModelFiles();
  CheckedModelFiles(const CheckedModelFiles&) = delete;
  CheckedModelFiles& operator=(const CheckedModelFiles&) = delete;

  // What Assimp's importers open files through.
  aiFileIO* io() { return &io_; }

  // The first file refused, and why: "side.mtl: not a regular file (...)".
  const std::optional<std::string>& refused() const { return refused_; }

 private:
  static aiFile* open(aiFileIO* io, const char* path, const char* mode);
  static void close(aiFileIO* io, aiFile* file);

  aiFileIO io_;
  std::optional<std::string> refused_;
};

}  // namespace rise
