#include "distributed_compare.hpp"

#include <iostream>
#include <optional>

#include "algorithms/registry.hpp"
#include "job.hpp"
#include "work_queue.hpp"

namespace rise::mpi {

int coordinateComparison(const cli::CompareOptions& options, int ranks) {
  const std::vector<const Renderer*> renderers = cli::comparedRenderers(options);
  const std::variant<std::filesystem::path, int> directory = cli::comparisonFolder(options);
  std::variant<cli::Job, int> prepared = cli::kExitBadInput;
  if (std::holds_alternative<std::filesystem::path>(directory))
    prepared = cli::prepare(options.settings, renderers);
  const int* failed = std::get_if<int>(&directory);
  if (!failed) failed = std::get_if<int>(&prepared);

  std::vector<std::optional<RenderResult>> results(renderers.size());
  const int status = handOut(ranks, static_cast<int>(renderers.size()), failed ? *failed : 0,
                             [&](int item, RenderResult result) {
                               const std::size_t index = static_cast<std::size_t>(item);
                               std::cerr << renderers[index]->name() << ": "
                                         << result.stats.value("render_seconds") << " s\n";
                               results[index] = std::move(result);
                               return 0;
                             });
  if (status != 0) return status;
  std::vector<ComparedRender> renders;
  for (std::size_t index = 0; index < renderers.size(); ++index)
    renders.push_back({&renderers[index]->description(), *std::move(results[index])});
  return cli::writeComparisonFolder(std::get<std::filesystem::path>(directory),
                                    std::get<cli::Job>(prepared).scene.source, renders,
                                    options.encoding);
}

int serveComparison(const cli::CompareOptions& options) {
  const std::vector<const Renderer*> renderers = cli::comparedRenderers(options);
  const std::variant<cli::Job, int> prepared = cli::prepare(options.settings, renderers);
  const cli::Job* job = std::get_if<cli::Job>(&prepared);
  return serve(job ? 0 : std::get<int>(prepared), [&](int item) {
    RenderObserver unwatched;  // the ranks draw no progress bars
    RenderResult result = renderTimed(*renderers[static_cast<std::size_t>(item)], job->scene,
                                      job->settings, unwatched);
    result.buffers.clear();  // the comparison shows the images and the numbers
    return result;
  });
}

}  // namespace rise::mpi
