// The help says what a student needs, in words: no command's help shows the
// parser's notation, every option that takes a value names it with a word
// and says what it takes, `rise --version` answers, and `rise inspect`
// offers only the algorithms whose rays it can show.
#include <gtest/gtest.h>

#include <string>

#include "algorithms/registry.hpp"
#include "support/rise_command_testing.hpp"

namespace rise {
namespace {

const char* kCommands[] = {"",        "render",  "compare", "validate", "algorithms",
                           "explain", "inspect", "merge",   "manual"};

TEST(Help, SaysWhatEachOptionTakesInWords) {
  for (const std::string command : kCommands) {
    const CommandResult help = runRise(command + " --help");
    EXPECT_EQ(help.status, 0) << command;
    for (const std::string notation :
         {"{false}", "{true}", "INT", "UINT", "FLOAT", "TEXT", "ENUM", "->", ":in [", "=", "x 4"})
      EXPECT_EQ(help.output.find(notation), std::string::npos)
          << "rise " << command << " --help shows '" << notation << "':\n"
          << help.output;
  }
  const CommandResult render = runRise("render --help");
  for (const std::string said :
       {"--width N ", "a whole number from 1 to 32768", "--tessellation N ", "default 8",
        "--pattern NAME ", "one of: adaptive, jittered, none, random, regular", "--tile X,Y,W,H ",
        "-o,--output FILE ", "--no-cull  ", "Examples:"})
    EXPECT_NE(render.output.find(said), std::string::npos) << said << " in\n" << render.output;
}

TEST(Help, TheVersionIsAnswered) {
  const CommandResult version = runRise("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.output, "rise " RISE_VERSION "\n");
}

TEST(Help, InspectOffersOnlyTheAlgorithmsThatTraceRays) {
  const CommandResult help = runRise("inspect --help");
  const std::size_t line = help.output.find("-a,--algorithm");
  ASSERT_NE(line, std::string::npos) << help.output;
  const std::string offered = help.output.substr(line, help.output.find('\n', line) - line);
  for (const Renderer* renderer : allRenderers()) {
    const bool tracesRays = renderer->description().offers(Look::RayTrees);
    EXPECT_EQ(offered.find(" " + std::string(renderer->name())) != std::string::npos, tracesRays)
        << renderer->name() << " in " << offered;
  }
  const CommandResult zBuffer =
      runRise("inspect " + example("classic.yaml") + " --pixel 1,1 -a z-buffer");
  EXPECT_EQ(zBuffer.status, 2);
  EXPECT_NE(zBuffer.output.find("traces no rays"), std::string::npos) << zBuffer.output;
}

}  // namespace
}  // namespace rise
