// What the studio says is so: a comparison and a ray tree made before an
// edit say they are out of date after it; Revert leaves no old error in the
// status bar; a comparison draws the shadows `rise compare` draws; and the
// compare panel's boxes all show, none off the panel's edge.
#include <gtest/gtest.h>

#include <string>

#include "studio/studio_testing.hpp"

namespace rise {
namespace {

TEST_F(Studio, MarksWhatAnEditLeftOutOfDate) {
  ASSERT_EQ(runSession(R"(open ${RISE_SOURCE_DIR}/examples/classic.yaml
click Render
wait
click-pixel 320 230
wait
click compare/z-buffer
click compare/hybrid
click Compare
wait
frames 2
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
  // Every algorithm's box lies within the compare panel's width.
  ASSERT_TRUE(before.contains("compare/hybrid"));
  ASSERT_TRUE(before.contains("Compare"));
  const float right = before.at("compare/shadows")[2];
  for (const auto& [name, box] : before)
    if (name.starts_with("compare/") && name != "compare/shadows")
      EXPECT_LE(box[2], right + 1.0f) << name;
}

}  // namespace
}  // namespace rise
