// Every class of bad input that once crashed RISE, hung it or let it take all
// the memory, given to the `rise` binary as a user would give it
// (support/bad_input_testing.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "support/bad_input_testing.hpp"
#include "support/png_header_testing.hpp"
#include "support/rise_process_testing.hpp"
#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;
using bad_input_testing::BadInput;
using bad_input_testing::expectRefusedAtOnce;
using bad_input_testing::nameOf;
using process_testing::Limits;
using process_testing::Outcome;
using process_testing::runRise;

const fs::path kExamples = fs::path(RISE_SOURCE_DIR) / "examples";
const std::string kCamera = "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n";

std::string withObject(const std::string& object) {
  return kCamera + "materials: {m: {}}\nobjects:\n  - " + object + "\n";
}

// Sydney's header with the vertex count made 0: Assimp crashed on it.
std::string sydneyWithoutVertices() {
  std::ifstream file(kExamples / "models/sydney/sydney.md2", std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(file), {}};
  for (int byte = 0; byte < 4; ++byte) bytes[24 + byte] = 0;
  return bytes;
}
std::vector<BadInput> badInputs() {
  const std::string render = "render";
  const std::string out = "DIR/out.png";
  return {
      {"leading_comma",
       {{"s.yaml", ",\n"}},
       {"validate", "DIR/s.yaml"},
       "/dev/null",
       2,
       "s.yaml:1:1: invalid YAML: unexpected ','"},
      {"comma_after_a_comment",
       {{"s.yaml", "# a scene\n,\n"}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "s.yaml:2:1: invalid YAML: unexpected ','"},
      {"deep_nesting",
       {{"s.yaml", std::string(100000, '[')}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "nested more than 64 deep"},
      {"zeros_as_the_scene",
       {},
       {render, "/dev/zero", "-o", out},
       "/dev/null",
       2,
       "/dev/zero: not a regular file (a device or a pipe); expected a file on disk"},
      {"noise_as_the_scene",
       {},
       {render, "/dev/urandom", "-o", out},
       "/dev/null",
       2,
       "/dev/urandom: not a regular file (a device or a pipe)"},
      {"zeros_on_standard_input",
       {},
       {render, "-", "-o", out},
       "/dev/zero",
       2,
       "<stdin>: the scene file is larger than the 16 MB"},
      {"noise_on_standard_input",
       {},
       {"validate", "-"},
       "/dev/urandom",
       2,
       "<stdin>: the scene file is larger than the 16 MB"},
      {"zeros_as_a_model",
       {{"s.yaml", withObject("mesh: {file: /dev/zero, material: m}")}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "not a regular file"},
      {"md2_of_no_vertices",
       {{"s.yaml", withObject("mesh: {file: empty.md2, material: m}")},
        {"empty.md2", sydneyWithoutVertices()}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "the MD2 header gives no vertices"},
      {"ply_of_2e9_faces",
       {{"s.yaml", withObject("mesh: {file: huge.ply, material: m}")},
        {"huge.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
         "property float y\nproperty float z\nelement face 2000000000\n"
         "property list uchar int vertex_indices\nend_header\n" +
             std::string(36, '\0')}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "its PLY header promises 2000000000 'face' elements"},
      {"obj_with_a_line_among_triangles",
       {{"s.yaml", withObject("mesh: {file: line.obj, material: m}")},
        {"line.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n"}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "a face has fewer than 3 corners (a line or a point) among faces of 3 or more (Assimp: "},
      {"image_of_10000_by_10000_pixels",
       {{"s.yaml", kCamera + "materials: {m: {texture: {image: huge.png}}}\nobjects: []\n"},
        {"huge.png", pngHeader(10000, 10000)}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "the image is 10000 x 10000 pixels, more than the 33554432 (8192 x 4096)"},
      {"image_cut_short",
       {{"s.yaml", kCamera + "materials: {m: {texture: {image: cut.png}}}\nobjects: []\n"},
        {"cut.png", pngHeader(4, 4)}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "the image data is corrupt or cut short (stb_image: "},
      {"width_of_a_billion",
       {{"s.yaml", "image: {width: 1000000000}\n" + kCamera + "objects: []\n"}},
       {"validate", "DIR/s.yaml"},
       "/dev/null",
       2,
       "'width' in image is 1000000000; expected a whole number of pixels from 1 to 32768"},
      {"image_too_large_for_the_memory",
       {},
       {render, (kExamples / "classic.yaml").string(), "--width", "32768", "--height", "32768",
        "-o", out},
       "/dev/null",
       2,
       "a 32768 x 32768 image with 1 sample a pixel needs about"},
      {"two_billion_samples",
       {},
       {render, (kExamples / "classic.yaml").string(), "--samples", "2000000000", "-o", out},
       "/dev/null",
       2,
       "--samples: 2000000000; expected a whole number from 1 to 65536"},
      {"a_hundred_thousand_threads",
       {},
       {render, (kExamples / "classic.yaml").string(), "--threads", "100000", "-o", out},
       "/dev/null",
       2,
       "--threads: 100000; expected a whole number from 0 to 256"},
      {"glass_of_ior_1e30",
       {{"s.yaml", kCamera +
                       "materials: {glass: {transmission: 0.9, ior: 1e30}}\n"
                       "objects: [sphere: {center: [0, 0, 0], radius: 1, material: glass}]\n"}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "'ior' in material 'glass' is 1e30; expected a number from 0.1 to 10"},
      {"camera_1e30_away",
       {{"s.yaml", "camera: {position: [0, 0, -1e30], look_at: [0, 0, 0]}\nobjects: []\n"}},
       {render, "DIR/s.yaml", "-o", out},
       "/dev/null",
       2,
       "'look_at' in camera is 1e30 units from 'position'"},
      {"ray_tree_of_depth_64",
       {{"s.yaml", kCamera + "materials: {g: {reflection: 0.5, transmission: 0.5}}\n"
                             "objects: [sphere: {center: [0, 0, 0], radius: 1, material: g}]\n"}},
       {render, "DIR/s.yaml", "--max-depth", "64", "-o", out},
       "/dev/null",
       2,
       "as material 'g' both reflects and refracts"},
      {"jpeg_output",
       {},
       {render, (kExamples / "classic.yaml").string(), "-o", "DIR/out.jpg"},
       "/dev/null",
       2,
       "unsupported image format '.jpg'"},
      {"output_in_a_missing_folder",
       {},
       {render, (kExamples / "classic.yaml").string(), "-o", "DIR/missing/out.png"},
       "/dev/null",
       2,
       "does not exist"},
      {"full_disk",
       {},
       {render, (kExamples / "classic.yaml").string(), "--width", "64", "-o", out, "--stats",
        "DIR/stats.json"},
       "/dev/null",
       1,
       "out.png: cannot write (File too large)",
       100},
      {"full_disk_for_the_statistics",
       {},
       {render, (kExamples / "classic.yaml").string(), "--width", "8", "-o", out, "--stats",
        "DIR/stats.json"},
       "/dev/null",
       1,
       "stats.json: cannot write (File too large)",
       300,
       {"out.png"}},
      {"full_disk_for_a_comparison",
       {},
       {"compare", (kExamples / "classic.yaml").string(), "--width", "8", "--algorithms",
        "z-buffer", "-o", "DIR/compared"},
       "/dev/null",
       1,
       "cannot write (File too large)",
       1000,
       {"compared"}},
      {"unknown_command",
       {},
       {"rnder", (kExamples / "classic.yaml").string()},
       "/dev/null",
       2,
       "unknown command 'rnder'; expected one of: render, compare, validate, algorithms"},
      {"width_of_zero",
       {},
       {render, (kExamples / "classic.yaml").string(), "--width", "0"},
       "/dev/null",
       2,
       "--width: 0; expected a whole number from 1 to 32768\n"},
      {"misspelt_structure",
       {},
       {render, (kExamples / "classic.yaml").string(), "--accel", "bhv"},
       "/dev/null",
       2,
       "--accel: bhv; expected one of bvh, embree, none, spheres\n"},
      {"unknown_transparency",
       {},
       {render, (kExamples / "classic.yaml").string(), "--transparency", "glass"},
       "/dev/null",
       2,
       "--transparency: glass; expected one of a-buffer, sorted\n"},
      {"plane_size_nan",
       {},
       {render, (kExamples / "classic.yaml").string(), "--plane-size", "nan", "-a", "z-buffer",
        "-o", out},
       "/dev/null",
       2,
       "--plane-size: nan; expected a finite number > 0"},
      {"threshold_nan",
       {},
       {render, (kExamples / "classic.yaml").string(), "--threshold", "nan", "-o", out},
       "/dev/null",
       2,
       "--threshold: nan; expected a finite number > 0"},
      {"negative_seed",
       {},
       {render, (kExamples / "classic.yaml").string(), "--seed", "-1", "-o", out},
       "/dev/null",
       2,
       "--seed: -1; expected a whole number >= 0"},
      {"statistics_over_the_image",
       {},
       {render, (kExamples / "classic.yaml").string(), "-o", out, "--stats", out},
       "/dev/null",
       2,
       "is the file -o names too"},
      {"statistics_over_the_scene",
       {{"s.yaml", withObject("sphere: {center: [0, 0, 0], radius: "
                              "1, material: m}")}},
       {render, "DIR/s.yaml", "-o", out, "--stats", "DIR/s.yaml"},
       "/dev/null",
       2,
       "is the scene file; RISE never writes over its input"},
      {"comparison_into_a_file",
       {{"taken", "a file"}},
       {"compare", (kExamples / "classic.yaml").string(), "-o", "DIR/taken"},
       "/dev/null",
       2,
       "is a file; expected a folder"},
      {"steps_into_a_file",
       {{"taken", "a file"}},
       {"explain", (kExamples / "classic.yaml").string(), "--width", "8", "-o", "DIR/taken"},
       "/dev/null",
       2,
       "is a file, not a folder to write into"},
      {"steps_of_an_image_too_large_for_the_memory",
       {},
       {"explain", (kExamples / "classic.yaml").string(), "--width", "30000", "--height", "30000",
        "-o", "DIR/steps"},
       "/dev/null",
       2,
       "a 30000 x 30000 image"},
      {"ray_tree_over_the_scene",
       {{"s.yaml", withObject("sphere: {center: [0, 0, 0], radius: 1, material: m}")}},
       {"inspect", "DIR/s.yaml", "--pixel", "0,0", "-o", "DIR/s.yaml"},
       "/dev/null",
       2,
       "is the scene file; RISE never writes over its input"},
      {"face_buffer_of_a_ray_tracer",
       {},
       {render, (kExamples / "classic.yaml").string(), "--aov", "face", "-o", out},
       "/dev/null",
       2,
       "ray-tracing has no 'face' buffer"},
      {"scene_image_too_large_for_the_memory",
       {{"s.yaml", "image: {width: 30000, height: 30000}\n" + kCamera + "objects: []\n"}},
       {"validate", "DIR/s.yaml"},
       "/dev/null",
       2,
       "a 30000 x 30000 image"},
  };
}

class BadInputUnderLimits : public TemporaryFolderTest,
                            public ::testing::WithParamInterface<BadInput> {};

TEST_P(BadInputUnderLimits, IsRefusedAtOnceWithItsMessageAndNoOutput) {
  expectRefusedAtOnce(GetParam(), directory_);
}

INSTANTIATE_TEST_SUITE_P(Resources, BadInputUnderLimits, ::testing::ValuesIn(badInputs()), nameOf);

// Checking a model's header reads the file, not as much as the largest file
// RISE would take (128 MB): the report's MD2 scene loads in 172 MB of address
// space, shared libraries included.
TEST(Resources, CheckingAModelTakesMemoryInProportionToItsFile) {
#ifdef RISE_SANITIZED_BUILD
  GTEST_SKIP() << "a sanitized build takes its address space by terabytes";
#endif
  Limits limits;
  limits.addressSpaceBytes = 172'000'000;
  const Outcome outcome = runRise({"validate", (kExamples / "md2.yaml").string()}, limits);
  EXPECT_EQ(outcome.status, 0) << outcome.output;
}

}  // namespace
}  // namespace rise
