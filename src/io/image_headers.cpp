#include "io/image_headers.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>

#include "core/memory_budget.hpp"
#include "core/text.hpp"
#include "io/file_limits.hpp"
#include "io/image_io.hpp"

namespace rise {
namespace {

// Enough of a file for any header stb_image reads: a Radiance HDR file's
// lines of text come before its size.
constexpr std::size_t kLongestHeader = 65536;
// Digits enough for any size, and few enough that their value fits.
constexpr std::size_t kMostSizeDigits = 15;

ImageFileError fileError(const std::filesystem::path& path, const std::string& problem) {
  return ImageFileError(path.string() + ": " + problem);
}

// What a header says of the pixels that follow it.
struct Claim {
  std::string_view format;
  std::int64_t width = 0;
  std::int64_t height = 0;
  // The least that the file holds when its pixels are all there: the header
  // and the pixels, in the format's most compact encoding.
  std::uintmax_t leastBytes = 0;
  bool compressed = false;
};

std::uintmax_t pixelsOf(const Claim& claim) {
  return static_cast<std::uintmax_t>(claim.width) * static_cast<std::uintmax_t>(claim.height);
}

std::uintmax_t divideUp(std::uintmax_t value, std::uintmax_t by) { return (value + by - 1) / by; }

// The words of a text header, one at a time: PNM's numbers between blanks
// and comments, a Radiance HDR file's lines.
class HeaderWords {
 public:
  explicit HeaderWords(std::string_view text, std::size_t from = 0) : text_(text), at_(from) {}

  // The next number of PNM's header, skipping blanks and '#' comments.
  std::optional<std::int64_t> pnmNumber(const std::filesystem::path& path) {
    while (at_ < text_.size() && (std::isspace(byte()) || text_[at_] == '#')) {
      if (text_[at_] == '#')
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      else
        ++at_;
    }
    return number(path);
  }

  // The number at the next byte, or nothing when there is no digit there.
  std::optional<std::int64_t> number(const std::filesystem::path& path) {
    const std::size_t start = at_;
    while (at_ < text_.size() && std::isdigit(byte())) ++at_;
    const std::string_view digits = text_.substr(start, at_ - start);
    if (digits.empty()) return std::nullopt;
    if (digits.size() > kMostSizeDigits)
      throw fileError(
          path, "the header is corrupt: " + inQuotes(digits, '\'') + " is no number of pixels");
    return std::stoll(std::string(digits));
  }

  bool skip(std::string_view expected) {
    if (!text_.substr(at_).starts_with(expected)) return false;
    at_ += expected.size();
    return true;
  }

  std::size_t offset() const { return at_; }

 private:
  unsigned char byte() const { return static_cast<unsigned char>(text_[at_]); }

  std::string_view text_;
  std::size_t at_;
};

// Binary PGM and PPM (P5, P6), the PNM files stb_image reads: the three
// numbers of the header, one blank, then every sample, 1 byte or 2.
std::optional<Claim> pnmClaim(std::string_view head, const std::filesystem::path& path) {
  if (!head.starts_with("P5") && !head.starts_with("P6")) return std::nullopt;
  HeaderWords words(head, 2);
  const std::optional<std::int64_t> width = words.pnmNumber(path);
  const std::optional<std::int64_t> height = words.pnmNumber(path);
  const std::optional<std::int64_t> largest = words.pnmNumber(path);
  if (!width || !height || !largest) return std::nullopt;  // decoding says why
  const std::uintmax_t sampleBytes = *largest > 255 ? 2 : 1;
  const std::uintmax_t channels = head[1] == '6' ? 3 : 1;
  Claim claim{head[1] == '6' ? "PPM" : "PGM", *width, *height, 0, false};
  claim.leastBytes = words.offset() + 1 + pixelsOf(claim) * channels * sampleBytes;
  return claim;
}

// TGA has no signature: stb_image takes for one, whatever its name, a file
// that no other format claims with such a header. Its pixels follow the
// 18-byte header, the identification field and the palette, whole or in runs
// (image types 9 to 11) of at most 128 pixels, each a count and a pixel.
std::optional<Claim> tgaClaim(std::string_view head) {
  if (head.size() < 18) return std::nullopt;
  const auto byte = [&](std::size_t at) { return static_cast<unsigned char>(head[at]); };
  const auto word = [&](std::size_t at) { return byte(at) | byte(at + 1) << 8; };
  const int type = byte(2), bits = byte(16);
  const bool knownType =
      type == 1 || type == 2 || type == 3 || type == 9 || type == 10 || type == 11;
  const bool knownBits = bits == 8 || bits == 15 || bits == 16 || bits == 24 || bits == 32;
  if (byte(1) > 1 || !knownType || !knownBits) return std::nullopt;
  const std::uintmax_t pixelBytes = divideUp(static_cast<std::uintmax_t>(bits), 8);
  const std::uintmax_t palette =
      byte(1) == 1 ? static_cast<std::uintmax_t>(word(5)) * divideUp(byte(7), 8) : 0;
  Claim claim{"TGA", word(12), word(14), 0, type >= 9};
  const std::uintmax_t pixels = claim.compressed ? divideUp(pixelsOf(claim), 128) * (1 + pixelBytes)
                                                 : pixelsOf(claim) * pixelBytes;
  claim.leastBytes = 18 + byte(0) + palette + pixels;
  return claim;
}

// Radiance HDR: lines of text up to an empty one, the size as "-Y H +X W",
// then each row either flat (4 bytes a pixel) or, between 8 and 32767
// pixels wide, as 4 runs (one a channel) of at most 127 pixels in 2 bytes.
std::optional<Claim> hdrClaim(std::string_view head, const std::filesystem::path& path) {
  if (!head.starts_with("#?RADIANCE\n") && !head.starts_with("#?RGBE\n")) return std::nullopt;
  const std::size_t endOfLines = head.find("\n\n");
  if (endOfLines == std::string_view::npos) return std::nullopt;
  HeaderWords words(head, endOfLines + 2);
  if (!words.skip("-Y ")) return std::nullopt;
  const std::optional<std::int64_t> height = words.number(path);
  if (!height || !words.skip(" +X ")) return std::nullopt;
  const std::optional<std::int64_t> width = words.number(path);
  if (!width) return std::nullopt;
  Claim claim{"Radiance HDR", *width, *height, 0, true};
  const auto wide = static_cast<std::uintmax_t>(claim.width);
  const std::uintmax_t flatRow = 4 * wide;
  const std::uintmax_t row =
      wide >= 8 && wide < 32768 ? std::min(flatRow, 4 + 4 * 2 * divideUp(wide, 127)) : flatRow;
  claim.leastBytes = words.offset() + 1 + static_cast<std::uintmax_t>(claim.height) * row;
  return claim;
}

std::string head(std::FILE* file) {
  std::string bytes(kLongestHeader, '\0');
  const long start = std::ftell(file);
  bytes.resize(std::fread(bytes.data(), 1, bytes.size(), file));
  std::fseek(file, start, SEEK_SET);
  return bytes;
}

std::string sizeText(std::int64_t width, std::int64_t height) {
  return std::to_string(width) + " x " + std::to_string(height) + " pixels";
}

void checkPixelCount(std::int64_t width, std::int64_t height, const std::filesystem::path& path) {
  if (width < 1 || height < 1)
    throw fileError(path, "the header is corrupt: it gives the image " + sizeText(width, height) +
                              "; expected at least 1 x 1");
  if (width > kMostImagePixels || height > kMostImagePixels || width * height > kMostImagePixels)
    throw fileError(path, "the image is " + sizeText(width, height) + ", more than the " +
                              std::to_string(kMostImagePixels) + " (8192 x 4096) that RISE reads");
}

void checkDecodingMemory(std::int64_t width, std::int64_t height,
                         const std::filesystem::path& path) {
  const auto decoding = static_cast<std::uint64_t>(width * height) * kDecodingBytesPerPixel;
  if (const std::optional<std::string> problem =
          memoryProblem(decoding, "decoding its " + sizeText(width, height)))
    throw fileError(path, *problem);
}

}  // namespace

void checkImageSize(std::int64_t width, std::int64_t height, const std::filesystem::path& path) {
  checkPixelCount(width, height, path);
  checkDecodingMemory(width, height, path);
}

void checkStbImageHeader(std::FILE* file, const std::filesystem::path& path) {
  const std::string bytes = head(file);
  std::optional<Claim> claim = pnmClaim(bytes, path);
  if (!claim) claim = hdrClaim(bytes, path);
  if (!claim) claim = tgaClaim(bytes);
  if (!claim) {
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_file(file, &width, &height, &channels)) return;  // decoding says why
    claim = Claim{"image", width, height, 0, true};
  }
  checkPixelCount(claim->width, claim->height, path);
  const std::uintmax_t size = std::filesystem::file_size(path);
  if (size < claim->leastBytes)
    throw fileError(
        path, "the file is cut short: its " + std::string(claim->format) + " header promises " +
                  std::to_string(claim->width) + " x " + std::to_string(claim->height) +
                  " pixels, " + (claim->compressed ? "at least " : "") +
                  std::to_string(claim->leastBytes) + " bytes, but it has " + std::to_string(size));
  checkDecodingMemory(claim->width, claim->height, path);
}

}  // namespace rise
