// The command line of `rise`, callable from the program's main and from the
// command-line fuzzer.
#pragma once

namespace rise::cli {

// Parses the arguments and runs the command they name; returns the exit
// status (job.hpp).
int run(int argc, char** argv);

}  // namespace rise::cli
