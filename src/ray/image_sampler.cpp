#include "ray/image_sampler.hpp"

#include <optional>
#include <string>

#include "core/text.hpp"

namespace rise {

TileTrace::TileTrace(const PixelRect& area, FilmTile film, RenderResult& buffers,
                     RenderObserver& observer)
    : area_(area),
      film_(std::move(film)),
      observer_(observer),
      steps_(observer.stepRecorder()),
      depth_(buffers.buffer("depth")),
      normal_(buffers.buffer("normal")),
      cost_(buffers.buffer("cost")) {}

void TileTrace::recordBuffers(const glm::ivec2& pixel, const SampleResult& shown,
                              std::uint64_t tests) {
  if (depth_) depth_->at(pixel.x, pixel.y) = Color(shown.depth);
  if (normal_) normal_->at(pixel.x, pixel.y) = shown.normal;
  if (cost_) cost_->at(pixel.x, pixel.y) = Color(static_cast<float>(tests));
}

namespace {

Step tileStep(const TileTrace& tile) {
  const PixelRect& area = tile.area();
  Step step{"tile", "tile " + std::to_string(area.x0) + "," + std::to_string(area.y0) + " " +
                        std::to_string(area.width()) + "x" + std::to_string(area.height()) +
                        " traced: " + counted(tile.counters.rays(), "ray") + ", " +
                        counted(tile.counters.intersections.tests, "intersection test")};
  step.values = {{"rays", static_cast<double>(tile.counters.rays())},
                 {"intersection_tests", static_cast<double>(tile.counters.intersections.tests)}};
  step.shapes.push_back({StepShape::Kind::Rectangle,
                         "tile",
                         {Vec2(static_cast<float>(area.x0), static_cast<float>(area.y0)),
                          Vec2(static_cast<float>(area.x1), static_cast<float>(area.y1))}});
  step.settled.push_back(area);
  return step;
}

// What a traced tile leaves for the end of the render: its costs and, where
// a pixel's colour needs the samples of the tiles around it, its own.
struct TracedTile {
  TraceCounters counters;
  std::uint64_t refinedPixels = 0;
  std::optional<FilmTile> samples;
};

}  // namespace

RenderResult traceImage(const RenderSettings& settings, RenderObserver& observer,
                        const std::function<void(TileTrace&)>& traceTile) {
  RenderResult result;
  if (settings.wantsBuffer("depth"))
    result.buffers["depth"] = Image(settings.width, settings.height, Color(kInfinity));
  if (settings.wantsBuffer("normal"))
    result.buffers["normal"] = Image(settings.width, settings.height);
  if (settings.wantsBuffer("cost")) result.buffers["cost"] = Image(settings.width, settings.height);
  Film film(settings.width, settings.height, settings.sampling.filter);

  StepRecorder* const steps = observer.stepRecorder();
  // The tiles are those of the whole image, and only those whose samples
  // reach the region are traced, so that every pixel of the region adds up
  // the same samples in the same order as in the whole image.
  std::vector<PixelRect> areas;
  for (const PixelRect& area : makeTiles(settings.width, settings.height))
    if (!film.reachOf(area).intersection(settings.area()).isEmpty()) areas.push_back(area);
  // A tile's samples are made on the worker that traces it, and given back
  // at once where the film needs no tile's samples but its own: a worker's
  // next tile then reuses memory it has just touched.
  std::vector<TracedTile> traced(areas.size());
  // Every traced tile writes its pixels, and nothing reads the others: the
  // region is cropped from it.
  Image shown = Image::unfilled(settings.width, settings.height);
  const Workers workers(settings.threads, observer);
  workers.forEachTask(static_cast<int>(areas.size()), [&](int index) {
    const PixelRect& area = areas[static_cast<std::size_t>(index)];
    TileTrace tile(area, film.tileFor(area), result, observer);
    traceTile(tile);
    if (steps) steps->record(tileStep(tile), index);
    tile.film().resolveInto(shown, tile.area());
    observer.onPixelsDone(tile.area(), shown);
    TracedTile& outcome = traced[static_cast<std::size_t>(index)];
    outcome.counters = tile.counters;
    outcome.refinedPixels = tile.refinedPixels;
    if (!film.tilesAreFinal()) outcome.samples = std::move(tile.film());
  });
  // Nobody wants what a cancelled render made: return at once.
  if (observer.cancelled()) return result;

  TraceCounters counters;
  std::uint64_t refinedPixels = 0;
  for (const TracedTile& tile : traced) {
    if (tile.samples) film.merge(*tile.samples);
    counters += tile.counters;
    refinedPixels += tile.refinedPixels;
  }
  result.image = film.tilesAreFinal() ? std::move(shown) : film.resolve(workers);
  cropToRegion(result, settings);
  counters.addTo(result.stats);
  result.stats.add("samples_per_pixel", settings.sampling.samples);
  if (settings.sampling.pattern == SamplePattern::Adaptive)
    result.stats.add("adaptive_refined_pixels", static_cast<double>(refinedPixels));
  return result;
}

}  // namespace rise
