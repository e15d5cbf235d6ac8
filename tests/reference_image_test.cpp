// `rise render --reference`: the error of a render against an image of the
// same size, zero against itself, falling as the samples grow, and refused,
// before any work, for an image of another size or a file that is no image.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

double counter(const std::string& output, const std::string& name) {
  std::smatch found;
  if (!std::regex_search(output, found, std::regex("\\b" + name + " +([0-9.e+-]+|inf)")))
    return -1.0;
  return std::stod(found[1]);
}

class ReferenceImage : public RiseCommand {
 protected:
  CommandResult pathTraced(int samples, const std::string& more = "") const {
    return runRise("render " + example("cornell-box-measured.yaml") +
                   " -a path-tracing --width 32 --height 32 --samples " + std::to_string(samples) +
                   " " + more);
  }
};

TEST_F(ReferenceImage, MeasuresTheErrorThatMoreSamplesShrink) {
  const std::string reference = file("reference.exr").string();
  ASSERT_EQ(pathTraced(512, "-o " + reference).status, 0);

  const CommandResult itself =
      pathTraced(512, "--reference " + reference + " -o " + file("same.exr").string());
  ASSERT_EQ(itself.status, 0) << itself.output;
  EXPECT_EQ(counter(itself.output, "reference_rmse"), 0.0) << itself.output;

  const CommandResult few =
      pathTraced(4, "--reference " + reference + " -o " + file("few.png").string());
  const CommandResult more =
      pathTraced(32, "--reference " + reference + " -o " + file("more.png").string());
  ASSERT_EQ(few.status, 0) << few.output;
  const double fewError = counter(few.output, "reference_relative_error");
  const double moreError = counter(more.output, "reference_relative_error");
  EXPECT_GT(fewError, 0.0);
  // Eight times the samples: the error about 1/sqrt(8) as large, the
  // reference's own noise aside.
  EXPECT_LT(moreError, 0.55 * fewError) << few.output << more.output;
  EXPECT_GT(counter(few.output, "reference_rmse"), counter(more.output, "reference_rmse"));
}

TEST_F(ReferenceImage, RefusesAnImageOfAnotherSizeOrNoImageBeforeRendering) {
  const std::string small = file("small.exr").string();
  ASSERT_EQ(runRise("render " + example("cornell-box-measured.yaml") +
                    " -a path-tracing --width 24 --height 16 --samples 1 -o " + small)
                .status,
            0);
  const CommandResult other =
      pathTraced(1, "--reference " + small + " -o " + file("a.png").string());
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.output.find("the image is 24x16; expected the render's size, 32x32"),
            std::string::npos)
      << other.output;
  EXPECT_FALSE(std::filesystem::exists(file("a.png")));

  const CommandResult missing =
      pathTraced(1, "--reference " + file("none.exr").string() + " -o " + file("b.png").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("--reference: "), std::string::npos) << missing.output;

  const CommandResult frames =
      runRise("render " + example("animation.yaml") + " --frames 0-1 --reference " + small);
  EXPECT_EQ(frames.status, 2) << frames.output;
}

}  // namespace
}  // namespace rise
