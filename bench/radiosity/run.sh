#!/usr/bin/env bash
# Radiosity beside the path tracer on the measured Cornell box
# (examples/cornell-box-measured.yaml, lit by its ceiling panel alone) at
# 512x512, both on the same threads, both solving the same equation for a
# room whose surfaces are all diffuse:
#  1. the path tracer's converged image, at --reference-samples: the answer
#     both are measured against (rise render --reference);
#  2. radiosity solved to --residual and drawn, timed as a user waits (the
#     whole process), its solve and its display apart (the display is what
#     a new camera costs), and its error against the reference; with its
#     form factors by rays, then by the hemicube;
#  3. the path tracer at a ladder of sample counts, each timed and measured
#     the same way; the time it takes to reach radiosity's error,
#     interpolated in log-log between the ladder's points.
# Each error is the RMSE over the image, and over the walls alone
# (bench/cycles/rmse.py --below 1: the pixels under 1 in both images, the
# lamp and the bright rim round it left out) with the relative error there.
set -euo pipefail
shopt -s inherit_errexit

usage() {
  cat <<EOF2
usage: bench/radiosity/run.sh [options] [BUILD_DIR]
  BUILD_DIR               the build holding rise (default: build)
  --reference-samples N   samples a pixel of the path tracer's reference (default: 1024)
  --ladder "N N ..."      the path tracer's sample counts timed (default: "1 4 16 64 256")
  --residual R            radiosity's residual (default: 0.01)
  --threads N             threads of both (default: 2)
  --out DIR               where the images, statistics and logs go (default: out/bench-radiosity)
EOF2
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

reference_samples=1024 ladder="1 4 16 64 256" residual=0.01 threads=2
out=out/bench-radiosity build=build
declare -A value_options=([--reference-samples]=reference_samples [--ladder]=ladder
  [--residual]=residual [--threads]=threads [--out]=out)
declare -A flag_options=()
start_benchmark "$@"
require_count --reference-samples "$reference_samples" 1
require_count --threads "$threads" 1
for samples in $ladder; do require_count --ladder "$samples" 1; done

scene=examples/cornell-box-measured.yaml
size=(--width 512 --height 512 --threads "$threads")
cp "$build/rise" "$out/rise"
rise="$out/rise"

# Runs rise render with the arguments, its statistics to $out/$1.json;
# prints the wall-clock seconds of the whole process.
timed_render() {
  local name="$1" TIMEFORMAT='%3R' wall
  shift
  if ! wall="$({ time "$rise" render "$scene" "${size[@]}" -o "$out/$name.exr" \
    --stats "$out/$name.json" "$@" >"$out/$name.log" 2>&1; } 2>&1)"; then
    die "rise render $* failed; see $out/$name.log"
  fi
  echo "$wall"
}

echo "1. the path tracer's reference, $reference_samples samples a pixel" >&2
timed_render reference -a path-tracing --samples "$reference_samples" --seed 1001 \
  --max-depth 64 >/dev/null

echo "2. radiosity to a residual of $residual" >&2
radiosity_wall="$(timed_render radiosity -a radiosity --residual "$residual" \
  --reference "$out/reference.exr")"
radiosity_error="$(json_value "$out/radiosity.json" reference_rmse 5)"
solve="$(json_seconds "$out/radiosity.json" solve_seconds)"
render="$(json_seconds "$out/radiosity.json" render_seconds)"
display="$(awk -v r="$render" -v s="$solve" 'BEGIN { printf "%.4f", r - s }')"
hemicube_wall="$(timed_render hemicube -a radiosity --residual "$residual" \
  --form-factors hemicube --reference "$out/reference.exr")"

# The RMSE, relative error and pixels left out over the walls.
walls() { python3 bench/cycles/rmse.py --below 1 "$out/$1.exr" "$out/reference.exr"; }

echo "3. the path tracer: $ladder samples a pixel" >&2
points=""
for samples in $ladder; do
  wall="$(timed_render "path-$samples" -a path-tracing --samples "$samples" --seed 1 \
    --max-depth 64 --reference "$out/reference.exr")"
  points+="$wall $(json_value "$out/path-$samples.json" reference_rmse 5) $samples $(walls "path-$samples")"$'\n'
done

# The wall time at which the path tracer's relative error over the walls
# falls to radiosity's, in log-log between the two ladder points around it.
radiosity_walls="$(walls radiosity)"
path_time="$(awk -v target="$(cut -d' ' -f2 <<<"$radiosity_walls")" 'NF {
    if (n > 0 && e[n] > target && $5 <= target) {
      f = (log(target) - log(e[n])) / (log($5) - log(e[n]))
      printf "%.3f", exp(log(t[n]) + f * (log($1) - log(t[n]))); found = 1; exit
    }
    ++n; t[n] = $1; e[n] = $5
  } END { if (!found) printf "beyond the ladder" }' <<<"$points")"

cat <<REPORT
scene: $scene, 512x512, $threads threads
radiosity: $(json_value "$out/radiosity.json" patches 0) patches, $(json_value "$out/radiosity.json" elements 0) elements, $(json_value "$out/radiosity.json" shots 0) shots to a residual of $residual
  wall (as the user waits): $radiosity_wall s; solve: $solve s; display: $display s
  RMSE against the path tracer's $reference_samples-sample reference: $radiosity_error
  over the walls (RMSE, relative error, pixels left out): $radiosity_walls
radiosity by the hemicube: $(json_value "$out/hemicube.json" hemicube_texels 0) hemicube texels, $(json_value "$out/hemicube.json" shots 0) shots
  wall: $hemicube_wall s; solve: $(json_seconds "$out/hemicube.json" solve_seconds) s; RMSE: $(json_value "$out/hemicube.json" reference_rmse 5)
  over the walls: $(walls hemicube)
path tracer (wall s, RMSE, samples; over the walls RMSE, relative error, pixels left out):
$points
the path tracer reaches radiosity's relative error over the walls in: $path_time s
REPORT
