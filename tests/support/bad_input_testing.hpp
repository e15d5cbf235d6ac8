// A bad input given to the `rise` binary as a user would give it, under an
// address-space limit and a time limit: it must exit with status 2 (1 for a
// write that fails), say what is wrong, write nothing, and do so at once.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "support/rise_process_testing.hpp"

namespace rise::bad_input_testing {

// A sanitized build reserves terabytes of shadow address space and runs
// several times slower: it gets no address-space limit and more time.
#ifdef RISE_SANITIZED_BUILD
inline constexpr std::uint64_t kAddressSpace = 0;
inline constexpr double kSeconds = 60.0;
#else
inline constexpr std::uint64_t kAddressSpace = 512'000'000;
inline constexpr double kSeconds = 5.0;
#endif

struct BadInput {
  std::string name;
  // The files of the case, written into its folder: name and contents.
  std::vector<std::pair<std::string, std::string>> files;
  std::vector<std::string> arguments;  // "DIR/" is replaced by the case's folder
  std::string standardInput = "/dev/null";
  int status = 2;
  std::string message;                 // a part of what rise says
  std::uint64_t fileSizeBytes = 0;     // the largest file it may write: a full disk
  std::vector<std::string> written{};  // the files it may leave, whole
};

inline void PrintTo(const BadInput& input, std::ostream* out) { *out << input.name; }

inline std::string nameOf(const ::testing::TestParamInfo<BadInput>& info) {
  return info.param.name;
}

// Runs the case in `folder` (empty), and checks what rise did.
inline void expectRefusedAtOnce(const BadInput& input, const std::filesystem::path& folder) {
  for (const auto& [name, contents] : input.files)
    std::ofstream(folder / name, std::ios::binary) << contents;
  std::vector<std::string> arguments = input.arguments;
  for (std::string& argument : arguments)
    if (argument.starts_with("DIR/")) argument = (folder / argument.substr(4)).string();
  process_testing::Limits limits;
  limits.addressSpaceBytes = kAddressSpace;
  limits.seconds = kSeconds;
  limits.standardInput = input.standardInput;
  limits.fileSizeBytes = input.fileSizeBytes;

  const process_testing::Outcome outcome = process_testing::runRise(arguments, limits);
  EXPECT_FALSE(outcome.timedOut) << "still running after " << kSeconds << " s";
  EXPECT_EQ(outcome.status, input.status) << outcome.output;
  EXPECT_NE(outcome.output.find(input.message), std::string::npos) << outcome.output;
  EXPECT_EQ(outcome.output.find("terminate called"), std::string::npos) << outcome.output;
  for (const std::filesystem::directory_entry& entry :
       std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const bool given = std::any_of(input.files.begin(), input.files.end(),
                                   [&](const auto& file) { return file.first == name; });
    const bool allowed =
        std::find(input.written.begin(), input.written.end(), name) != input.written.end();
    EXPECT_TRUE(given || allowed) << name << " was written";
  }
}

}  // namespace rise::bad_input_testing
