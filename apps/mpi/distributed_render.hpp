// A render shared among MPI ranks: rank 0 cuts the image into tiles (or a
// sequence into frames) and hands them out from a queue (work_queue.hpp);
// the others render what they are given and send back the pixels, the
// buffers asked for and the statistics; rank 0 writes the files, each whole,
// as `rise render` does. Every rank loads the scene itself. A rank that fails
// says why and stops the handing out: the run fails with its status and no
// file is written.
#pragma once

#include <filesystem>
#include <string>

#include "algorithms/registry.hpp"
#include "animation.hpp"
#include "render_outputs.hpp"
#include "settings_options.hpp"

namespace rise::mpi {

struct DistributedRenderOptions {
  cli::SettingsOptions settings;
  std::filesystem::path output;
  std::string algorithm{defaultRenderer(Use::Render).name()};
  cli::RenderOutputOptions outputs;
  cli::AnimationOptions animation;
  int tileSize = 64;
};

// Rank 0's part: returns the run's exit status.
int coordinate(const DistributedRenderOptions& options, int ranks);

// Every other rank's part: returns its exit status.
int work(const DistributedRenderOptions& options);

}  // namespace rise::mpi
