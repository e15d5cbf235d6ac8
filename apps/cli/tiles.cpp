#include "tiles.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/memory_budget.hpp"
#include "io/atomic_file.hpp"
#include "io/file_limits.hpp"
#include "io/image_io.hpp"
#include "job.hpp"
#include "option_checks.hpp"

namespace rise::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPlaceSuffix = ".tile.json";

// A piece of the image: its file, and where it lies in an image of what size.
struct Piece {
  fs::path place;
  fs::path image;
  PixelRect area;
  int imageWidth;
  int imageHeight;
};

class MergeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string describe(const PixelRect& area) {
  return std::to_string(area.x0) + "," + std::to_string(area.y0) + "," +
         std::to_string(area.width()) + "," + std::to_string(area.height());
}

// A whole number of the place's JSON, from `least` to the largest image side.
int placeNumber(const nlohmann::json& json, const char* key, int least, const fs::path& place) {
  const nlohmann::json& value = json.at(key);
  if (!value.is_number_integer() || value.get<std::int64_t>() < least ||
      value.get<std::int64_t>() > kLargestImageSide)
    throw MergeError(place.string() + ": '" + key + "' is " + value.dump() +
                     "; expected a whole number of pixels from " + std::to_string(least) + " to " +
                     std::to_string(kLargestImageSide));
  return value.get<int>();
}

Piece readPiece(const fs::path& place) {
  if (const std::optional<std::string> problem = fileKindOrSizeProblem(place, kLargestSceneFile))
    throw MergeError(place.string() + ": " + *problem);
  std::ifstream file(place);
  try {
    const nlohmann::json json = nlohmann::json::parse(file);
    const auto number = [&](const char* key, int least) {
      return placeNumber(json, key, least, place);
    };
    const int x = number("x", 0), y = number("y", 0);
    Piece piece{place, place.parent_path() / json.at("image").get<std::string>(),
                PixelRect{x, y, x + number("width", 1), y + number("height", 1)},
                number("image_width", 1), number("image_height", 1)};
    if (piece.area.x1 > piece.imageWidth || piece.area.y1 > piece.imageHeight)
      throw MergeError(place.string() + ": the region " + describe(piece.area) +
                       " does not lie inside the " + std::to_string(piece.imageWidth) + "x" +
                       std::to_string(piece.imageHeight) + " image");
    return piece;
  } catch (const nlohmann::json::exception& error) {
    throw MergeError(place.string() +
                     ": expected a tile's place (image, x, y, width, height, image_width, "
                     "image_height): " +
                     error.what());
  }
}

std::vector<Piece> readPieces(const fs::path& directory) {
  if (!fs::is_directory(directory)) throw MergeError(directory.string() + ": not a folder");
  std::vector<fs::path> places;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory))
    if (entry.path().filename().string().ends_with(kPlaceSuffix)) places.push_back(entry.path());
  if (places.empty())
    throw MergeError(directory.string() + ": no pieces (*" + std::string(kPlaceSuffix) +
                     ", written by rise render --tile)");
  std::sort(places.begin(), places.end());
  std::vector<Piece> pieces;
  for (const fs::path& place : places) pieces.push_back(readPiece(place));
  return pieces;
}

// The rectangles no piece covers, each as wide and then as tall as it goes:
// what is missing, in regions a --tile can render.
std::vector<PixelRect> gaps(const std::vector<Piece>& pieces, int width, int height) {
  std::vector<bool> covered(static_cast<std::size_t>(width) * height, false);
  const auto at = [&](int x, int y) { return covered[static_cast<std::size_t>(y) * width + x]; };
  const auto cover = [&](const PixelRect& area) {
    for (int y = area.y0; y < area.y1; ++y)
      std::fill_n(covered.begin() + static_cast<std::ptrdiff_t>(y) * width + area.x0, area.width(),
                  true);
  };
  for (const Piece& piece : pieces) cover(piece.area);
  std::vector<PixelRect> missing;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (at(x, y)) continue;
      int x1 = x;
      while (x1 < width && !at(x1, y)) ++x1;
      int y1 = y + 1;
      while (y1 < height &&
             std::none_of(covered.begin() + static_cast<std::ptrdiff_t>(y1) * width + x,
                          covered.begin() + static_cast<std::ptrdiff_t>(y1) * width + x1,
                          [](bool c) { return c; }))
        ++y1;
      missing.push_back({x, y, x1, y1});
      cover(missing.back());
    }
  }
  return missing;
}

void checkPieces(const std::vector<Piece>& pieces) {
  const Piece& first = pieces.front();
  if (const std::optional<std::string> problem = memoryProblem(
          static_cast<std::uint64_t>(first.imageWidth) * first.imageHeight * sizeof(Color),
          "the " + std::to_string(first.imageWidth) + "x" + std::to_string(first.imageHeight) +
              " image the pieces make"))
    throw MergeError(first.place.string() + ": " + *problem);
  for (const Piece& piece : pieces)
    if (piece.imageWidth != first.imageWidth || piece.imageHeight != first.imageHeight)
      throw MergeError(piece.place.string() + ": a piece of a " + std::to_string(piece.imageWidth) +
                       "x" + std::to_string(piece.imageHeight) + " image, but " +
                       first.place.string() + " is of a " + std::to_string(first.imageWidth) + "x" +
                       std::to_string(first.imageHeight) + " one");
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
      if (const PixelRect both = pieces[i].area.intersection(pieces[j].area); !both.isEmpty())
        throw MergeError(pieces[i].place.string() + " and " + pieces[j].place.string() +
                         " overlap in the region " + describe(both));
  const std::vector<PixelRect> missing = gaps(pieces, first.imageWidth, first.imageHeight);
  if (missing.empty()) return;
  std::string regions;
  for (std::size_t i = 0; i < std::min<std::size_t>(missing.size(), 8); ++i)
    regions += "\n  --tile " + describe(missing[i]);
  if (missing.size() > 8) regions += "\n  and " + std::to_string(missing.size() - 8) + " more";
  throw MergeError(first.place.parent_path().string() +
                   ": the pieces leave a gap; no piece covers" + regions);
}

bool holdsLinearValues(const fs::path& image) { return image.extension() == ".exr"; }

// The pieces' stored values joined: OpenEXR's floats as they are; the 8-bit
// formats' levels read and written raw, so that they do not change either.
Image joined(const std::vector<Piece>& pieces) {
  const bool linear = holdsLinearValues(pieces.front().image);
  Image whole;  // taken once a piece is found to be what its place says
  for (const Piece& piece : pieces) {
    if (holdsLinearValues(piece.image) != linear)
      throw MergeError(piece.image.string() + ": expected " +
                       (linear ? "OpenEXR, as " : "8-bit values, as ") +
                       pieces.front().image.string() + " holds");
    const Image image = readImage(piece.image, Encoding::Linear);
    if (image.width() != piece.area.width() || image.height() != piece.area.height())
      throw MergeError(piece.image.string() + ": " + std::to_string(image.width()) + "x" +
                       std::to_string(image.height()) + " pixels, but " + piece.place.string() +
                       " places a " + std::to_string(piece.area.width()) + "x" +
                       std::to_string(piece.area.height()) + " region");
    if (whole.width() == 0) whole = Image(piece.imageWidth, piece.imageHeight);
    paste(image, piece.area, whole);
  }
  return whole;
}

struct MergeOptions {
  fs::path directory;
  fs::path output;
  Encoding encoding = Encoding::Srgb;
};

int merge(const MergeOptions& options) {
  if (!outputsAreWritable({{options.output, "-o"}}, "-")) return kExitBadInput;
  try {
    checkImageFormat(options.output);
  } catch (const ImageFileError& error) {
    std::cerr << "rise: -o " << error.what() << "\n";
    return kExitBadInput;
  }
  Image whole;
  bool linear = false;
  try {
    const std::vector<Piece> pieces = readPieces(options.directory);
    checkPieces(pieces);
    linear = holdsLinearValues(pieces.front().image);
    if (!linear && holdsLinearValues(options.output))
      throw MergeError(options.output.string() +
                       ": the pieces hold 8-bit display values; expected a .png or .ppm");
    whole = joined(pieces);
  } catch (const std::runtime_error& error) {  // MergeError, ImageFileError
    std::cerr << "rise: " << error.what() << "\n";
    return kExitBadInput;
  }
  try {
    writeImage(whole, options.output, linear ? options.encoding : Encoding::Linear);
  } catch (const std::exception& error) {
    std::cerr << "rise: " << error.what() << "\n";
    return kExitOutputError;
  }
  std::cerr << "wrote " << options.output.string() << "\n";
  return 0;
}

}  // namespace

void addTileOption(CLI::App& command, SettingsOptions& options) {
  command
      .add_option_function<std::vector<int>>(
          "--tile",
          [&options](const std::vector<int>& values) {
            options.request.settings.region =
                PixelRect{values[0], values[1], values[0] + values[2], values[1] + values[3]};
          },
          "Render only this region, X,Y,W,H, and write its place beside the image (for rise "
          "merge)")
      ->option_text("X,Y,W,H")
      ->delimiter(',')
      ->expected(4)
      ->check(wholeNumberFrom(0, kLargestImageSide));
}

fs::path defaultTileOutput(const std::string& scenePath, const PixelRect& region) {
  return defaultOutput(scenePath,
                       "." + std::to_string(region.x0) + "_" + std::to_string(region.y0) + ".exr");
}

void paste(const Image& tile, const PixelRect& place, Image& whole) {
  for (int y = 0; y < tile.height(); ++y)
    for (int x = 0; x < tile.width(); ++x) whole.at(place.x0 + x, place.y0 + y) = tile.at(x, y);
}

fs::path tilePlacePath(const fs::path& image) {
  return fs::path(image.string() + std::string(kPlaceSuffix));
}

void writeTilePlace(const fs::path& image, const RenderSettings& settings, const std::string& scene,
                    std::string_view algorithm) {
  const PixelRect& area = *settings.region;
  const nlohmann::json place = {{"image", image.filename().string()},
                                {"x", area.x0},
                                {"y", area.y0},
                                {"width", area.width()},
                                {"height", area.height()},
                                {"image_width", settings.width},
                                {"image_height", settings.height},
                                {"scene", scene},
                                {"algorithm", algorithm},
                                {"seed", settings.seed}};
  writeFileAtomically(tilePlacePath(image), place.dump(2) + "\n");
}

std::function<std::optional<int>()> addMergeCommand(CLI::App& app) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* command = app.add_subcommand(
      "merge", "Join the pieces rendered with --tile in a folder into the whole image");
  command->add_option("folder", options->directory, "Folder of the pieces and their places")
      ->required();
  command->add_option("-o,--output", options->output, "Image to write: .png, .ppm or .exr")
      ->required();
  command
      ->add_option("--encoding", options->encoding,
                   "Pieces in OpenEXR: srgb (the display standard) or linear (raw values)")
      ->transform(encodings());
  return [options, command]() -> std::optional<int> {
    if (!*command) return std::nullopt;
    return merge(*options);
  };
}

}  // namespace rise::cli
