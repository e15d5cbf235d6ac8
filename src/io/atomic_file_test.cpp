// Outputs are whole or absent: written beside their target and renamed over
// it, removed when the process is interrupted while writing, and written in
// place where the target is not a regular file, which a rename would replace.
#include "io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/temporary_folder_testing.hpp"

namespace rise {
namespace {

namespace fs = std::filesystem;

class AtomicFiles : public TemporaryFolderTest {
 protected:
  int filesInFolder() const {
    return static_cast<int>(std::distance(fs::directory_iterator(directory_), {}));
  }
};

TEST_F(AtomicFiles, AFileAppearsOnlyWhenWhole) {
  AtomicFile file(directory_ / "out.txt");
  file.write("half", 4);
  EXPECT_FALSE(fs::exists(directory_ / "out.txt"));
  file.commit();
  std::stringstream text;
  text << std::ifstream(directory_ / "out.txt").rdbuf();
  EXPECT_EQ(text.str(), "half");
  EXPECT_EQ(filesInFolder(), 1);
}

// In a child, so that the signal ends the child, not the test.
TEST_F(AtomicFiles, AnInterruptedWriteLeavesNothingBehindAndEndsByItsSignal) {
  for (const int signal : {SIGINT, SIGTERM}) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      AtomicFile file(directory_ / "large.png");
      file.write("partly written", 14);
      std::raise(signal);
      _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child ended with status " << status;
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_EQ(filesInFolder(), 0) << "after signal " << signal;
  }
}

TEST_F(AtomicFiles, ATargetThatIsNotARegularFileIsWrittenInPlace) {
  ASSERT_EQ(symlink("/dev/null", (directory_ / "null").c_str()), 0);
  writeFileAtomically(directory_ / "null", "into the device");
  EXPECT_TRUE(fs::is_symlink(directory_ / "null"));
  EXPECT_TRUE(fs::is_character_file(directory_ / "null"));
  EXPECT_EQ(filesInFolder(), 1);
  EXPECT_THROW(writeFileAtomically("/dev/full", "more than the device takes"), OutputFileError);
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST_F(AtomicFiles, ANameAsLongAsTheFileSystemTakesIsWritten) {
  const fs::path longest = directory_ / std::string(255, 'x');
  writeFileAtomically(longest, "x");
  EXPECT_TRUE(fs::exists(longest));
}

}  // namespace
}  // namespace rise
