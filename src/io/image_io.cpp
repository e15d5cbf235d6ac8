// Writing and reading image files. Every write goes to a temporary file in the
// target's directory and is renamed over the target only when complete, so a
// viewer or a later run never sees half an image.
#include "io/image_io.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <spng.h>
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/byte_encoding.hpp"
#include "io/pcx_file.hpp"

namespace rise {

float srgbFromLinear(float linear) {
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float linearFromSrgb(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

namespace {

ImageFileError fileError(const std::filesystem::path& path, std::string_view problem) {
  return ImageFileError(path.string() + ": " + std::string(problem));
}

std::string because(std::string_view problem, std::string_view reason) {
  return std::string(problem) + " (" + std::string(reason) + ")";
}

// A file that appears under its final name only once it is complete. It is
// written under a name unique to this process and call, in the target's own
// directory so that the final rename stays on one file system and is atomic.
// Destroyed without commit(), it deletes itself.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path target)
      : target_(std::move(target)), temporary_(uniqueNameBeside(target_)) {
    file_ = std::fopen(temporary_.c_str(), "wb");
    if (file_ == nullptr) throw fileError(target_, because("cannot write", std::strerror(errno)));
  }

  ~TemporaryFile() {
    if (file_ != nullptr) std::fclose(file_);
    if (!committed_) {
      std::error_code ignored;
      std::filesystem::remove(temporary_, ignored);
    }
  }

  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  // Failures are remembered and reported by commit() rather than thrown:
  // OpenEXR writes its final offsets from a destructor, which cannot throw.
  void write(const void* data, std::size_t size) {
    if (error_ == 0 && std::fwrite(data, 1, size, file_) != size) error_ = errno;
  }

  std::uint64_t position() const { return static_cast<std::uint64_t>(ftello(file_)); }

  void seek(std::uint64_t position) {
    if (error_ == 0 && fseeko(file_, static_cast<off_t>(position), SEEK_SET) != 0) error_ = errno;
  }

  void commit() {
    if (std::fclose(file_) != 0 && error_ == 0) error_ = errno;
    file_ = nullptr;
    if (error_ != 0) throw fileError(target_, because("cannot write", std::strerror(error_)));
    std::error_code renameError;
    std::filesystem::rename(temporary_, target_, renameError);
    if (renameError) throw fileError(target_, because("cannot write", renameError.message()));
    committed_ = true;
  }

 private:
  static std::filesystem::path uniqueNameBeside(const std::filesystem::path& target) {
    static std::atomic<unsigned> writesStarted{0};
    std::filesystem::path name = target;
    name += ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(writesStarted++);
    return name;
  }

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
  int error_ = 0;
  bool committed_ = false;
};

enum class ImageFormat { Png, Ppm, Exr };

ImageFormat formatOf(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  std::string lowered = extension;
  std::transform(lowered.begin(), lowered.end(), lowered.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lowered == ".png") return ImageFormat::Png;
  if (lowered == ".ppm") return ImageFormat::Ppm;
  if (lowered == ".exr") return ImageFormat::Exr;
  throw fileError(path, "unsupported image format '" + extension + "' (use .png, .ppm or .exr)");
}

float linearFromByte(std::uint8_t byte, Encoding encoding) {
  const float value = static_cast<float>(byte) / 255.0f;
  return encoding == Encoding::Srgb ? linearFromSrgb(value) : value;
}

// Interleaved 8-bit RGB, top row first: the layout of both PNG and PPM.
std::vector<std::uint8_t> rgbBytes(const Image& image, Encoding encoding) {
  const ByteEncoder& toByte = byteEncoder(encoding);
  const std::vector<Color>& pixels = image.pixels();
  std::vector<std::uint8_t> bytes(pixels.size() * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i)
    for (int channel = 0; channel < 3; ++channel)
      bytes[3 * i + channel] = toByte(pixels[i][channel]);
  return bytes;
}

// zlib's fastest level, every row given as its difference from the row above
// (PNG's "up" filter): a rendered image comes out within a few percent of the
// size that trying every filter on every row gives, in a quarter of the time.
constexpr int kPngCompressionLevel = 1;
constexpr int kPngFilters = SPNG_FILTER_CHOICE_UP;

void writePng(const Image& image, Encoding encoding, const std::filesystem::path& path,
              TemporaryFile& file) {
  const std::vector<std::uint8_t> bytes = rgbBytes(image, encoding);
  const std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> png(spng_ctx_new(SPNG_CTX_ENCODER),
                                                           spng_ctx_free);
  if (!png) throw fileError(path, "cannot encode PNG (out of memory)");
  spng_rw_fn* append = [](spng_ctx*, void* user, void* data, std::size_t size) {
    static_cast<TemporaryFile*>(user)->write(data, size);
    return 0;
  };
  spng_ihdr header{};
  header.width = static_cast<std::uint32_t>(image.width());
  header.height = static_cast<std::uint32_t>(image.height());
  header.bit_depth = 8;
  header.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
  int error = spng_set_png_stream(png.get(), append, &file);
  if (error == 0) error = spng_set_ihdr(png.get(), &header);
  if (error == 0)
    error = spng_set_option(png.get(), SPNG_IMG_COMPRESSION_LEVEL, kPngCompressionLevel);
  if (error == 0) error = spng_set_option(png.get(), SPNG_FILTER_CHOICE, kPngFilters);
  if (error == 0)
    error = spng_encode_image(png.get(), bytes.data(), bytes.size(), SPNG_FMT_PNG,
                              SPNG_ENCODE_FINALIZE);
  if (error != 0) throw fileError(path, because("cannot encode PNG", spng_strerror(error)));
}

void writePpm(const Image& image, Encoding encoding, TemporaryFile& file) {
  const std::string header =
      "P6\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n255\n";
  const std::vector<std::uint8_t> bytes = rgbBytes(image, encoding);
  file.write(header.data(), header.size());
  file.write(bytes.data(), bytes.size());
}

// OpenEXR's output stream, writing into the temporary file.
class ExrStream : public Imf::OStream {
 public:
  ExrStream(TemporaryFile& file, const std::filesystem::path& path)
      : Imf::OStream(path.c_str()), file_(file) {}

  void write(const char bytes[], int count) override {
    file_.write(bytes, static_cast<std::size_t>(count));
  }
  uint64_t tellp() override { return file_.position(); }
  void seekp(uint64_t position) override { file_.seek(position); }

 private:
  TemporaryFile& file_;
};

void writeExr(const Image& image, const std::filesystem::path& path, TemporaryFile& file) {
  static_assert(sizeof(Color) == 3 * sizeof(float), "Color must be three packed floats");
  // A frame buffer slice takes a mutable pointer, but an output file only reads it.
  char* pixels = const_cast<char*>(reinterpret_cast<const char*>(image.pixels().data()));
  const std::size_t rowStride = sizeof(Color) * static_cast<std::size_t>(image.width());
  Imf::Header header(image.width(), image.height());
  Imf::FrameBuffer frameBuffer;
  const char* const channelNames[] = {"R", "G", "B"};
  for (int channel = 0; channel < 3; ++channel) {
    header.channels().insert(channelNames[channel], Imf::Channel(Imf::FLOAT));
    frameBuffer.insert(
        channelNames[channel],
        Imf::Slice(Imf::FLOAT, pixels + channel * sizeof(float), sizeof(Color), rowStride));
  }
  try {
    ExrStream stream(file, path);
    Imf::OutputFile output(stream, header);
    output.setFrameBuffer(frameBuffer);
    output.writePixels(image.height());
  } catch (const std::exception& error) {
    throw fileError(path, because("cannot encode OpenEXR", error.what()));
  }
}

}  // namespace

void writeImage(const Image& image, const std::filesystem::path& path, Encoding encoding) {
  const ImageFormat format = formatOf(path);
  TemporaryFile file(path);
  switch (format) {
    case ImageFormat::Png:
      writePng(image, encoding, path, file);
      break;
    case ImageFormat::Ppm:
      writePpm(image, encoding, file);
      break;
    case ImageFormat::Exr:
      writeExr(image, path, file);
      break;
  }
  file.commit();
}

namespace {

// PNG, JPEG, TGA, BMP and the other 8-bit formats stb_image reads.
Image readEightBitImage(const std::filesystem::path& path, Encoding encoding) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw fileError(path, because("cannot read", std::strerror(errno)));
  int width = 0;
  int height = 0;
  int channelsInFile = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> bytes(
      stbi_load_from_file(file, &width, &height, &channelsInFile, 3), stbi_image_free);
  std::fclose(file);
  if (!bytes) throw fileError(path, because("cannot read", stbi_failure_reason()));

  Image image(width, height);
  const stbi_uc* byte = bytes.get();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x, byte += 3)
      image.at(x, y) = Color(linearFromByte(byte[0], encoding), linearFromByte(byte[1], encoding),
                             linearFromByte(byte[2], encoding));
  return image;
}

// Radiance HDR holds linear floats, which stb_image returns unchanged.
Image readHdrImage(std::FILE* file, const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<float, void (*)(void*)> values(
      stbi_loadf_from_file(file, &width, &height, &channels, 3), stbi_image_free);
  if (!values) throw fileError(path, because("cannot read", stbi_failure_reason()));
  Image image(width, height);
  const float* value = values.get();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x, value += 3)
      image.at(x, y) = Color(value[0], value[1], value[2]);
  return image;
}

bool hasExtension(const std::filesystem::path& path, std::string_view wanted) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == wanted;
}

// OpenEXR's red, green and blue, as RISE writes them, read back as floats.
Image readExr(const std::filesystem::path& path) {
  try {
    Imf::InputFile input(path.c_str());
    const Imath::Box2i window = input.header().dataWindow();
    Image image(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1);
    char* origin = reinterpret_cast<char*>(&image.at(0, 0)) -
                   (static_cast<std::ptrdiff_t>(window.min.y) * image.width() + window.min.x) *
                       static_cast<std::ptrdiff_t>(sizeof(Color));
    const std::size_t rowStride = sizeof(Color) * static_cast<std::size_t>(image.width());
    Imf::FrameBuffer frameBuffer;
    const char* const channelNames[] = {"R", "G", "B"};
    for (int channel = 0; channel < 3; ++channel)
      frameBuffer.insert(
          channelNames[channel],
          Imf::Slice(Imf::FLOAT, origin + channel * sizeof(float), sizeof(Color), rowStride));
    input.setFrameBuffer(frameBuffer);
    input.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& error) {
    throw fileError(path, because("cannot read OpenEXR", error.what()));
  }
}

}  // namespace

Image readImage(const std::filesystem::path& path, Encoding encoding) {
  if (hasExtension(path, ".pcx")) return readPcxFile(path, encoding);
  if (hasExtension(path, ".exr")) return readExr(path);
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             std::fclose);
  if (!file) throw fileError(path, because("cannot read", std::strerror(errno)));
  // stb_image reads the signature and puts the file back where it was.
  if (stbi_is_hdr_from_file(file.get())) return readHdrImage(file.get(), path);
  return readEightBitImage(path, encoding);
}

}  // namespace rise
