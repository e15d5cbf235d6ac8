#!/usr/bin/env bash
# The original RISE report's Table 1, run again: its model scene (a Quake II
# model of 666 triangles among a few primitives, examples/md2.yaml) ray
# traced with and without bounding spheres, with and without 16 jittered
# samples a pixel, and beside them the BVH that has since become the
# default. Each render's "render_seconds" (building the structure and
# rendering, not loading the scene) is printed beside the report's figure.
set -euo pipefail
shopt -s inherit_errexit

readonly SCENE=examples/md2.yaml

usage() {
  cat <<EOF
usage: bench/table1/run.sh [--runs N] [--threads N] [--out DIR] [BUILD_DIR]
  BUILD_DIR     RISE's build directory, holding the rise executable (default: build)
  --runs N      render each row N times and keep the best (default: 1)
  --threads N   worker threads (default: one per core)
  --out DIR     where images, statistics and logs go (default: out/bench-table1)
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

runs=1 threads=0 out=out/bench-table1 build=build
declare -A value_options=([--runs]=runs [--threads]=threads [--out]=out) flag_options=()
start_benchmark "$@"
require_count --runs "$runs" 1
require_count --threads "$threads" 0

# Renders one row ($1: a file name, $2: the structure, then the sampling
# options) and prints its render seconds.
render() {
  local name="$1" accel="$2"
  shift 2
  local stats="$out/$name.json" log="$out/$name.log"
  if ! "$build/rise" render "$SCENE" -o "$out/$name.png" --accel "$accel" --threads "$threads" \
    --stats "$stats" "$@" >"$log" 2>&1; then
    die "RISE failed; see $log"
  fi
  json_value "$stats" render_seconds
}

# Prints the best of the runs of one row, and leaves the statistics of its
# last run in $out/$1.json.
best_of_runs() {
  local run seconds times=()
  for ((run = 1; run <= runs; ++run)); do
    seconds="$(render "$@")"
    times+=("$seconds")
    printf '  %s, run %d: %.3f s\n' "$1" "$run" "$seconds" >&2
  done
  printf '%s\n' "${times[@]}" | sort -g | head -n 1
}

readonly ANTIALIASING=(--samples 16 --pattern jittered)
# The rows: the report's wording, its seconds (- where it has none), a file
# name, the structure, and whether to anti-alias.
readonly ROWS=(
  "bounding sphere|41|spheres|spheres|no"
  "without bounding sphere|83|none|none|no"
  "anti-aliasing|834|none-aa|none|yes"
  "anti-aliasing and bounding sphere|415|spheres-aa|spheres|yes"
  "BVH|-|bvh|bvh|no"
  "anti-aliasing and BVH|-|bvh-aa|bvh|yes"
)

echo "Table 1: $SCENE, best of $runs; images and statistics in $out" >&2
lines=()
for row in "${ROWS[@]}"; do
  IFS='|' read -r label report name accel antialias <<<"$row"
  sampling=()
  [[ "$antialias" == yes ]] && sampling=("${ANTIALIASING[@]}")
  seconds="$(best_of_runs "$name" "$accel" "${sampling[@]}")"
  stats="$out/$name.json"
  lines+=("$(printf '| %-33s | %10s | %8.3f | %-7s | %9.1f | %11.1f |' "$label" "$report" \
    "$seconds" "$accel" "$(json_value "$stats" intersection_tests_per_ray)" \
    "$(json_value "$stats" nodes_visited_per_ray)")")
done

first="$out/spheres.json"
echo
printf '%s at %sx%s on %s threads (the report: one processor of 2004)\n' "$SCENE" \
  "$(json_value "$first" width)" "$(json_value "$first" height)" "$(json_value "$first" threads)"
echo
printf '| %-33s | %10s | %8s | %-7s | %9s | %11s |\n' "Table 1 row" "report (s)" "RISE (s)" \
  "--accel" "tests/ray" "volumes/ray"
printf '|%s|%s|%s|%s|%s|%s|\n' "-----------------------------------" "------------" \
  "----------" "---------" "-----------" "-------------"
printf '%s\n' "${lines[@]}"
