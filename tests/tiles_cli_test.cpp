// Splitting a render by hand: `rise render --tile` and `rise merge`, as a job
// array uses them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "io/image_io.hpp"
#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

class TileCommand : public RiseCommand {
 protected:
  // Renders one region of soft-shadows.yaml, 50x30, 4 samples through a tent
  // filter, into pieces/.
  CommandResult renderTile(const std::string& region, const std::string& name) {
    fs::create_directories(file("pieces"));
    return runRise("render " + example("soft-shadows.yaml") + " --width 50 --height 30 " +
                   kSampling + " --tile " + region + " -o " + file("pieces/" + name).string());
  }
  // Merges pieces/ into merged.png, which a refused set must not leave.
  CommandResult mergeRefused() {
    const CommandResult merge =
        runRise("merge " + file("pieces").string() + " -o " + file("merged.png").string());
    EXPECT_EQ(merge.status, 2) << merge.output;
    EXPECT_FALSE(fs::exists(file("merged.png")));
    return merge;
  }
  static constexpr const char* kSampling = "--samples 4 --filter tent --threads 2";
};

TEST_F(TileCommand, PiecesMergedEqualTheWholeRender) {
  for (const char* extension : {".exr", ".png"}) {
    fs::remove_all(file("pieces"));
    const std::string whole = std::string("whole") + extension;
    ASSERT_EQ(runRise("render " + example("soft-shadows.yaml") + " --width 50 --height 30 " +
                      kSampling + " -o " + file(whole).string())
                  .status,
              0);
    // Three pieces, none on the 16-pixel tiles the ray tracer cuts.
    for (const auto& [region, name] :
         {std::pair{"0,0,23,30", "left"}, {"23,0,27,11", "top"}, {"23,11,27,19", "bottom"}}) {
      const CommandResult tile = renderTile(region, name + std::string(extension));
      ASSERT_EQ(tile.status, 0) << tile.output;
    }
    std::ifstream placeFile(file(std::string("pieces/top") + extension + ".tile.json"));
    const nlohmann::json place = nlohmann::json::parse(placeFile);
    EXPECT_EQ(place["x"], 23);
    EXPECT_EQ(place["height"], 11);
    EXPECT_EQ(place["image_width"], 50);

    const std::string merged = std::string("merged") + extension;
    const CommandResult merge =
        runRise("merge " + file("pieces").string() + " -o " + file(merged).string());
    ASSERT_EQ(merge.status, 0) << merge.output;
    EXPECT_EQ(readImage(file(merged), Encoding::Linear).pixels(),
              readImage(file(whole), Encoding::Linear).pixels())
        << extension;
  }
}

TEST_F(TileCommand, MergeNamesTheMissingRegion) {
  ASSERT_EQ(renderTile("0,0,50,10", "top.exr").status, 0);
  ASSERT_EQ(renderTile("0,10,20,20", "left.exr").status, 0);
  const CommandResult merge = mergeRefused();
  EXPECT_NE(merge.output.find("--tile 20,10,30,20"), std::string::npos) << merge.output;
}

TEST_F(TileCommand, MergeRefusesOverlappingPieces) {
  ASSERT_EQ(renderTile("0,0,50,20", "top.exr").status, 0);
  ASSERT_EQ(renderTile("0,15,50,15", "bottom.exr").status, 0);
  const CommandResult merge = mergeRefused();
  EXPECT_NE(merge.output.find("overlap in the region 0,15,50,5"), std::string::npos)
      << merge.output;
}

TEST_F(TileCommand, ATileBeyondTheImageIsBadInput) {
  const CommandResult tile = renderTile("40,0,20,10", "beyond.exr");
  EXPECT_EQ(tile.status, 2);
  EXPECT_NE(tile.output.find("within the 50x30 image"), std::string::npos) << tile.output;
  EXPECT_FALSE(fs::exists(file("pieces/beyond.exr")));
}

}  // namespace
}  // namespace rise
