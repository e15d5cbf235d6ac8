#include "core/memory_reuse.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  rise::keepFreedMemoryForReuse();
  return rise::cli::run(argc, argv);
}
