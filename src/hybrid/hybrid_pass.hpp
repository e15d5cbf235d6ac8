// The bookkeeping of the hybrid algorithm's passes (hybrid.cpp): what each
// accumulation pass of a group keeps while its pixels are found and shaded,
// where its samples and buffers go, and the byte it keeps of each pixel.
#pragma once

#include <cstddef>

#include "core/left_unfilled.hpp"
#include "hybrid/hybrid_counters.hpp"
#include "hybrid/item_buffer.hpp"
#include "raster/visible_surface_renderer.hpp"

namespace rise::hybrid {

// The buffers the settings want, of the image's size: the "cost" buffer and,
// with `whatWasHit`, those of what the primary rays hit, which the
// accumulation keeps of its first pass alone (visible_surface_renderer.hpp).
// All are left unfilled: pass 2 writes every pixel of each, on the workers.
// The image itself is the film's (SampleImage).
RenderResult blankResult(const RenderSettings& settings, bool whatWasHit);

// Where one accumulation pass reports: its steps (the first pass's only) and
// the ray trees of the chosen pixel, as sample `index` of the pixel.
struct PassRecording {
  StepRecorder* steps;
  StepRecorder* trees;
  int index;
};

// A pixel's primary ray and the first hit the item buffer and the item tests
// found for it, from the moment they are found to its shading a few dozen
// pixels later, and never written to memory of the image's size; and whether
// the pixel falls back, told to memory (Settled) once it is shaded.
struct FoundHit {
  Ray ray;
  Item item;  // the item buffer's
  Hit hit;    // on the item's exact surface: its shape none where the item buffer shows nothing
  Verdict verdict = Verdict::FromItemBuffer;
};

// What pass 2 settled of each pixel of a pass, for the pass's steps and for
// an outline found after the pixel was shaded, which must know what it takes
// back: a byte a pixel. Left unfilled: the workers write each pixel's, so
// that its memory is first touched on all of them and not on one.
struct Settled {
  Verdict verdict : 2 = Verdict::FromItemBuffer;
  bool mirrorOrGlass : 1 = false;  // its shading spawned reflected or refracted rays
  bool spawnedRays : 1 = false;    // ... or any rays
};
static_assert(sizeof(Settled) == 1);
using SettledPixels = UnfilledVector<Settled>;

// Where the samples of one or more passes of a group go: at each pixel their
// mean, to be added to the film. Where the film keeps each sample in its
// pixel (the box filter), all the group's passes share one, and their
// samples take the memory of one image rather than one each; otherwise each
// pass has its own, added at its offset. Left unfilled: the first of its
// passes clears each pixel as it comes to it.
struct SampleImage {
  Image means;
  int passes;
  float weight;  // of each sample: 1 / passes
};

// The pass's buffers, filled pixel by pixel.
struct Images {
  Images(const RenderSettings& settings, bool whatWasHit)
      : result{blankResult(settings, whatWasHit)} {}
  Images(const Images&) = delete;  // the pointers are into its own result

  RenderResult result;
  Image* cost = result.buffer("cost");  // or none, where not wanted
  // None but in the first pass, and there only those wanted.
  Image* depth = result.buffer("depth");
  Image* normal = result.buffer("normal");
  Image* face = result.buffer("face");
};

// One pass of a group: where its rays go, where it reports, what pass 2
// settled of each pixel, where its samples go and the buffers its shading
// fills.
struct GroupPass {
  GroupPass(const AccumulationPass& pass, const PassRecording& recording, SettledPixels& settled,
            SampleImage& samples, bool clearsSamples, const RenderSettings& settings)
      : pass(pass),
        recording(recording),
        settled(settled),
        samples(samples),
        clearsSamples(clearsSamples),
        images(settings, recording.index == 0) {
    settled.resize(static_cast<std::size_t>(settings.width) * settings.height);
  }

  const AccumulationPass& pass;
  const PassRecording recording;
  SettledPixels& settled;  // the render's, kept from group to group
  SampleImage& samples;
  const bool clearsSamples;  // the first of the passes that share them
  Images images;
  const ItemBuffer* items = nullptr;  // once pass 1 has filled it
};

}  // namespace rise::hybrid
