#include "reference_image.hpp"

#include <iostream>

#include "core/image_error.hpp"
#include "io/image_io.hpp"

namespace rise::cli {

void addReferenceOption(CLI::App& command, std::filesystem::path& reference) {
  command
      .add_option("--reference", reference,
                  "An image of the same size to measure the render against (.exr keeps linear "
                  "values): adds reference_rmse and reference_relative_error to the counters")
      ->excludes(command.get_option("--frames"))
      ->excludes(command.get_option("--tile"));
}

std::optional<Image> readReference(const std::filesystem::path& path,
                                   const RenderSettings& settings) {
  try {
    Image reference = readImage(path);
    if (reference.width() == settings.width && reference.height() == settings.height)
      return reference;
    std::cerr << "rise: --reference " << path.string() << ": the image is " << reference.width()
              << "x" << reference.height() << "; expected the render's size, " << settings.width
              << "x" << settings.height << "\n";
  } catch (const ImageFileError& error) {
    std::cerr << "rise: --reference: " << error.what() << "\n";
  }
  return std::nullopt;
}

void measureAgainst(const Image& reference, RenderResult& result) {
  result.stats.add("reference_rmse", rmse(result.image, reference));
  result.stats.add("reference_relative_error", relativeRmse(result.image, reference));
}

}  // namespace rise::cli
