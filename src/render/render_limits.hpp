// The limits of a render: what RISE refuses before it starts, or stops when
// it is reached, so that no scene and no setting makes a render run for
// days or fill the memory. Each is documented in the README's Limits.
//
// Before a render, the algorithm works out what it needs from its settings
// (Renderer::needs): the memory of the film, the image and the auxiliary
// buffers (so many bytes a pixel), of each thread's samples of a pixel, and
// of the scene's primitives in the structures built from them; and, for
// those that trace rays, the most rays a sample can become where materials
// both reflect and refract (each hit then spawns two rays, down to the
// maximum depth). Those are held against the memory a render may take and
// the most rays a render may trace; the memory, what RISE may take
// (core/memory_budget.hpp).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "render/renderer.hpp"

namespace rise {

// A render that would exceed a limit; the message names the value and the
// limit, and what to do instead. The command line exits with status 2.
class RenderLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Rays at some ten million a second: a day and more.
inline constexpr double kMostRays = 1e12;
// Threads beyond the cores only wait; each takes a stack of its own.
inline constexpr int kMostThreads = 256;

// Depth sort compares pairs of polygons, as many as the square of their
// number for a scene where every polygon overlaps every other, and splits
// those it cannot order: about a minute of comparisons, and the pieces of
// some hundreds of megabytes.
inline constexpr std::uint64_t kMostDepthSortComparisons = 2'000'000'000;
inline constexpr std::uint64_t kMostDepthSortSplits = 2'000'000;

// The parts of what a render needs that every algorithm has, for the
// algorithms' Renderer::needs: the image, its buffers and whatever else the
// algorithm keeps of each pixel (`bytesPerPixel`), each thread's samples of
// a pixel, and the scene's primitives in the structures built from them. No
// rays.
RenderNeeds memoryNeeds(const Scene& scene, const RenderSettings& settings,
                        std::uint64_t bytesPerPixel);

// The most rays a render's samples become where each is Whitted's recursion:
// a path down to the maximum depth, or a tree of them where a material both
// reflects and refracts; each hit with a shadow ray a light.
double recursionRays(const Scene& scene, const RenderSettings& settings);

// Throws RenderLimitError when a render by `renderer` needs more than the
// limits allow, or asks for more than kMostThreads threads.
void checkRenderFits(const Scene& scene, const RenderSettings& settings, const Renderer& renderer);

// Throws RenderLimitError when `bytes`, memory an algorithm works out it needs
// once it knows the polygons on the screen, before it takes it, are more than
// a render may take; `what` names that memory ("the A-buffer's fragment
// lists") and `instead` says what to do ("--transparency sorted").
void checkWorkingMemoryFits(std::uint64_t bytes, const std::string& what,
                            const std::string& instead);

}  // namespace rise
