// Runs the `rise` binary as a user would, under limits a test sets: its
// address space (setrlimit RLIMIT_AS), the size of the files it may write
// (RLIMIT_FSIZE, which makes a full disk of any folder) and the seconds it
// may run, after which it is killed. Standard input comes from a file.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

namespace rise::process_testing {

struct Limits {
  std::uint64_t addressSpaceBytes = 0;  // 0: none
  std::uint64_t fileSizeBytes = 0;      // 0: none
  double seconds = 60.0;
  std::string standardInput = "/dev/null";
};

struct Outcome {
  int status = -1;  // the exit status; -1 when it was killed
  bool timedOut = false;
  std::string output;  // standard output and standard error together
  double seconds = 0.0;
};

namespace detail {

inline void limit(int resource, std::uint64_t bytes) {
  if (bytes == 0) return;
  const rlimit value{bytes, bytes};
  setrlimit(resource, &value);
}

// In the child: the limits, the input, the output to the pipe, then rise.
// Only calls that are safe between fork and exec: the arguments are made
// before the fork.
[[noreturn]] inline void becomeRise(const std::vector<char*>& argv, const Limits& limits,
                                    int outputPipe) {
  limit(RLIMIT_AS, limits.addressSpaceBytes);
  limit(RLIMIT_FSIZE, limits.fileSizeBytes);
  signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
  const int input = open(limits.standardInput.c_str(), O_RDONLY);
  dup2(input, STDIN_FILENO);
  dup2(outputPipe, STDOUT_FILENO);
  dup2(outputPipe, STDERR_FILENO);
  execv(RISE_EXECUTABLE, argv.data());
  _exit(127);
}

}  // namespace detail

inline Outcome runRise(const std::vector<std::string>& arguments, const Limits& limits = {}) {
  std::vector<char*> argv{const_cast<char*>(RISE_EXECUTABLE)};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  int pipeEnds[2];
  if (pipe(pipeEnds) != 0) return {};
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) detail::becomeRise(argv, limits, pipeEnds[1]);
  close(pipeEnds[1]);
  fcntl(pipeEnds[0], F_SETFL, O_NONBLOCK);
  Outcome outcome;
  int status = 0;
  char buffer[4096];
  for (;;) {
    ssize_t read = 0;
    while ((read = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0)
      outcome.output.append(buffer, static_cast<std::size_t>(read));
    if (waitpid(child, &status, WNOHANG) == child) break;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (elapsed.count() > limits.seconds && !outcome.timedOut) {
      outcome.timedOut = true;
      kill(child, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ssize_t read = 0;
  while ((read = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0)
    outcome.output.append(buffer, static_cast<std::size_t>(read));
  close(pipeEnds[0]);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

}  // namespace rise::process_testing
