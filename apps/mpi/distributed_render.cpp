#include "distributed_render.hpp"

#include <mpi.h>

#include <array>
#include <chrono>
#include <iostream>
#include <vector>

#include "algorithms/registry.hpp"
#include "job.hpp"
#include "render/film.hpp"

namespace rise::mpi {
namespace {

namespace fs = std::filesystem;

// The messages: a rank says it is ready, sends a result or says it failed;
// rank 0 answers with work or with the word to stop.
enum Tag : int { kReady = 1, kResult, kFailed, kWork, kStop };

// One piece of work: a region of one frame (-1: the still image).
struct WorkItem {
  int frame;
  PixelRect area;
};

std::array<int, 5> encode(const WorkItem& item) {
  return {item.frame, item.area.x0, item.area.y0, item.area.x1, item.area.y1};
}

WorkItem decode(const std::array<int, 5>& values) {
  return {values[0], {values[1], values[2], values[3], values[4]}};
}

void sendStatus(Tag tag, int status) { MPI_Send(&status, 1, MPI_INT, 0, tag, MPI_COMM_WORLD); }

RenderResult renderItem(const Renderer& renderer, cli::Job& job, const Camera& camera,
                        const WorkItem& item) {
  if (item.frame >= 0)
    job.scene.camera = cameraForFrame(camera, item.frame, job.scene.animationFrames);
  RenderSettings settings = job.settings;
  if (item.area.width() != settings.width || item.area.height() != settings.height)
    settings.region = item.area;
  RenderObserver unwatched;  // the ranks draw no progress bars
  return renderer.render(job.scene, settings, unwatched);
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

// Rank 0's queue: who holds which item, the image being gathered, and the
// first failure.
class Coordinator {
 public:
  Coordinator(const DistributedRenderOptions& options, std::vector<WorkItem> items,
              const RenderSettings& settings)
      : options_(options),
        items_(std::move(items)),
        whole_(settings.width, settings.height),
        pattern_(options.output.empty() ? cli::defaultFramePattern(options.settings.scenePath)
                                        : options.output) {}

  // Answers every rank until each has stopped or failed.
  void run(int ranks) {
    std::vector<int> held(static_cast<std::size_t>(ranks), -1);
    for (int active = ranks - 1; active > 0;) {
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
      const int rank = status.MPI_SOURCE;
      int& item = held[static_cast<std::size_t>(rank)];
      if (status.MPI_TAG == kResult) {
        receiveResult(rank, items_[static_cast<std::size_t>(item)]);
      } else {
        int rankStatus = 0;
        MPI_Recv(&rankStatus, 1, MPI_INT, rank, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (status.MPI_TAG == kFailed) {
          fail(rankStatus, "rank " + std::to_string(rank) + " failed");
          --active;
          continue;
        }
      }
      if (failure_ != 0 || next_ == items_.size()) {
        MPI_Send(nullptr, 0, MPI_INT, rank, kStop, MPI_COMM_WORLD);
        --active;
        continue;
      }
      item = static_cast<int>(next_++);
      const std::array<int, 5> work = encode(items_[static_cast<std::size_t>(item)]);
      MPI_Send(work.data(), 5, MPI_INT, rank, kWork, MPI_COMM_WORLD);
    }
  }

  void fail(int status, const std::string& why) {
    if (failure_ != 0) return;
    failure_ = status;
    std::cerr << "rise-mpi: " << why << "; the run stops\n";
  }

  // Writes the still image once every tile is in; returns the exit status.
  int finish() {
    if (failure_ != 0 || options_.animation.requested()) return failure_;
    return write(whole_, options_.output.empty()
                             ? cli::defaultOutput(options_.settings.scenePath, ".png")
                             : options_.output);
  }

 private:
  void receiveResult(int rank, const WorkItem& item) {
    Image piece(item.area.width(), item.area.height());
    MPI_Recv(&piece.at(0, 0), 3 * item.area.width() * item.area.height(), MPI_FLOAT, rank, kResult,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (item.frame >= 0) {
      if (failure_ == 0) failure_ = write(piece, cli::framePath(pattern_, item.frame));
      return;
    }
    for (int y = 0; y < piece.height(); ++y)
      for (int x = 0; x < piece.width(); ++x)
        whole_.at(item.area.x0 + x, item.area.y0 + y) = piece.at(x, y);
  }

  int write(const Image& image, const fs::path& path) {
    try {
      writeImage(image, path, options_.encoding);
    } catch (const std::exception& error) {
      std::cerr << "rise-mpi: " << error.what() << "\n";
      return cli::kExitOutputError;
    }
    std::cerr << "wrote " << path.string() << "\n";
    return 0;
  }

  const DistributedRenderOptions& options_;
  std::vector<WorkItem> items_;
  std::size_t next_ = 0;
  Image whole_;
  fs::path pattern_;
  int failure_ = 0;
};

}  // namespace

int coordinate(const DistributedRenderOptions& options, int ranks) {
  const auto start = std::chrono::steady_clock::now();
  std::variant<cli::Job, int> prepared =
      cli::prepare(options.settings, {findRenderer(options.algorithm)->description().family});
  std::vector<WorkItem> items;
  int status = 0;
  if (const int* failed = std::get_if<int>(&prepared)) {
    status = *failed;
  } else {
    const auto chosen = workItems(options, std::get<cli::Job>(prepared));
    if (const std::string* problem = std::get_if<std::string>(&chosen)) {
      std::cerr << "rise-mpi: " << *problem << "\n";
      status = cli::kExitBadInput;
    } else {
      items = std::get<std::vector<WorkItem>>(chosen);
    }
  }
  if (options.animation.requested() && !options.output.empty() && status == 0) {
    if (const std::optional<std::string> problem =
            cli::animationOutputProblem(options.output, options.animation.video)) {
      std::cerr << "rise-mpi: " << *problem << "\n";
      status = cli::kExitBadInput;
    }
  }
  const RenderSettings settings =
      status == 0 ? std::get<cli::Job>(prepared).settings : RenderSettings{};
  Coordinator coordinator(options, std::move(items), settings);
  if (status != 0) coordinator.fail(status, "rank 0 cannot render the scene");
  coordinator.run(ranks);
  if (const int finished = coordinator.finish(); finished != 0) return finished;
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::cerr << "rise-mpi: " << ranks - 1 << " ranks rendering, " << seconds.count() << " s\n";
  if (options.animation.requested() && !options.animation.video.empty()) {
    const auto frames = cli::framesToRender(options.animation, std::get<cli::Job>(prepared).scene);
    return cli::writeVideo(options.output.empty()
                               ? cli::defaultFramePattern(options.settings.scenePath)
                               : options.output,
                           std::get<std::vector<int>>(frames), options.animation.video);
  }
  return 0;
}

int work(const DistributedRenderOptions& options) {
  std::variant<cli::Job, int> prepared =
      cli::prepare(options.settings, {findRenderer(options.algorithm)->description().family});
  if (const int* failed = std::get_if<int>(&prepared)) {
    sendStatus(kFailed, *failed);
    return *failed;
  }
  cli::Job& job = std::get<cli::Job>(prepared);
  const Renderer& renderer = *findRenderer(options.algorithm);
  const Camera camera = job.scene.camera;
  sendStatus(kReady, 0);
  for (;;) {
    MPI_Status status;
    std::array<int, 5> values{};
    MPI_Recv(values.data(), 5, MPI_INT, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if (status.MPI_TAG == kStop) return 0;
    try {
      const RenderResult result = renderItem(renderer, job, camera, decode(values));
      MPI_Send(result.image.pixels().data(), 3 * result.image.width() * result.image.height(),
               MPI_FLOAT, 0, kResult, MPI_COMM_WORLD);
    } catch (const std::exception& error) {
      std::cerr << "rise-mpi: " << error.what() << "\n";
      sendStatus(kFailed, cli::kExitOutputError);
      return cli::kExitOutputError;
    }
  }
}

}  // namespace rise::mpi
