// What the tests that go over every example scene share: the scenes' file
// names, and a test name made of each.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace rise::example_testing {

// The file names of examples/*.yaml, sorted.
inline std::vector<std::string> exampleScenes() {
  std::vector<std::string> names;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(RISE_SOURCE_DIR) + "/examples"))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// "md2-skin.yaml" -> "md2_skin", for INSTANTIATE_TEST_SUITE_P.
inline std::string exampleTestName(const testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(0, info.param.find('.'));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

}  // namespace rise::example_testing
