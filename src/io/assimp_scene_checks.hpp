// Assimp's scene checked and repaired where Assimp 5.2 would crash on it,
// and Assimp's messages put in the words of the person who chose the file.
#pragma once

#include <assimp/scene.h>

#include <string>

namespace rise {

// Assimp's messages, on one line, with single spaces.
std::string tidied(const std::string& message);

// What Assimp's message means for the person who chose the file, with
// Assimp's own words after it for whoever looks deeper.
std::string explained(const std::string& message);

// Sets the kinds of faces (points, lines, triangles, polygons) each mesh
// has to those its faces have. A loader may leave them wrong (a PLY file that
// declares its faces twice leaves faces of no corners flagged as polygons),
// and Assimp's triangulation then stops the program on an assertion rather
// than report an error. Faces of no corners are refused.
void checkFacesAndTheirTypes(aiScene& scene);

// FindInvalidData fails when it drops every mesh, and aiApplyPostProcessing
// in Assimp 5.2 then frees the scene a second time and crashes: that file is
// refused before.
void checkSomeMeshKeepsItsPoints(const aiScene& scene);

}  // namespace rise
