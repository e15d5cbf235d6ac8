#!/usr/bin/env bash
# The hybrid scan-line / ray-tracing algorithm beside Whitted's ray tracer
# with the BVH, on the same scenes, with 1 and with 16 jittered samples a
# pixel: the report's model scene (examples/md2.yaml), the classic scene, a
# mesh of 1,000,000 triangles (bench/raster/make_mesh.py) over a mirror floor
# and over a matte one, and the spheres scene of the POV-Ray benchmark. For
# each, the table shows both best times; the median of their ratios run by
# run, with and without the BVH's build, and in how many runs the hybrid was
# the faster; the share of Whitted's rays that were primary rays (the work the
# item buffer can take over), the hybrid's fallback pixels and the time of
# each of its two passes. With --unlit every ray is a primary ray; with
# --accel both take another acceleration structure (those of the original
# report's day, bounding spheres or none, without the million triangles).
# shellcheck disable=SC2059 # the table's rows and header print by one format, ROW
set -euo pipefail
shopt -s inherit_errexit

usage() {
  cat <<EOF
usage: bench/hybrid/run.sh [--runs N] [--threads N] [--unlit] [--accel NAME] [--out DIR] [BUILD_DIR]
  BUILD_DIR     RISE's build directory, holding the rise executable (default: build)
  --runs N      render each row N times: the best times, the median ratios (default: 3)
  --threads N   worker threads (default: 2)
  --unlit       the scenes with their lights taken away and their mirrors and glass made
                matte: every ray a primary ray
  --accel NAME  both algorithms' acceleration structure: bvh (default), spheres, none, embree
  --out DIR     where the mesh, images, statistics and logs go (default: out/bench-hybrid)
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

runs=3 threads=2 unlit=false accel=bvh out=out/bench-hybrid build=build
declare -A value_options=([--runs]=runs [--threads]=threads [--accel]=accel [--out]=out)
declare -A flag_options=([--unlit]=unlit)
start_benchmark "$@"
require_count --runs "$runs" 1
require_count --threads "$threads" 1

make_mesh_once "$out/bumpy-sphere.ply"
cp bench/hybrid/million-mirror.yaml bench/hybrid/million-matte.yaml "$out/"

# Prints the path of the scene $1's copy in $out/unlit, lit by nothing and matte
# (bench/hybrid/unlit-scene).
unlit_copy() {
  local copy
  copy="$out/unlit/$(basename "$1")"
  mkdir -p "$out/unlit"
  bench/hybrid/unlit-scene "$1" >"$copy"
  echo "$copy"
}

# Renders once as $1 (the rest being rise's arguments) and keeps the
# statistics as $out/$1.json when its render_seconds is the best yet; and
# adds its render_seconds to $out/$1.times and to $out/$1.unbuilt the time of
# the render but the BVH's build, which both algorithms make alike and whose
# spread can outweigh their difference.
render_once() {
  local name="$1" seconds best=""
  shift
  "$build/rise" render -o "$out/$name.png" --threads "$threads" --accel "$accel" \
    --stats "$out/$name.run.json" "$@" >"$out/$name.log" 2>&1 || die "RISE failed; see $out/$name.log"
  seconds="$(json_value "$out/$name.run.json" render_seconds 4)"
  echo "$seconds" >>"$out/$name.times"
  awk -v a="$seconds" -v b="$(json_value "$out/$name.run.json" accel_build_seconds 4)" \
    'BEGIN { printf "%.4f\n", a - b }' >>"$out/$name.unbuilt"
  [[ ! -f "$out/$name.json" ]] || best="$(json_value "$out/$name.json" render_seconds 4)"
  if [[ -z "$best" ]] || awk -v a="$seconds" -v b="$best" 'BEGIN { exit !(a < b) }'; then
    mv "$out/$name.run.json" "$out/$name.json"
  else
    rm "$out/$name.run.json"
  fi
}

# Whitted's and the hybrid's renders of a row ($1 names it, the rest are
# rise's arguments), taking turns run by run, so that the load of a shared
# machine falls on both alike; the one that goes first changes from run to
# run, so that each follows itself as often as the other. (A process's
# fresh memory can cost more after one that used less: the host backs the
# difference anew.)
render_pair() {
  local name="$1" run algorithm
  local -a order=(ray-tracing hybrid)
  shift
  rm -f "$out/$name"-{ray-tracing,hybrid}.{json,times,unbuilt}
  for ((run = 1; run <= runs; ++run)); do
    for algorithm in "${order[@]}"; do render_once "$name-$algorithm" "$@" -a "$algorithm"; done
    order=("${order[1]}" "${order[0]}")
  done
}

# The median of a / b, where a and b are the numbers on the same lines of the
# files $1 and $2: the ratio of two renders run one right after the other.
median_ratio() {
  paste "$1" "$2" | awk '{ print $1 / $2 }' | sort -g |
    awk '{ r[NR] = $1 } END { printf "%.2f", NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2 }'
}

# "k/n": on how many of the n lines of $2 the number is smaller than on the
# same line of $1.
smaller_on() {
  paste "$1" "$2" | awk '{ k += $2 < $1 } END { printf "%d/%d", k, NR }'
}

# A row of the table, its columns aligned.
readonly ROW='| %-26s | %7s | %11s | %10s | %6s | %9s | %5s | %7s | %9s | %10s | %10s |'

share() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.0f%%", 100 * a / b }'; }

readonly SCENES=(
  "md2|examples/md2.yaml"
  "classic|examples/classic.yaml"
  "1M triangles, mirror floor|$out/million-mirror.yaml"
  "1M triangles, matte floor|$out/million-matte.yaml"
  "spheres|examples/spheres.yaml"
)

lighting=""
[[ "$unlit" == false ]] || lighting=", unlit"
echo "Hybrid against Whitted ($accel)$lighting, $threads threads, best of $runs; images and" \
  "statistics in $out" >&2
lines=()
for row in "${SCENES[@]}"; do
  IFS='|' read -r label scene <<<"$row"
  # Without a hierarchy, a ray that meets the mesh's bounding sphere tests all its triangles.
  [[ "$label" != 1M* || "$accel" == bvh || "$accel" == embree ]] || continue
  name="$(basename "$scene" .yaml)"
  [[ "$unlit" == false ]] || scene="$(unlit_copy "$scene")" name="unlit-$name"
  for samples in 1 16; do
    sampling=()
    ((samples > 1)) && sampling=(--samples "$samples" --pattern jittered)
    render_pair "$name-$samples" "$scene" "${sampling[@]}"
    w="$out/$name-$samples-ray-tracing.json" h="$out/$name-$samples-hybrid.json"
    whitted="$(json_value "$w" render_seconds 4)" hybrid="$(json_value "$h" render_seconds 4)"
    lines+=("$(printf "$ROW" "$label" "$samples" "$whitted" "$hybrid" \
      "$(median_ratio "${w%.json}.times" "${h%.json}.times")" \
      "$(median_ratio "${w%.json}.unbuilt" "${h%.json}.unbuilt")" \
      "$(smaller_on "${w%.json}.times" "${h%.json}.times")" \
      "$(share "$(json_value "$w" primary_rays 0)" "$(json_value "$w" rays 0)")" \
      "$(json_value "$h" fallback_pixels 0)" "$(json_value "$h" item_buffer_seconds 3)" \
      "$(json_value "$h" ray_pass_seconds 3)")")
    echo "  $label, $samples samples: Whitted $whitted s, hybrid $hybrid s" >&2
  done
done

echo
printf "$ROW\n" "scene" "samples" "Whitted (s)" "hybrid (s)" "W / h" "but build" "ahead" \
  "primary" "fallbacks" "pass 1 (s)" "pass 2 (s)"
printf '|%s|%s|%s|%s|%s|%s|%s|%s|%s|%s|%s|\n' "----------------------------" "---------" \
  "-------------" "------------" "--------" "-----------" "-------" "---------" "-----------" \
  "------------" "------------"
printf '%s\n' "${lines[@]}"
