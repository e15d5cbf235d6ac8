// What the tests of model files share: the example models, and a folder in
// which a test writes files of its own.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "support/temporary_folder_testing.hpp"

namespace rise::mesh_file_testing {

namespace fs = std::filesystem;

inline const fs::path kModels = fs::path(RISE_SOURCE_DIR) / "examples/models";
inline const fs::path kSydney = kModels / "sydney/sydney.md2";
inline const fs::path kRatamahatta = kModels / "ratamahatta/tris.md2";
inline const fs::path kSpot = kModels / "spot/spot_triangulated.obj";
inline const fs::path kTeapot = kModels / "utah-teapot/teapot-full_Mesh001.ply";
inline const fs::path kBunny = kModels / "stanford-bunny/stanford-bunny.obj";
inline const fs::path kCornellBox = kModels / "cornell-box/CornellBox-Original.obj";

// A cube in the OFF format: eight corners, six square faces.
inline constexpr const char* kCubeOff = R"(OFF
8 6 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3
)";

class MeshFiles : public TemporaryFolderTest {
 protected:
  fs::path write(const std::string& name, const std::string& contents) const {
    std::ofstream(directory_ / name, std::ios::binary) << contents;
    return directory_ / name;
  }

  // The first `bytes` bytes of a real model, as a file of its own.
  fs::path truncatedCopy(const fs::path& model, std::size_t bytes) const {
    std::ifstream in(model, std::ios::binary);
    std::string start(bytes, '\0');
    in.read(start.data(), static_cast<std::streamsize>(bytes));
    return write("cut-" + std::to_string(bytes) + model.extension().string(), start);
  }

  fs::path randomBytes(const std::string& name, std::size_t bytes) const {
    std::mt19937 generator(7);
    std::string contents(bytes, '\0');
    for (char& c : contents) c = static_cast<char>(generator() & 0xff);
    return write(name, contents);
  }
};

// A UV sphere of radius 1 as an OBJ without normals: 12 rings of 24 quads,
// with a vertex at each pole.
inline std::string sphereObj() {
  constexpr int kRings = 12;
  constexpr int kSegments = 24;
  std::string obj = "v 0 1 0\n";
  for (int ring = 1; ring < kRings; ++ring) {
    const float polar = kPi * static_cast<float>(ring) / kRings;
    for (int segment = 0; segment < kSegments; ++segment) {
      const float azimuth = 2.0f * kPi * static_cast<float>(segment) / kSegments;
      obj += "v " + std::to_string(std::sin(polar) * std::cos(azimuth)) + " " +
             std::to_string(std::cos(polar)) + " " +
             std::to_string(-std::sin(polar) * std::sin(azimuth)) + "\n";
    }
  }
  obj += "v 0 -1 0\n";
  const auto vertex = [](int ring, int segment) {  // OBJ indices start at 1
    return std::to_string(2 + (ring - 1) * kSegments + segment % kSegments);
  };
  const std::string south = std::to_string(2 + (kRings - 1) * kSegments);
  for (int segment = 0; segment < kSegments; ++segment) {
    obj += "f 1 " + vertex(1, segment) + " " + vertex(1, segment + 1) + "\n";
    for (int ring = 1; ring + 1 < kRings; ++ring)
      obj += "f " + vertex(ring, segment) + " " + vertex(ring + 1, segment) + " " +
             vertex(ring + 1, segment + 1) + " " + vertex(ring, segment + 1) + "\n";
    obj += "f " + vertex(kRings - 1, segment) + " " + south + " " +
           vertex(kRings - 1, segment + 1) + "\n";
  }
  return obj;
}

}  // namespace rise::mesh_file_testing
