// `rise-mpi`: `rise render` shared among the ranks of an MPI run,
//   mpirun -np 5 rise-mpi render SCENE -o image.png
//   mpirun -np 5 rise-mpi render SCENE --frames 0-39 -o run_%04d.png
// and `rise compare` shared the same way, an algorithm to each rank that asks,
//   mpirun -np 5 rise-mpi compare SCENE -o DIR
// Rank 0 hands out the work and writes the files; ranks 1 and up render, so
// a run needs two ranks at least. The files are the ones `rise render` and
// `rise compare` make, value for value (the times aside). Exit status as `rise`'s: 0 done, 1 a file
// could not be written, 2 bad input.
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "core/process_memory.hpp"
#include "distributed_compare.hpp"
#include "distributed_render.hpp"
#include "job.hpp"
#include "option_checks.hpp"

namespace rise::mpi {
namespace {

CLI::App* addRenderCommand(CLI::App& app, DistributedRenderOptions& options) {
  CLI::App* command =
      app.add_subcommand("render", "Render a scene, or its frames, on the ranks of an MPI run");
  cli::addSettingsOptions(*command, options.settings);
  cli::addAnimationOptions(*command, options.animation);
  command->add_option("-o,--output", options.output,
                      "Image to write: .png, .ppm or .exr (default: the scene's name, .png); with "
                      "--frames, a pattern with the frame number: run_%04d.png");
  command->add_option("-a,--algorithm", options.algorithm, "Algorithm (see `rise algorithms`)")
      ->check(CLI::IsMember(cli::algorithmNames()));
  cli::addRenderOutputOptions(*command, options.outputs);
  command
      ->add_option("--tile-size", options.tileSize,
                   "The side of the square tiles handed out, in pixels")
      ->capture_default_str()
      ->check(cli::wholeNumberFrom(1, 4096));
  return command;
}

CLI::App* addCompareCommand(CLI::App& app, cli::CompareOptions& options) {
  CLI::App* command = app.add_subcommand(
      "compare",
      "Render a scene with every algorithm, the algorithms shared among the ranks: "
      "the folder `rise compare` writes");
  cli::addCompareOptions(*command, options);
  return command;
}

int run(int argc, char** argv, int rank, int ranks) {
  CLI::App app{"RISE over MPI: a render or a comparison shared among the ranks", "rise-mpi"};
  app.require_subcommand(1);
  DistributedRenderOptions options;
  const CLI::App* renderCommand = addRenderCommand(app, options);
  cli::CompareOptions compareOptions;
  addCompareCommand(app, compareOptions);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // Every rank parses the same arguments: rank 0 alone speaks.
    if (rank != 0) return cli::kExitBadInput;
    return app.exit(error) == 0 ? 0 : cli::kExitBadInput;
  }
  if (ranks < 2) {
    if (rank == 0)
      std::cerr << "rise-mpi: rank 0 hands out the work and the others render; expected 2 "
                   "ranks or more (mpirun -np 3 rise-mpi ...), or rise alone\n";
    return cli::kExitBadInput;
  }
  if (*renderCommand) return rank == 0 ? coordinate(options, ranks) : work(options);
  return rank == 0 ? coordinateComparison(compareOptions, ranks) : serveComparison(compareOptions);
}

}  // namespace
}  // namespace rise::mpi

int main(int argc, char** argv) {
  rise::setUpProcessMemory();
  MPI_Init(&argc, &argv);
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const int status = rise::mpi::run(argc, argv, rank, ranks);
  MPI_Finalize();
  return status;
}
