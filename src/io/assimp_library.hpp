// Assimp's functions (its C interface), from its library, loaded when the
// first model is read: a scene without one does not pay for loading it.
#pragma once

#include <assimp/cimport.h>
#include <assimp/material.h>

#include "core/shared_library.hpp"

namespace rise {

struct AssimpFunctions {
  SharedLibrary library{RISE_ASSIMP_LIBRARY};
  RISE_LIBRARY_FUNCTION(library, aiCreatePropertyStore);
  RISE_LIBRARY_FUNCTION(library, aiSetImportPropertyInteger);
  RISE_LIBRARY_FUNCTION(library, aiReleasePropertyStore);
  RISE_LIBRARY_FUNCTION(library, aiImportFileExWithProperties);
  RISE_LIBRARY_FUNCTION(library, aiApplyPostProcessing);
  RISE_LIBRARY_FUNCTION(library, aiReleaseImport);
  RISE_LIBRARY_FUNCTION(library, aiGetErrorString);
  RISE_LIBRARY_FUNCTION(library, aiGetMaterialColor);
  RISE_LIBRARY_FUNCTION(library, aiGetMaterialFloatArray);
  RISE_LIBRARY_FUNCTION(library, aiGetMaterialString);
  RISE_LIBRARY_FUNCTION(library, aiGetMaterialTexture);
};

inline const AssimpFunctions& loadedAssimp() {
  static const AssimpFunctions functions;
  return functions;
}

}  // namespace rise
