#!/usr/bin/env bash
# The visible-surface algorithms' benchmarks.
#  1. The original RISE report's model scene (examples/md2.yaml, a Quake II
#     model of 666 triangles among a few primitives) drawn by each of the
#     four algorithms, beside the 2 s the report gives for its scanline.
#  2. A mesh of 1,000,000 triangles (make_mesh.py) at 1920x1080, Gouraud
#     shaded under one point light, by RISE's z-buffer and scanline and by
#     Mesa's software OpenGL (llvmpipe, through OSMesa) from the same camera.
#     A frame is timed the same way for both: the geometry is given once
#     (RISE tessellates the scene, OpenGL fills its vertex buffers), then each
#     frame transforms, culls, clips, rasterises and shades it; the best of
#     the frames counts. RISE's whole render (tessellation included, as
#     `rise render` reports it) is shown too.
set -euo pipefail
shopt -s inherit_errexit

readonly WIDTH=1920
readonly HEIGHT=1080

usage() {
  cat <<EOF
usage: bench/raster/run.sh [--frames N] [--threads N] [--out DIR] [BUILD_DIR]
  BUILD_DIR     RISE's build directory, holding rise and bench/rise_raster_bench and, when
                libosmesa6-dev was found, bench/rise_osmesa_bench (default: build)
  --frames N    frames (and renders) of each, the best counting (default: 5)
  --threads N   worker threads of RISE and of llvmpipe (default: 2)
  --out DIR     where the mesh, images, statistics and logs go (default: out/bench-raster)
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

frames=5 threads=2 out=out/bench-raster build=build
declare -A value_options=([--frames]=frames [--threads]=threads [--out]=out) flag_options=()
start_benchmark "$@"
require_count --frames "$frames" 1
require_count --threads "$threads" 1
[[ -x "$build/bench/rise_raster_bench" ]] ||
  die "no $build/bench/rise_raster_bench (built with the benchmarks: scripts/install-deps --bench)"

# Renders a scene with `rise render` $frames times; prints the best render_seconds.
best_render() {
  local scene="$1" name="$2" run
  shift 2
  for ((run = 1; run <= frames; ++run)); do
    "$build/rise" render "$scene" -o "$out/$name.png" --threads "$threads" \
      --stats "$out/$name.json" "$@" >"$out/$name.log" 2>&1 || die "RISE failed; see $out/$name.log"
    json_seconds "$out/$name.json" render_seconds
  done | smallest
}

# The value a benchmark program prints on its line "name value".
value() { sed -n "s/^$1 //p"; }

echo "The report's model scene (examples/md2.yaml), 640x480, Gouraud, $threads threads, best of $frames:"
printf '| %-16s | %-9s | %-14s |\n' "algorithm" "RISE (s)" "the report (s)"
printf '|%s|%s|%s|\n' "------------------" "-----------" "----------------"
for algorithm in depth-sort area-subdivision z-buffer scanline; do
  report="-"
  [[ "$algorithm" == scanline ]] && report="2.0"
  printf '| %-16s | %-9s | %-14s |\n' "$algorithm" \
    "$(best_render examples/md2.yaml "md2-$algorithm" -a "$algorithm" --shading gouraud)" "$report"
done
echo

million_triangle_scene
mesh="$out/bumpy-sphere.ply"

echo "1,000,000 triangles, ${WIDTH}x${HEIGHT}, Gouraud, $threads threads, best of $frames:"
declare -A frame render
for algorithm in z-buffer scanline; do
  frame[$algorithm]="$("$build/bench/rise_raster_bench" "$out/million.yaml" "$algorithm" gouraud \
    "$threads" "$frames" | value best_seconds)"
  render[$algorithm]="$(best_render "$out/million.yaml" "million-$algorithm" -a "$algorithm" \
    --shading gouraud --encoding linear)"
done
llvmpipe="-"
if [[ -x "$build/bench/rise_osmesa_bench" ]]; then
  llvmpipe="$(LP_NUM_THREADS="$threads" "$build/bench/rise_osmesa_bench" "$mesh" "$WIDTH" \
    "$HEIGHT" "$frames" "$out/million-llvmpipe.ppm" | value best_seconds)"
else
  echo "(no bench/rise_osmesa_bench: install libosmesa6-dev and build again)" >&2
fi
printf '| %-29s | %-9s | %-16s |\n' "renderer" "frame (s)" "frame / llvmpipe"
printf '|%s|%s|%s|\n' "-------------------------------" "-----------" "------------------"
printf '| %-29s | %-9s | %-16s |\n' "llvmpipe (OSMesa)" "$llvmpipe" "1.00"
for algorithm in z-buffer scanline; do
  printf '| %-29s | %-9.3f | %-16s |\n' "RISE $algorithm" "${frame[$algorithm]}" \
    "$(ratio "${frame[$algorithm]}" "$llvmpipe")"
  printf '| %-29s | %-9s | %-16s |\n' "RISE $algorithm, whole render" "${render[$algorithm]}" \
    "$(ratio "${render[$algorithm]}" "$llvmpipe")"
done
echo
echo "images: $out/million-{z-buffer,scanline}.png (linear values), $out/million-llvmpipe.ppm"
