// The hybrid algorithm's rule for silhouettes (hybrid.cpp). Polygons are not
// the exact surfaces: a curved object's lie inside its true outline, and at
// any edge rounding may put a pixel centre on either side. Where they disagree the item buffer is
// wrong there, and the pixel falls back to a full primary ray, Whitted's own. The rule:
//   outside  the pixel's ray misses its own item's exact surface: its polygon
//            reaches past the true outline;
//   inside   the item seen at a neighbouring pixel (left, right, above or
//            below) meets the pixel's ray nearer than its own item does, or
//            where the item buffer shows nothing: that item's true outline
//            reaches past its polygons. The neighbours of such a pixel are
//            tested against the same item in turn, so that the test follows
//            the outline as far out as it reaches.
// A pixel's own tests need only the item buffer, so each pixel is tested and
// shaded at once, a run of a row at a time, and nothing of it is kept in
// memory the size of the image but what its steps show. The outlines are
// followed once every row is shaded; the pixels they reach beyond the
// neighbours of their polygons (few, but a band of them around a coarsely
// cut sphere) are shaded again, by full primary rays, their first samples
// shaded once more as they were and taken back out of the image.
// Everywhere else the item buffer's answer is the primary ray's, to the bit.
// (A sliver of an exact surface narrower than a pixel, where none of its
// polygons is seen nearby, escapes the rule: a few pixels at most.)
#include <algorithm>
#include <deque>
#include <set>
#include <tuple>

#include "hybrid/hybrid_group.hpp"

namespace rise::hybrid {

// The nearest hit of the pixel's ray on the item's exact surface alone.
bool HybridGroup::intersect(const Item& item, GroupPass& pass, int x, int y, const Ray& ray,
                            Hit& hit, HybridCounters& counters) {
  const std::uint64_t before = counters.traced.intersections.tests;
  const bool found =
      shapeNumbered(item.shape)
          ->intersectPrimitive(item.primitive, ray, 0.0f, hit, counters.traced.intersections);
  const std::uint64_t tests = counters.traced.intersections.tests - before;
  counters.counts[kItemTests] += tests;
  addCost(pass, x, y, tests);
  return found;
}

// The pixel's ray against its own item's exact surface: the hit, or none
// (its shape none) where the item buffer shows nothing or the ray misses.
FoundHit HybridGroup::ownHit(GroupPass& pass, int x, int y, const Item& own, const Ray& ray,
                             HybridCounters& counters) {
  FoundHit found{ray, own, {}};
  if (own.shape >= 0 && intersect(own, pass, x, y, ray, found.hit, counters))
    found.hit.shape = shapeNumbered(own.shape);
  return found;
}

// Whether `item` meets the pixel's ray before the pixel's own item does,
// `own` its ray and its hit (at the same distance, the one the structures
// would pick: the first in the scene's order).
bool HybridGroup::coversNearer(const Item& item, GroupPass& pass, int x, int y, const FoundHit& own,
                               HybridCounters& counters) {
  Hit hit;
  if (!intersect(item, pass, x, y, own.ray, hit, counters)) return false;
  return std::tie(hit.t, item) < std::tie(own.hit.t, own.item);
}

// The faces the item buffer shows at the pixel's four neighbours, its own
// face where a neighbour is off the image. Read without a branch for each,
// which an edge running through a row would mispredict.
std::array<int, 4> HybridGroup::facesBeside(const ItemBuffer& items, int x, int y, int face) const {
  std::array<int, 4> faces{};
  for (std::size_t i = 0; i < kNeighbours.size(); ++i) {
    const glm::ivec2 beside{x + kNeighbours[i].x, y + kNeighbours[i].y};
    faces[i] = onImage(beside) ? items.faceAt(beside.x, beside.y) : face;
  }
  return faces;
}

// Pass 2 begins at each pixel: its ray against its own item's exact
// surface, then against each other item seen beside it; those that cover
// it nearer make it fall back, and are the seeds of followOutlines. Inside
// a polygon, as most pixels are, every neighbour shows the pixel's own
// face and there is no other item to test.
FoundHit HybridGroup::findHit(GroupPass& pass, int x, int y, const Ray& ray, PassWork& work) {
  const ItemBuffer& items = *pass.items;
  const int face = items.faceAt(x, y);
  const Item own = items.itemOf(face);
  if (pass.clearsSamples) pass.samples.means.at(x, y) = Color(0.0f);
  if (pass.images.cost) pass.images.cost->at(x, y) = Color(0.0f);
  FoundHit found = ownHit(pass, x, y, own, ray, work.counters);
  work.coveredPixels += own.shape >= 0 ? 1 : 0;
  if (pass.images.face) pass.images.face->at(x, y) = Color(static_cast<float>(face));
  if (own.shape >= 0 && !found.hit.shape) found.verdict = Verdict::Outside;
  const std::array<int, 4> beside = facesBeside(items, x, y, face);
  if (std::ranges::count(beside, face) == 4) return found;
  std::array<Item, 4> tested;
  int count = 0;
  for (const int besideFace : beside) {
    if (besideFace == face || besideFace < 0) continue;
    const Item item = items.itemOf(besideFace);
    const auto end = tested.begin() + count;
    if (item == own || std::find(tested.begin(), end, item) != end) continue;
    tested[static_cast<std::size_t>(count++)] = item;
    if (!coversNearer(item, pass, x, y, found, work.counters)) continue;
    fallBack(found);
    work.seeds.push_back({x, y, item});
  }
  return found;
}

// From each seed outwards, while the item keeps covering the pixels it
// reaches: the true outline beyond the polygons. Seldom more than a pixel
// or two, so done on one thread, once every pixel is shaded: a pixel it
// reaches that the item buffer answered is shaded again, by a full
// primary ray. Its first shading's rays stay counted, as the work they
// were; what it was counted as is taken back.
void HybridGroup::followOutlines(GroupPass& pass, PassWork& work) {
  HybridCounters outlines;
  std::vector<glm::ivec2> shadedAgain;
  std::set<std::tuple<int, int, Item>> tested;
  for (const Seed& seed : work.seeds) tested.insert({seed.x, seed.y, seed.item});
  std::deque<Seed> pending(work.seeds.begin(), work.seeds.end());
  while (!pending.empty()) {
    const Seed seed = pending.front();
    pending.pop_front();
    forEachNeighbour(seed.x, seed.y, [&](int x, int y) {
      if (itemAt(pass, x, y) == seed.item || !tested.insert({x, y, seed.item}).second) return;
      FoundHit found = ownHit(pass, x, y, itemAt(pass, x, y), rayAt(pass, x, y), outlines);
      if (!coversNearer(seed.item, pass, x, y, found, outlines)) return;
      pending.push_back({x, y, seed.item});
      Settled& settled = settledAt(pass, x, y);
      // Already falling back, or the tree pixel, not shaded yet.
      if (!fallBack(settled) || isTreePixel(pass, x, y)) return;
      HybridCounters& counted = work.counters;
      --counted.counts[kFromItemBuffer];
      counted.counts[kSpawning] -= settled.spawnedRays;
      counted.counts[kMirrorOrGlass] -= settled.mirrorOrGlass;
      takeBackSample(pass, x, y, found);
      found.verdict = Verdict::Inside;
      shade(pass, x, y, found, outlines);
      shadedAgain.push_back({x, y});
      showShaded(pass, x, y);
    });
  }
  work.counters += outlines;
  const GroupPass& first = passes_.front();
  if (!shadedAgain.empty() && &pass == &first && first.recording.steps)
    first.recording.steps->record(
        shadedAgainStep(shadedAgain, outlines, [&](int x, int y) { return shownOf(first, x, y); }),
        std::int64_t{2} * settings_.height);
}

// Takes the sample that the pixel's shading from the item buffer added
// out of its pass's image: the same colour, shaded again as it was
// (first_hit_batch.hpp), its rays not counted twice.
void HybridGroup::takeBackSample(GroupPass& pass, int x, int y, const FoundHit& found) {
  TraceCounters uncounted;
  const Color added = shadeFromItemBuffer(found, uncounted, nullptr).color;
  pass.samples.means.at(x, y) -= added * pass.samples.weight;
}

}  // namespace rise::hybrid
