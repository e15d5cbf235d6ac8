#!/usr/bin/env bash
# What a user waits for, against the renderers they would use instead: each
# row runs RISE and a peer on the same input, in one run of this script, on
# the same threads, and prints the two times and their ratio.
#  1. Whitted's ray tracer on the spheres scene (examples/spheres.yaml,
#     bench/spheres/spheres.pov), 800x600, one sample a pixel and then 16
#     jittered: the whole `rise render` process (loading, building, tracing,
#     writing the PNG) against POV-Ray 3.7's parsing, bounding and tracing
#     as its statistics give them.
#  2. The primary rays of a bumpy sphere of 100,000 triangles (no normals in
#     the file: RISE computes them) at 1920x1080, in a scene without lights:
#     RISE's render_seconds (BVH build, trace, shading) against Embree 3's
#     build and rtcIntersect1 loop (embree_primary.cpp).
#  3. The z-buffer and the scanline, Gouraud, over 1,000,000 triangles at
#     1920x1080: RISE's render_seconds against llvmpipe's frame
#     (bench/raster/osmesa_gouraud.cpp).
# Each is run --runs times, interleaved, and the best counts: the noise of a
# shared machine only ever adds time. With --baseline, another build of RISE
# takes its turn beside it in every run, so that a change is judged against
# the same peers' times, and a second table gives its rows.
set -euo pipefail
shopt -s inherit_errexit

usage() {
  cat <<EOF
usage: bench/end-to-end/run.sh [--runs N] [--threads N] [--out DIR] [--baseline DIR] [BUILD_DIR]
  BUILD_DIR     a Release build with link-time optimisation, holding rise and the peers'
                programs bench/rise_embree_primary_bench and bench/rise_osmesa_bench
                (default: build-release, made by cmake -B build-release)
  --runs N      runs of each renderer, the best counting (default: 3)
  --threads N   threads of every renderer (default: 2)
  --out DIR     where the meshes, scenes, images, statistics and logs go
                (default: out/bench-end-to-end)
  --baseline DIR
                another build (before a change), whose RISE runs beside BUILD_DIR's in
                every run; its rows are printed in a table of their own
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

runs=3 threads=2 out=out/bench-end-to-end build=build-release baseline=""
declare -A value_options=([--runs]=runs [--threads]=threads [--out]=out [--baseline]=baseline)
declare -A flag_options=()
parse_options "$@"
require_count --runs "$runs" 1
require_count --threads "$threads" 1

enter_repository
[[ -z "$baseline" ]] || baseline="$(realpath -m "$baseline")"
rise="$build/rise"
embree="$build/bench/rise_embree_primary_bench"
osmesa="$build/bench/rise_osmesa_bench"
[[ -x "$rise" ]] || die "no RISE executable at $rise (cmake -B build-release, or pass BUILD_DIR)"
[[ -x "$embree" ]] || die "no $embree (scripts/install-deps --bench, then build again)"
[[ -x "$osmesa" ]] || die "no $osmesa (scripts/install-deps --bench, then build again)"
[[ -z "$baseline" || -x "$baseline/rise" ]] || die "no RISE executable at $baseline/rise"
command -v povray >/dev/null || die "povray is not installed (scripts/install-deps --bench)"
grep -q '^CMAKE_INTERPROCEDURAL_OPTIMIZATION:.*=OFF' "$build/CMakeCache.txt" 2>/dev/null &&
  echo "warning: $build is built without link-time optimisation" >&2
mkdir -p "$out"

# POV-Ray on the spheres at 800x600 ($1 names the run, the rest are its
# anti-aliasing options): the seconds its own statistics give its parsing,
# bounding and tracing. Its whole process less its start-up would move by a
# tenth of a second from run to run, as much as the 1-sample render itself:
# its front end sleeps in steps of 10 to 100 ms (0.67 to 0.77 s on one empty
# pixel). Its own times leave out only its start-up and the writing of its
# image, which RISE's wall time counts for RISE.
povray_run() {
  local name="$1" log="$out/$1.log" parse bounding trace
  shift
  povray +Ibench/spheres/spheres.pov +O"$out/$name.png" +FN File_Gamma=sRGB +WT"$threads" -D \
    +W800 +H600 "$@" >"$log" 2>&1 || die "POV-Ray failed; see $log"
  parse="$(povray_seconds "$log" Parse)"
  bounding="$(povray_seconds "$log" Bounding)"
  trace="$(povray_seconds "$log" Trace)"
  awk -v parse="$parse" -v bounding="$bounding" -v trace="$trace" \
    'BEGIN { printf "%.3f\n", parse + bounding + trace }'
}

# The 100,000-triangle mesh without normals (made once) in a scene without
# lights, and the million-triangle one of the raster benchmark.
make_mesh_once "$out/sphere-100k.ply" --segments 250 --rings 201 --no-normals
mesh_scene sphere-100k "[]" >"$out/primary.yaml"
million_triangle_scene

rows=(spheres spheres-aa primary z-buffer scanline)
declare -A rise_times baseline_times peer_times
for row in "${rows[@]}"; do
  rise_times[$row]=""
  baseline_times[$row]=""
  peer_times[$row]=""
done
# Times a row's render (its name, then the options of `rise render`) by RISE
# and, when there is one, by the baseline, into rise_time and baseline_time
# ("wall render_seconds"). The two take turns going first, run by run, so
# that neither gains from the order (a warm cache, a processor's clock
# already raised). Each time is taken into a variable first: a failure
# inside $(...) given as an argument would go unnoticed.
render_row() {
  baseline_time=""
  if [[ -n "$baseline" ]] && ((run % 2 == 0)); then
    baseline_time="$(timed_render "$baseline/rise" "$1-baseline" "${@:2}")"
    rise_time="$(timed_render "$rise" "$@")"
    return
  fi
  rise_time="$(timed_render "$rise" "$@")"
  [[ -z "$baseline" ]] || baseline_time="$(timed_render "$baseline/rise" "$1-baseline" "${@:2}")"
}
# Appends a run's times (RISE's, the baseline's, the peer's) to a row.
record() {
  rise_times[$1]+="$rise_time"$'\n'
  baseline_times[$1]+="$baseline_time"$'\n'
  peer_times[$1]+="$2"$'\n'
}
# One run of every row.
run_rows() {
  local rise_time baseline_time peer_time llvmpipe algorithm
  render_row spheres examples/spheres.yaml --width 800 --height 600
  peer_time="$(povray_run povray-spheres -A)"
  record spheres "$peer_time"
  render_row spheres-aa examples/spheres.yaml --width 800 --height 600 --samples 16 \
    --pattern jittered
  peer_time="$(povray_run povray-spheres-aa +A0.0 +AM1 +R4 +J)"
  record spheres-aa "$peer_time"
  render_row primary "$out/primary.yaml"
  peer_time="$("$embree" "$out/sphere-100k.ply" 1920 1080 "$threads" 1 \
    "$out/embree-primary.ppm" | sed -n 's/^best_seconds //p')"
  record primary "$peer_time"
  llvmpipe="$(LP_NUM_THREADS="$threads" "$osmesa" "$out/bumpy-sphere.ply" 1920 1080 1 \
    "$out/million-llvmpipe.ppm" | sed -n 's/^best_seconds //p')"
  for algorithm in z-buffer scanline; do
    render_row "million-$algorithm" "$out/million.yaml" -a "$algorithm" --shading gouraud \
      --encoding linear
    record "$algorithm" "$llvmpipe"
  done
}
# How busy the machine was: a run is quiet when nothing else took the cores.
load_average() { cut -d' ' -f1-3 /proc/loadavg; }
load_before="$(load_average)"
for ((run = 1; run <= runs; ++run)); do
  echo "run $run of $runs" >&2
  run_rows
done
load_after="$(load_average)"

# The best of a row's runs: RISE's or the baseline's (the array $1) wall time
# (field 3 = 1) or render_seconds (2), the peer's.
best_rise() {
  local -n times="$1"
  cut -d' ' -f"$3" <<<"${times[$2]}" | grep . | smallest
}
# The peer's best time.
best_peer() {
  grep . <<<"${peer_times[$1]}" | smallest | awk '{ printf "%.3f\n", $1 }'
}

declare -A work=(
  [spheres]="Whitted, 11 spheres + checker plane, 800x600, 1 spp"
  [spheres-aa]="same, 16 jittered spp"
  [primary]="primary rays, 100k-triangle mesh, 1920x1080"
  [z-buffer]="z-buffer, Gouraud, 1M triangles, 1920x1080"
  [scanline]="scanline, same"
)
declare -A peer=(
  [spheres]="POV-Ray, parse + trace" [spheres-aa]="POV-Ray +A0.0 +AM1 +R4 +J, same"
  [primary]="Embree 3 build + rtcIntersect1" [z-buffer]="llvmpipe frame" [scanline]="llvmpipe frame"
)
# What the ratio compares, as the issue's table does, and its target.
declare -A ratio_of=(
  [spheres]="RISE wall / peer" [spheres-aa]="RISE wall / peer" [primary]="peer / RISE render"
  [z-buffer]="RISE render / peer" [scanline]="RISE render / peer"
)
declare -A target=([spheres]="<= 0.5" [spheres-aa]="<= 0.35" [primary]=">= 0.5"
  [z-buffer]="<= 1.5" [scanline]="<= 2.0")

# The table of RISE's rows, or the baseline's ($1: the array of their times).
print_table() {
  local row wall render peer_seconds value
  printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "work" "RISE wall (s)" "RISE render (s)" \
    "peer" "peer (s)" "ratio" "ratio is" "target"
  echo "|---|---|---|---|---|---|---|---|"
  for row in "${rows[@]}"; do
    wall="$(best_rise "$1" "$row" 1)"
    render="$(best_rise "$1" "$row" 2)"
    peer_seconds="$(best_peer "$row")"
    case "$row" in
      spheres*) value="$(ratio "$wall" "$peer_seconds")" ;;
      primary) value="$(ratio "$peer_seconds" "$render")" ;;
      *) value="$(ratio "$render" "$peer_seconds")" ;;
    esac
    printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "${work[$row]}" "$wall" "$render" \
      "${peer[$row]}" "$peer_seconds" "$value" "${ratio_of[$row]}" "${target[$row]}"
  done
}

echo
echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $threads threads, best of $runs"
echo "load average (1, 5, 15 min) before the runs: $load_before; after: $load_after"
if [[ -n "$baseline" ]]; then
  echo
  echo "baseline, $baseline:"
  print_table baseline_times
  echo
  echo "$build:"
fi
print_table rise_times
echo
echo "images: $out/*.png, $out/embree-primary.ppm, $out/million-llvmpipe.ppm"
