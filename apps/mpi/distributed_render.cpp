#include "distributed_render.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <vector>

#include "algorithms/registry.hpp"
#include "job.hpp"
#include "render/film.hpp"
#include "render/tile_statistics.hpp"
#include "tiles.hpp"
#include "work_queue.hpp"

namespace rise::mpi {
namespace {

namespace fs = std::filesystem;

// One piece of work: a region of one frame (-1: the still image).
struct WorkItem {
  int frame;
  PixelRect area;
};

RenderResult renderItem(const Renderer& renderer, cli::Job& job, const Camera& camera,
                        const WorkItem& item, const std::vector<std::string>& buffers) {
  if (item.frame >= 0)
    job.scene.camera = cameraForFrame(camera, item.frame, job.scene.animationFrames);
  RenderSettings settings = job.settings;
  if (item.area.width() != settings.width || item.area.height() != settings.height)
    settings.region = item.area;
  RenderObserver unwatched;  // the ranks draw no progress bars
  RenderResult result = renderTimed(renderer, job.scene, settings, unwatched);
  // Only the buffers asked for travel to rank 0.
  std::erase_if(result.buffers, [&](const auto& buffer) {
    return std::find(buffers.begin(), buffers.end(), buffer.first) == buffers.end();
  });
  return result;
}

// What rank 0 hands out: the frames the options choose, or the image's tiles.
std::variant<std::vector<WorkItem>, std::string> workItems(const DistributedRenderOptions& options,
                                                           const cli::Job& job) {
  const PixelRect whole{0, 0, job.settings.width, job.settings.height};
  std::vector<WorkItem> items;
  if (options.animation.requested()) {
    const auto frames = cli::framesToRender(options.animation, job.scene);
    if (const std::string* problem = std::get_if<std::string>(&frames)) return *problem;
    for (int frame : std::get<std::vector<int>>(frames)) items.push_back({frame, whole});
    return items;
  }
  for (const PixelRect& tile : makeTiles(whole.x1, whole.y1, options.tileSize))
    items.push_back({-1, tile});
  return items;
}

fs::path outputOf(const DistributedRenderOptions& options) {
  if (!options.output.empty()) return options.output;
  return options.animation.requested() ? cli::defaultFramePattern(options.settings.scenePath)
                                       : cli::defaultOutput(options.settings.scenePath, ".png");
}

// Rank 0's checks before it hands out work: the files it will write, the
// scene, the frames. Returns the status of the message printed about the
// first that fails.
int prepareRun(const DistributedRenderOptions& options, const Renderer& renderer,
               std::optional<cli::Job>& job, std::vector<WorkItem>& items) {
  if (!cli::drawsShadowsAsked(renderer.description(), options.settings.request.settings.shadows))
    return cli::kExitBadInput;
  const fs::path output = options.output.empty()
                              ? cli::defaultOutput(options.settings.scenePath, ".png")
                              : options.output;
  if (!cli::renderOutputsAreValid(options.outputs, options.settings, renderer.description(),
                                  output))
    return cli::kExitBadInput;
  const std::vector<std::string>& buffers = options.outputs.buffers;
  if (!options.animation.requested() &&
      std::find(buffers.begin(), buffers.end(), "shadow-map") != buffers.end()) {
    std::cerr << "rise-mpi: --aov shadow-map: the shadow map is the light's picture, not cut "
                 "into the image's tiles; write it with rise render, or with --frames\n";
    return cli::kExitBadInput;
  }
  std::variant<cli::Job, int> prepared = cli::prepare(options.settings, renderer);
  if (const int* failed = std::get_if<int>(&prepared)) return *failed;
  const auto chosen = workItems(options, std::get<cli::Job>(prepared));
  std::optional<std::string> problem;
  if (const std::string* message = std::get_if<std::string>(&chosen))
    problem = *message;
  else if (options.animation.requested() && !options.output.empty())
    problem = cli::animationOutputProblem(options.output, options.animation.video);
  if (problem) {
    std::cerr << "rise-mpi: " << *problem << "\n";
    return cli::kExitBadInput;
  }
  job = std::get<cli::Job>(std::move(prepared));
  items = std::get<std::vector<WorkItem>>(chosen);
  return 0;
}

// What rank 0 makes of the results: each frame written as it comes in, or
// the tiles put together into the image, its buffers and its statistics.
class Gatherer {
 public:
  Gatherer(const DistributedRenderOptions& options, const Renderer& renderer, const cli::Job& job,
           std::vector<WorkItem> items)
      : options_(options),
        renderer_(renderer),
        job_(job),
        items_(std::move(items)),
        tileStats_(items_.size()) {
    whole_.image = Image(job.settings.width, job.settings.height);
    for (const std::string& name : options.outputs.buffers) whole_.buffers[name] = whole_.image;
  }

  const std::vector<WorkItem>& items() const { return items_; }

  int take(int item, RenderResult result) {
    const WorkItem& piece = items_[static_cast<std::size_t>(item)];
    if (piece.frame >= 0) return write(result, cli::framePath(outputOf(options_), piece.frame));
    cli::paste(result.image, piece.area, whole_.image);
    for (auto& [name, buffer] : whole_.buffers)
      cli::paste(result.buffers.at(name), piece.area, buffer);
    tileStats_[static_cast<std::size_t>(item)] = std::move(result.stats);
    return 0;
  }

  // Writes the still image, once every tile is in.
  int finish(double seconds) {
    whole_.stats = combinedTileStats(renderer_.description(), tileStats_, seconds);
    return write(whole_, outputOf(options_));
  }

 private:
  int write(const RenderResult& result, const fs::path& path) {
    const cli::RenderDescription description = cli::describe(job_, renderer_.name());
    try {
      cli::writeRenderOutputs(result, path, options_.outputs, description);
    } catch (const std::exception& error) {
      std::cerr << "rise-mpi: " << error.what() << "\n";
      return cli::kExitOutputError;
    }
    cli::printStats(std::cerr, description, result.stats);
    std::cerr << "wrote " << path.string() << "\n";
    return 0;
  }

  const DistributedRenderOptions& options_;
  const Renderer& renderer_;
  const cli::Job& job_;
  std::vector<WorkItem> items_;
  std::vector<Stats> tileStats_;
  RenderResult whole_;
};

}  // namespace

int coordinate(const DistributedRenderOptions& options, int ranks) {
  const auto start = std::chrono::steady_clock::now();
  const Renderer& renderer = *findRenderer(options.algorithm);
  std::optional<cli::Job> job;
  std::vector<WorkItem> items;
  const int prepared = prepareRun(options, renderer, job, items);
  std::optional<Gatherer> gatherer;
  if (prepared == 0) gatherer.emplace(options, renderer, *job, std::move(items));
  const int count = gatherer ? static_cast<int>(gatherer->items().size()) : 0;
  const int status = handOut(ranks, count, prepared, [&](int item, RenderResult result) {
    return gatherer->take(item, std::move(result));
  });
  if (status != 0) return status;
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::cerr << "rise-mpi: " << ranks - 1 << " ranks rendering, " << seconds.count() << " s\n";
  if (!options.animation.requested()) return gatherer->finish(seconds.count());
  if (options.animation.video.empty()) return 0;
  std::vector<int> frames;
  for (const WorkItem& item : gatherer->items()) frames.push_back(item.frame);
  return cli::writeVideo(outputOf(options), frames, options.animation.video);
}

int work(const DistributedRenderOptions& options) {
  const Renderer& renderer = *findRenderer(options.algorithm);
  std::variant<cli::Job, int> prepared = cli::prepare(options.settings, renderer);
  cli::Job* job = std::get_if<cli::Job>(&prepared);
  int status = job ? 0 : std::get<int>(prepared);
  std::vector<WorkItem> items;
  if (job) {
    auto chosen = workItems(options, *job);
    if (auto* chosenItems = std::get_if<std::vector<WorkItem>>(&chosen))
      items = std::move(*chosenItems);
    else
      status = cli::kExitBadInput;  // rank 0 says why
  }
  const Camera camera = job ? job->scene.camera : Camera{};
  return serve(status, [&](int item) {
    return renderItem(renderer, *job, camera, items[static_cast<std::size_t>(item)],
                      options.outputs.buffers);
  });
}

}  // namespace rise::mpi
