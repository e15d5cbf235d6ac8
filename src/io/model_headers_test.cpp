// Model headers that promise what their files do not hold are refused before
// Assimp reads them, each with the promise it breaks.
#include "io/model_headers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/mesh_file.hpp"

namespace rise {
namespace {

std::vector<std::uint8_t> sydney() {
  std::ifstream file(std::filesystem::path(RISE_SOURCE_DIR) / "examples/models/sydney/sydney.md2",
                     std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

// Sydney with one 32-bit field of her header (counted from 0) replaced.
std::vector<std::uint8_t> sydneyWith(int field, std::int32_t value) {
  std::vector<std::uint8_t> file = sydney();
  for (int byte = 0; byte < 4; ++byte)
    file[4 * field + byte] =
        static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * byte));
  return file;
}

std::string md2Problem(const std::vector<std::uint8_t>& file) {
  try {
    checkedMd2Header(file);
  } catch (const MeshFileError& error) {
    return error.what();
  }
  return "";
}

TEST(Md2Header, ReadsSydneysCounts) {
  const std::vector<std::uint8_t> file = sydney();
  const Md2Header header = checkedMd2Header(file);
  EXPECT_EQ(header.vertices, 342);
  EXPECT_EQ(header.triangles.count, 679);
  EXPECT_EQ(header.frames.count, 198);
  EXPECT_TRUE(md2SkinNames(header, file).empty());
}

TEST(Md2Header, RefusesEachFieldThatBreaksItsPromise) {
  constexpr int kFrameSize = 4, kVertices = 6, kTexCoords = 7, kTriangles = 8, kSkins = 5;
  constexpr int kSkinsOffset = 11, kTrianglesOffset = 13, kEnd = 16;
  EXPECT_EQ(md2Problem(sydneyWith(kVertices, 0)), "the MD2 header gives no vertices");
  EXPECT_EQ(md2Problem(sydneyWith(kVertices, 100)),
            "the MD2 header is corrupt: a keyframe of 100 vertices takes 440 bytes, but the "
            "header says 1408");
  EXPECT_EQ(md2Problem(sydneyWith(kFrameSize, 2000000000)),
            "the file is cut short: its 198 keyframes should end at byte 396000010040, but it has "
            "302128 bytes");
  EXPECT_EQ(md2Problem(sydneyWith(kTriangles, 0)), "the MD2 header gives no triangles");
  EXPECT_EQ(md2Problem(sydneyWith(kTriangles, -3)), "the MD2 header gives no triangles");
  EXPECT_EQ(md2Problem(sydneyWith(kTriangles, 100000)),
            "the file is cut short: its 100000 triangles should end at byte 1201892, but it has "
            "302128 bytes");
  EXPECT_EQ(md2Problem(sydneyWith(kTrianglesOffset, 8)),
            "the MD2 header is corrupt: its 679 triangles start at byte 8");
  EXPECT_EQ(md2Problem(sydneyWith(kTexCoords, 2)),
            "triangle 0 refers to texture coordinate 2, but the model has 2");
  EXPECT_EQ(md2Problem(sydneyWith(kSkins, 1000000)),
            "the file is cut short: its 1000000 skin names should end at byte 64000068, but it "
            "has 302128 bytes");
  EXPECT_EQ(md2Problem(sydneyWith(kEnd, 400000)),
            "the file is cut short: its header says it ends at byte 400000, but it has 302128 "
            "bytes");
  // One skin name over the texture coordinates, which hold no 0 byte in 64.
  std::vector<std::uint8_t> unended = sydneyWith(kSkins, 1);
  std::fill(unended.begin() + 68, unended.begin() + 68 + 64, 'x');
  EXPECT_EQ(md2Problem(unended),
            "the MD2 header is corrupt: skin name 0 does not end within its 64 bytes");
  EXPECT_EQ(md2Problem(sydneyWith(kSkinsOffset, -1)), "");  // no skins: never read
}

TEST(Md2Header, RefusesATriangleOutsideTheVertices) {
  std::vector<std::uint8_t> file = sydney();
  file[1892] = 0xff;  // the first vertex index of the first triangle
  file[1893] = 0xff;
  EXPECT_EQ(md2Problem(file), "triangle 0 refers to vertex 65535, but the model has 342 vertices");
}

// The message a header check gives the whole file, or "" when it passes it.
std::string headerProblem(void (*check)(std::string_view, std::uintmax_t),
                          const std::string& file) {
  try {
    check(file, file.size());
  } catch (const MeshFileError& error) {
    return error.what();
  }
  return "";
}

std::string plyProblem(const std::string& file) { return headerProblem(checkPlyHeader, file); }

const std::string kTriangleHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nelement face FACES\n"
    "property list uchar int vertex_indices\nend_header\n";

std::string plyWithFaces(const std::string& faces, std::size_t bodyBytes) {
  std::string header = kTriangleHeader;
  header.replace(header.find("FACES"), 5, faces);
  return header + std::string(bodyBytes, '\0');
}

TEST(PlyHeader, RefusesCountsTheFileCannotHold) {
  // Three vertices of 12 bytes and a face of at least 1: 37 bytes.
  EXPECT_EQ(plyProblem(plyWithFaces("1", 37 + 12)), "");
  EXPECT_EQ(plyProblem(plyWithFaces("2000000000", 49)),
            "the file is cut short or corrupt: its PLY header promises 2000000000 'face' "
            "elements, of at least 2000000000 bytes, but 49 bytes follow the header");
  EXPECT_EQ(plyProblem(plyWithFaces("99999999999999999999", 49)),
            "the PLY header is corrupt: an element line without a count");
  EXPECT_EQ(plyProblem("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n"),
            "the PLY header is cut short: it has no 'end_header' line");
  EXPECT_EQ(plyProblem("solid cube\n"), "not a PLY model: it does not start with 'ply'");
}

TEST(PlyHeader, CountsTwoBytesAValueInText) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nend_header\n";
  EXPECT_EQ(plyProblem(header + "0 0\n1 0\n0 1\n1 1\n"), "");
  EXPECT_NE(plyProblem(header + "0 0\n1 0\n"), "");
}

TEST(OffHeader, RefusesCountsTheFileCannotHold) {
  const std::string triangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_NO_THROW(checkOffHeader(triangle, triangle.size()));
  const std::string huge = "OFF\n# a comment\n2000000000 1 0\n0 0 0\n";
  try {
    checkOffHeader(huge, huge.size());
    FAIL() << "2e9 vertices in 6 bytes passed";
  } catch (const MeshFileError& error) {
    EXPECT_STREQ(error.what(),
                 "the file is cut short or corrupt: its OFF header promises 2000000000 vertices "
                 "and 1 faces, but 6 bytes follow the header");
  }
}

std::string offProblem(const std::string& file) { return headerProblem(checkOffHeader, file); }

// Assimp reads a count's leading digits into 32 bits that wrap, so a count
// too long for any integer would still be trusted.
TEST(OffHeader, RefusesCountsOfAnyLength) {
  const std::string tooLong(58, '5');
  EXPECT_EQ(offProblem("OFF\n4 " + tooLong + " 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
            "the file is cut short or corrupt: its OFF header promises 4 vertices and " + tooLong +
                " faces, but 32 bytes follow the header");
  EXPECT_NE(offProblem("OFF\n4 4294967297 0\n0 0 0\n"), "");  // wraps to 1
}

// The counts are found where Assimp's reader finds them: after a keyword with
// prefixes, after an n-dimension, on the keyword's own line, or with no
// keyword at all.
TEST(OffHeader, FindsTheCountsWhereverTheReaderDoes) {
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  for (const std::string header :
       {"OFF 3 1 0\n", "COFF\n3 1 0\n", "STCNOFF\n3 1 0\n", "nOFF\n3\n3 1 0\n",
        "# a model\nOFF # the keyword\n\n3 1 0\n", "3 1 0\n"}) {
    EXPECT_EQ(offProblem(header + body), "") << header;
    std::string huge = header;
    huge.replace(huge.rfind("3 1"), 3, "3 3000000000");
    EXPECT_NE(offProblem(huge + body), "") << huge;
  }
  EXPECT_EQ(offProblem("OFF\n\n"), "");                // no counts: Assimp refuses it
  EXPECT_EQ(offProblem("OFF\nx 3000000000 0\n"), "");  // no vertices: Assimp refuses it
  EXPECT_EQ(offProblem("solid x\n"), "");              // not an OFF header: Assimp refuses it
}

}  // namespace
}  // namespace rise
