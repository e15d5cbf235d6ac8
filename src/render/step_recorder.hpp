// The steps of an algorithm, as it reports them in its own words: what a
// teacher shows before the final image. Each algorithm says what a step is
// (a window examined, a pair of polygons compared, a polygon drawn, a
// scanline swept, a tile traced), tells it in a sentence, gives the numbers
// and tables a student reads (the active edge list, the polygons classified),
// the shapes to draw over the image (the window, the spans, the polygon
// split), and which pixels it changed: so that the image as it stood after
// any step can be rebuilt.
//
// A render records steps only when its observer hands it a StepRecorder;
// otherwise it pays one test of a null pointer where a step would be.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/image.hpp"
#include "core/math.hpp"
#include "render/ray_tree.hpp"

namespace rise {

// A pixel a step set, or tried to: its colour and face, and the inverse depth
// w = 1/n it was drawn at (0 where the algorithm has none). `kept` is false
// where the pixel lost a depth test and stayed as it was.
struct PixelWrite {
  int x, y;
  Color color;
  int face;
  float inverseDepth = 0.0f;
  bool kept = true;
};

// A shape drawn over the image, in raster coordinates (pixel (i, j) covers
// [i, i+1) x [j, j+1)): a rectangle (two corners), a polygon, a segment or a
// point. `role` says what it is, in a word the player colours by: "window",
// "polygon", "other", "behind", "front", "span", "edge", "tile", "rays",
// "fallback".
struct StepShape {
  enum class Kind { Rectangle, Polygon, Segment, Point };
  Kind kind;
  std::string role;
  std::vector<Vec2> points;

  bool operator==(const StepShape&) const = default;
};

// A small table: the active edge list, the polygons a window classified.
// A cell holds a number or a word.
using StepCell = std::variant<double, std::string>;
struct StepTable {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<StepCell>> rows;
};

// What the steps up to one, and it, did: every step, kept or not.
struct StepTally {
  std::vector<std::pair<std::string, std::uint64_t>> kinds;  // steps of each kind, as met
  std::uint64_t painted = 0;                                 // pixels set
  std::uint64_t hidden = 0;   // pixels where a write lost a depth test
  std::uint64_t settled = 0;  // pixels made final

  void add(const struct Step& step);
};

struct Step {
  Step() = default;
  Step(std::string kind, std::string text) : kind(std::move(kind)), text(std::move(text)) {}

  std::string kind;  // the algorithm's word for it: "window", "compare", "scanline"...
  std::string text;  // the step in a sentence
  std::vector<std::pair<std::string, double>> values;
  std::vector<StepTable> tables;
  std::vector<StepShape> shapes;
  std::vector<PixelWrite> writes;
  // Pixels that are final after this step: their colour is the render's.
  std::vector<PixelRect> settled;
  int skippedBefore = 0;  // steps left out by the budget since the last kept one
  // What the steps left out before this one changed, for rebuilding the
  // image as it stood: applied before this step's own.
  std::vector<PixelWrite> writesBefore;
  std::vector<PixelRect> settledBefore;
  StepTally soFar;  // of a kept step: what it and every step before it did
};

// What a recorder keeps: the steps that touch `region` (all, when it is
// empty), of those every `every`th (0: as many as keep about
// kDefaultKeptSteps), and the ray trees of the samples of `treePixel`.
struct StepBudget {
  static constexpr int kDefaultKeptSteps = 200;

  std::optional<PixelRect> region;
  int every = 0;
  std::optional<glm::ivec2> treePixel;
};

// Where the steps are recorded.
class StepRecorder {
 public:
  explicit StepRecorder(StepBudget budget = {}) : budget_(std::move(budget)) {}

  const StepBudget& budget() const { return budget_; }

  // At most this many steps are recorded in full; later ones only by the
  // pixels they change.
  static constexpr std::size_t kMostDetailedSteps = 100000;

  // Whether a step within `bounds` is worth telling in full: it touches the
  // budget's region and the recorder is not full. Counts the steps it turns
  // down, which a step that changes no pixel need not be recorded at all.
  bool wantsDetail(const PixelRect& bounds);
  std::uint64_t stepsNotDetailed() const { return notDetailed_; }
  bool wantsTreeOf(const glm::ivec2& pixel) const { return budget_.treePixel == pixel; }

  // Records a step in the order given by `order`; a step recorded in parts
  // (one per band of the image, drawn by different threads) gives each part
  // the same order and its own `part`, and the parts are joined in part
  // order. Safe to call from several threads.
  void record(Step step, std::int64_t order, int part = 0);
  void recordTree(RayTree tree);

  // Every step, its parts joined, in order; what the budget keeps of them,
  // each kept step carrying the writes and settled pixels of the steps left
  // out before it; and the ray trees in the order of their samples.
  std::vector<Step> allSteps() const;
  std::vector<Step> keptSteps() const;
  std::vector<RayTree> trees() const;

 private:
  struct Recorded {
    std::int64_t order;
    int part;
    Step step;
  };

  StepBudget budget_;
  std::atomic<std::uint64_t> notDetailed_{0};
  mutable std::mutex mutex_;
  std::vector<Recorded> recorded_;
  std::vector<RayTree> trees_;
};

// The raster bounds of a step's shapes and writes; empty for a step with
// neither.
PixelRect boundsOf(const Step& step);

}  // namespace rise
