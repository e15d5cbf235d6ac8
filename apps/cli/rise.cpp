#include "core/process_memory.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  rise::setUpProcessMemory();
  return rise::cli::run(argc, argv);
}
