#include "run.hpp"

int main(int argc, char** argv) { return rise::cli::run(argc, argv); }
