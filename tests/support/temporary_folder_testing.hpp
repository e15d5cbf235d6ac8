// A test fixture with a fresh folder for the files a test writes, removed
// when the test ends. The folder is named after the test and the process,
// so that tests running at once never share one.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace rise {

class TemporaryFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo& test = *::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("rise-") + test.test_suite_name() + "-" + test.name() + "-" +
                       std::to_string(getpid());
    for (char& c : name)
      if (c == '/') c = '-';  // parameterised tests are named "Suite/Test/0"
    directory_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path directory_;
};

}  // namespace rise
