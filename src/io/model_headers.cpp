#include "io/model_headers.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>
#include <optional>

#include "core/text.hpp"
#include "io/mesh_file.hpp"

namespace rise {

namespace {

constexpr std::int64_t kMd2SkinNameSize = 64;
constexpr std::int64_t kMd2TexCoordSize = 4;   // two 16-bit integers
constexpr std::int64_t kMd2TriangleSize = 12;  // three vertex and three texture indices
constexpr std::int64_t kMd2GlCommandSize = 4;
constexpr std::int64_t kMd2FrameHeaderSize = 40;  // scale, translation, name
constexpr std::int64_t kMd2FrameVertexSize = 4;   // x, y, z and a normal index

std::int32_t littleEndian32(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(bytes[at]) |
                                   static_cast<std::uint32_t>(bytes[at + 1]) << 8 |
                                   static_cast<std::uint32_t>(bytes[at + 2]) << 16 |
                                   static_cast<std::uint32_t>(bytes[at + 3]) << 24);
}

std::uint16_t littleEndian16(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::uint16_t>(bytes[at] | bytes[at + 1] << 8);
}

Md2Header readMd2Fields(std::span<const std::uint8_t> file) {
  const auto field = [&](int index) -> std::int64_t { return littleEndian32(file, 4 * index); };
  Md2Header header;
  header.skinWidth = field(2);
  header.skinHeight = field(3);
  header.frameSize = field(4);
  header.skins = {field(5), field(11)};
  header.vertices = field(6);
  header.texCoords = {field(7), field(12)};
  header.triangles = {field(8), field(13)};
  header.glCommands = {field(9), field(15)};
  header.frames = {field(10), field(14)};
  header.end = field(16);
  return header;
}

MeshFileError cutShort(std::int64_t count, const std::string& what, std::int64_t end,
                       std::size_t size) {
  return MeshFileError("the file is cut short: its " + std::to_string(count) + " " + what +
                       " should end at byte " + std::to_string(end) + ", but it has " +
                       std::to_string(size) + " bytes");
}

// The keyframes first: the part that makes up most of a model, and the first
// to go when a file is cut short.
void checkMd2Keyframes(const Md2Header& header, std::size_t size) {
  if (header.frames.count < 1) throw MeshFileError("the MD2 header gives no keyframes");
  if (header.frames.offset < static_cast<std::int64_t>(kMd2HeaderSize) || header.frameSize <= 0)
    throw MeshFileError("the MD2 header is corrupt: its keyframes start at byte " +
                        std::to_string(header.frames.offset) + " and take " +
                        std::to_string(header.frameSize) + " bytes each");
  const std::int64_t end = header.frames.offset + header.frames.count * header.frameSize;
  if (end > static_cast<std::int64_t>(size))
    throw cutShort(header.frames.count, "keyframes", end, size);
  if (header.vertices < 1) throw MeshFileError("the MD2 header gives no vertices");
  const std::int64_t frameSize = kMd2FrameHeaderSize + kMd2FrameVertexSize * header.vertices;
  if (header.frameSize != frameSize)
    throw MeshFileError("the MD2 header is corrupt: a keyframe of " +
                        std::to_string(header.vertices) + " vertices takes " +
                        std::to_string(frameSize) + " bytes, but the header says " +
                        std::to_string(header.frameSize));
}

void checkMd2Part(const Md2Header::Part& part, std::int64_t itemSize, const std::string& what,
                  std::size_t size) {
  if (part.count < 0 || (part.count > 0 && part.offset < static_cast<std::int64_t>(kMd2HeaderSize)))
    throw MeshFileError("the MD2 header is corrupt: its " + std::to_string(part.count) + " " +
                        what + " start at byte " + std::to_string(part.offset));
  const std::int64_t end = part.offset + part.count * itemSize;
  if (part.count > 0 && end > static_cast<std::int64_t>(size))
    throw cutShort(part.count, what, end, size);
}

void checkMd2Triangles(const Md2Header& header, std::span<const std::uint8_t> file) {
  for (std::int64_t i = 0; i < header.triangles.count; ++i) {
    const std::size_t at = static_cast<std::size_t>(header.triangles.offset + i * kMd2TriangleSize);
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint16_t vertex = littleEndian16(file, at + 2 * corner);
      const std::uint16_t texCoord = littleEndian16(file, at + 6 + 2 * corner);
      if (vertex >= header.vertices)
        throw MeshFileError("triangle " + std::to_string(i) + " refers to vertex " +
                            std::to_string(vertex) + ", but the model has " +
                            std::to_string(header.vertices) + " vertices");
      if (header.texCoords.count > 0 && texCoord >= header.texCoords.count)
        throw MeshFileError("triangle " + std::to_string(i) + " refers to texture coordinate " +
                            std::to_string(texCoord) + ", but the model has " +
                            std::to_string(header.texCoords.count));
    }
  }
}

}  // namespace

Md2Header checkedMd2Header(std::span<const std::uint8_t> file) {
  if (file.size() < kMd2HeaderSize)
    throw MeshFileError("the file is too short for an MD2 header: " + std::to_string(file.size()) +
                        " of " + std::to_string(kMd2HeaderSize) + " bytes");
  if (std::memcmp(file.data(), "IDP2", 4) != 0)
    throw MeshFileError("not an MD2 model: it does not start with 'IDP2'");
  if (const std::int32_t version = littleEndian32(file, 4); version != 8)
    throw MeshFileError("MD2 version " + std::to_string(version) + "; expected 8");
  const Md2Header header = readMd2Fields(file);
  checkMd2Keyframes(header, file.size());
  if (header.triangles.count < 1) throw MeshFileError("the MD2 header gives no triangles");
  if (header.skinWidth < 0 || header.skinHeight < 0)
    throw MeshFileError("the MD2 header is corrupt: its skin is " +
                        std::to_string(header.skinWidth) + " x " +
                        std::to_string(header.skinHeight) + " pixels");
  checkMd2Part(header.skins, kMd2SkinNameSize, "skin names", file.size());
  checkMd2Part(header.texCoords, kMd2TexCoordSize, "texture coordinates", file.size());
  checkMd2Part(header.triangles, kMd2TriangleSize, "triangles", file.size());
  checkMd2Part(header.glCommands, kMd2GlCommandSize, "OpenGL commands", file.size());
  if (header.end > static_cast<std::int64_t>(file.size()) || header.end < 0)
    throw MeshFileError("the file is cut short: its header says it ends at byte " +
                        std::to_string(header.end) + ", but it has " + std::to_string(file.size()) +
                        " bytes");
  checkMd2Triangles(header, file);
  for (std::int64_t i = 0; i < header.skins.count; ++i) {
    const std::uint8_t* name = file.data() + header.skins.offset + i * kMd2SkinNameSize;
    if (std::find(name, name + kMd2SkinNameSize, 0) == name + kMd2SkinNameSize)
      throw MeshFileError("the MD2 header is corrupt: skin name " + std::to_string(i) +
                          " does not end within its 64 bytes");
  }
  return header;
}

std::vector<std::string> md2SkinNames(const Md2Header& header, std::span<const std::uint8_t> file) {
  std::vector<std::string> names;
  for (std::int64_t i = 0; i < header.skins.count; ++i)
    names.emplace_back(
        reinterpret_cast<const char*>(file.data() + header.skins.offset + i * kMd2SkinNameSize));
  return names;
}

namespace {

std::vector<std::string_view> wordsOf(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t start = line.find_first_not_of(" \t\r", at);
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r", start), line.size());
    words.push_back(line.substr(start, end - start));
    at = end;
  }
  return words;
}

std::optional<std::uint64_t> countIn(std::string_view word) {
  std::uint64_t count = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), count);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return count;
}

// The bytes of a binary PLY value type; 0 for a name PLY does not have.
std::uint64_t plyTypeSize(std::string_view type) {
  const std::string name = lowercase(type);
  for (const auto& [size, names] :
       {std::pair{1, "char int8 uchar uint8"}, std::pair{2, "short int16 ushort uint16"},
        std::pair{4, "int int32 uint uint32 float float32"}, std::pair{8, "double float64"}}) {
    for (std::string_view known : wordsOf(names))
      if (known == name) return static_cast<std::uint64_t>(size);
  }
  return 0;
}

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t leastSize = 0;  // the bytes of one element at the least
};

// The least bytes a property takes: in text a digit and a space; in binary
// its value, or a list's count with no items.
std::uint64_t leastPropertySize(const std::vector<std::string_view>& words, bool text) {
  if (text) return 2;
  const bool list = words.size() >= 3 && lowercase(words[1]) == "list";
  return plyTypeSize(words.size() >= 2 ? words[list ? 2 : 1] : "");
}

// Refuses a header line that Assimp's PLY reader could loop on instead of
// reporting: a keyword PLY does not have, or a property of a type it does
// not have.
void checkPlyHeaderLine(const std::vector<std::string_view>& words, int line) {
  const auto corrupt = [&](const std::string& what) {
    return MeshFileError("the PLY header is corrupt: line " + std::to_string(line) + ": " + what);
  };
  const std::string keyword = lowercase(words[0]);
  if (keyword != "ply" && keyword != "format" && keyword != "comment" && keyword != "obj_info" &&
      keyword != "element" && keyword != "property")
    throw corrupt("'" + std::string(words[0]) +
                  "' is not a PLY keyword (format, element, property, comment, end_header)");
  if (keyword != "property") return;
  const bool list = words.size() >= 2 && lowercase(words[1]) == "list";
  const std::size_t typesEnd = list ? 4 : 2;
  if (words.size() < typesEnd + 1)
    throw corrupt("a property needs a type and a name" +
                  std::string(list ? " (a list: two types and a name)" : ""));
  for (std::size_t type = list ? 2 : 1; type < typesEnd; ++type)
    if (plyTypeSize(words[type]) == 0)
      throw corrupt("'" + std::string(words[type]) +
                    "' is not a PLY type (char, uchar, short, ushort, int, uint, float, double)");
}

// The vertex and face counts of an OFF file, as the digits Assimp's reader
// takes for them, and where the lines after them start.
struct OffCounts {
  std::string_view vertices;
  std::string_view faces;
  std::size_t bodyStart = 0;
};

// Follows Assimp's reader, which trusts the counts it finds: a keyword of
// optional prefixes (ST, C, N, 4, n) and OFF, or none; a dimension when the
// prefix has n; then the counts, each as the digits a word starts with, read
// into 32 bits that wrap. Nothing where the reader refuses the header itself.
std::optional<OffCounts> offCountsAsAssimpReadsThem(std::string_view text) {
  std::size_t at = 0;
  const auto isDigitAt = [&](std::size_t i) {
    return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) != 0;
  };
  const auto skipToNextToken = [&] {
    for (;;) {
      at = std::min(text.find_first_not_of(" \t\r\n", at), text.size());
      if (at == text.size() || text[at] != '#') return;
      at = std::min(text.find('\n', at), text.size());
    }
  };
  const auto takes = [&](std::string_view prefix) {
    if (!text.substr(at).starts_with(prefix)) return false;
    at += prefix.size();
    return true;
  };
  const auto digits = [&] {
    const std::size_t first = at;
    while (isDigitAt(at)) ++at;
    return text.substr(first, at - first);
  };
  skipToNextToken();
  takes("ST");
  takes("C");
  takes("N");
  takes("4");
  const bool hasDimension = takes("n");
  const bool hasKeyword = takes("OFF");
  skipToNextToken();
  if (!hasKeyword && !isDigitAt(at)) return std::nullopt;
  if (hasDimension) {
    digits();
    skipToNextToken();
  }
  OffCounts counts;
  counts.vertices = digits();
  skipToNextToken();
  counts.faces = digits();
  counts.bodyStart = std::min(text.find('\n', at), text.size()) + 1;
  return counts;
}

// Whether the count written as `digits` exceeds `most`, however many digits
// it has.
bool countBeyond(std::string_view digits, std::uint64_t most) {
  const std::optional<std::uint64_t> count = countIn(digits);
  return !count || *count > most;
}

}  // namespace

void checkPlyHeader(std::string_view start, std::uintmax_t fileSize) {
  if (lowercase(start.substr(0, 3)) != "ply")
    throw MeshFileError("not a PLY model: it does not start with 'ply'");
  const std::size_t endLine = start.find("end_header");
  if (endLine == std::string_view::npos)
    throw MeshFileError("the PLY header is cut short: it has no 'end_header' line");
  const std::size_t bodyStart = start.find('\n', endLine);
  const std::vector<std::string_view> endWords =
      wordsOf(start.substr(endLine, bodyStart - endLine));
  if (start[endLine - 1] != '\n' || endWords.size() != 1 || endWords.front() != "end_header")
    throw MeshFileError("the PLY header is corrupt: 'end_header' is not a line of its own");
  bool text = false;
  std::vector<PlyElement> elements;
  std::size_t at = 0;
  int line = 0;
  while (at < endLine) {
    const std::size_t lineEnd = std::min(start.find('\n', at), endLine);
    const std::vector<std::string_view> words = wordsOf(start.substr(at, lineEnd - at));
    at = lineEnd + 1;
    ++line;
    if (words.empty()) continue;
    checkPlyHeaderLine(words, line);
    const std::string keyword = lowercase(words[0]);
    if (keyword == "format" && words.size() >= 2) text = lowercase(words[1]) == "ascii";
    if (keyword == "element") {
      const std::optional<std::uint64_t> count =
          words.size() >= 3 ? countIn(words[2]) : std::nullopt;
      if (!count) throw MeshFileError("the PLY header is corrupt: an element line without a count");
      elements.push_back({std::string(words[1]), *count, 0});
    }
    if (keyword == "property" && !elements.empty())
      elements.back().leastSize += leastPropertySize(words, text);
  }
  const std::uintmax_t body = bodyStart == std::string_view::npos ? 0 : fileSize - bodyStart - 1;
  for (const PlyElement& element : elements) {
    // At most 2^40 elements of at most 2^24 bytes keeps the product in range.
    const bool tooMany = element.count > (1ULL << 40) || element.leastSize > (1ULL << 24);
    const std::uint64_t least = tooMany ? 0 : element.count * element.leastSize;
    if (tooMany || least > body + 1)
      throw MeshFileError("the file is cut short or corrupt: its PLY header promises " +
                          std::to_string(element.count) + " '" + element.name +
                          "' elements, of at least " + std::to_string(least) + " bytes, but " +
                          std::to_string(body) + " bytes follow the header");
  }
}

void checkOffHeader(std::string_view start, std::uintmax_t fileSize) {
  // Assimp refuses a header without both counts (it reads no digits as 0).
  const std::optional<OffCounts> counts = offCountsAsAssimpReadsThem(start);
  if (!counts || counts->vertices.empty() || counts->faces.empty()) return;
  // A vertex or a face line holds at least a digit and its line's end.
  constexpr std::uint64_t kLeastLine = 2;
  const std::uintmax_t body = fileSize - std::min<std::uintmax_t>(counts->bodyStart, fileSize);
  const std::uint64_t most = body / kLeastLine + 1;
  if (countBeyond(counts->vertices, most) || countBeyond(counts->faces, most))
    throw MeshFileError("the file is cut short or corrupt: its OFF header promises " +
                        std::string(counts->vertices) + " vertices and " +
                        std::string(counts->faces) + " faces, but " + std::to_string(body) +
                        " bytes follow the header");
}

}  // namespace rise
