// The meshes and rays the acceleration benchmarks trace.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/ray.hpp"
#include "scene/shape.hpp"

namespace rise::bench {

// An icosahedron whose triangles are each split in four, `subdivisions`
// times (20 * 4^subdivisions triangles), pushed out onto a sphere and then
// made bumpy, so that its triangles face every way and its surface folds,
// as a scanned model's does.
std::unique_ptr<Shape> bumpyIcosphere(int subdivisions);

// The Stanford bunny, from examples/models.
std::unique_ptr<Shape> stanfordBunny();

// The primary rays of a width x height pinhole camera that frames the
// shape's bounds, seen from above and to one side.
std::vector<Ray> cameraRays(const Shape& shape, int width, int height);

}  // namespace rise::bench
