// What the studio says is so: a comparison and a ray tree made before an
// edit say they are out of date after it; Revert leaves no old error in the
// status bar; and on a screen of any size every panel, and every box of the
// compare panel, lies within the window.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "algorithms/registry.hpp"
#include "io/image_io.hpp"
#include "studio/studio_testing.hpp"

namespace rise {
namespace {

// The classic scene rendered, the glass sphere's pixel traced, and the
// z-buffer compared with the hybrid.
const std::string kRenderedTracedAndCompared = R"(open ${RISE_SOURCE_DIR}/examples/classic.yaml
click Render
wait
click-pixel 320 230
wait
click compare/z-buffer
click compare/hybrid
click Compare
wait
)";

TEST_F(Studio, MarksWhatAnEditLeftOutOfDate) {
  ASSERT_EQ(runSession(kRenderedTracedAndCompared + R"(frames 2
layout ${OUT}/before.txt
set materials/glass/color [0.3, 0.6, 1]
frames 3
layout ${OUT}/after.txt
replace-text radius: 1, material: glass}|radius: [1, material: glass}
click Apply
frames 2
expect-refused invalid YAML
click Revert
frames 2
expect-status reverted to the scene
)"),
            0);
  const auto before = layout("before.txt"), after = layout("after.txt");
  EXPECT_FALSE(before.contains("compare/out of date"));
  EXPECT_FALSE(before.contains("ray tree/out of date"));
  EXPECT_TRUE(after.contains("compare/out of date"));
  EXPECT_TRUE(after.contains("ray tree/out of date"));
}

// Run on screens of 1280 x 800, 1600 x 1000 and 1920 x 1080: the window fits
// the screen, every panel lies within the window, the compare panel's boxes
// within the panel, and the screenshot shows the renders.
TEST_F(Studio, EveryPanelLiesWithinTheWindow) {
  ASSERT_EQ(runSession(kRenderedTracedAndCompared + R"(frames 3
layout ${OUT}/layout.txt
screenshot ${OUT}/screenshot.png
)"),
            0);
  const auto widgets = layout();
  ASSERT_TRUE(widgets.contains("window"));
  const float width = widgets.at("window")[2], height = widgets.at("window")[3];
  // The screen the test's X server has: the window no larger.
  int screenWidth = 0, screenHeight = 0;
  if (const char* screen = std::getenv("RISE_TEST_SCREEN"))
    ASSERT_EQ(std::sscanf(screen, "%dx%d", &screenWidth, &screenHeight), 2) << screen;
  if (screenWidth > 0) {
    EXPECT_LE(width, static_cast<float>(screenWidth));
    EXPECT_LE(height, static_cast<float>(screenHeight));
  }
  const Image screenshot = readImage(directory_ / "screenshot.png", Encoding::Linear);
  EXPECT_EQ(screenshot.width(), static_cast<int>(width));
  EXPECT_EQ(screenshot.height(), static_cast<int>(height));
  EXPECT_GT(variance(screenshot), 0.005);
  for (const std::string panel :
       {"scene", "viewport", "render", "compare", "ray tree", "scene text"}) {
    ASSERT_TRUE(widgets.contains("panel/" + panel)) << panel;
    const std::array<float, 4> box = widgets.at("panel/" + panel);
    EXPECT_GE(box[0], 0.0f) << panel;
    EXPECT_GE(box[1], 0.0f) << panel;
    EXPECT_LE(box[2], width + 0.5f) << panel << " at " << width << " x " << height;
    EXPECT_LE(box[3], height + 0.5f) << panel << " at " << width << " x " << height;
  }
  const std::array<float, 4> compare = widgets.at("panel/compare");
  for (const Renderer* renderer : allRenderers()) {
    const std::string box = "compare/" + std::string(renderer->name());
    ASSERT_TRUE(widgets.contains(box)) << box;
    EXPECT_LE(widgets.at(box)[2], compare[2]) << box;
  }
}

}  // namespace
}  // namespace rise
