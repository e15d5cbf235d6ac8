#!/usr/bin/env bash
# RISE's path tracer beside Blender's Cycles on the CPU, on the measured
# Cornell box (examples/cornell-box-measured.yaml, lit by its ceiling panel
# alone) at 512x512, both on the same threads. Path tracers are judged by
# the error they reach in a given time, not by the time of a sample count:
# each renderer's samples cost and buy different amounts. So:
#  0. a check of the units and the camera: the emitters alone, seen
#     directly, must be their emission in both (a pixel of the panel) and
#     draw the same outline;
#  1. a converged reference from each renderer, at --reference-samples, made
#     of two halves with seeds of their own, whose difference says how much
#     noise the reference still holds; the RMSE between the two references
#     must be no more than that noise: the main check that the two draw the
#     same scene (geometry, camera, units, colours);
#  2. a ladder of sample counts, each rendered by both with another seed than
#     the reference's (so that its samples are not the reference's own): the
#     wall time of the whole process, as a user waits, and the RMSE against
#     RISE's reference;
#  3. the headline: the RMSE Cycles reaches at --target-samples, and the time
#     each renderer takes to reach it, interpolated in log-log between the
#     ladder's points; the ratio RISE / Cycles, whose target is <= 1.
set -euo pipefail
shopt -s inherit_errexit

usage() {
  cat <<EOF
usage: bench/cycles/run.sh [options] [BUILD_DIR]
  BUILD_DIR               the build holding rise (default: build)
  --reference-samples N   samples a pixel of each reference, in two halves (default: 4096;
                          16384 takes about four times as long)
  --ladder "N N ..."      the sample counts timed (default: "4 8 16 32 64 128 256"); keep the
                          largest well under the reference's, whose own noise adds to the RMSE
  --target-samples N      the headline's target is the RMSE Cycles reaches at N samples, one of
                          the ladder's (default: 64)
  --runs N                runs of each ladder point by each renderer, the best time counting
                          (default: 1)
  --threads N             threads of both renderers (default: 2)
  --max-depth N           RISE's longest path (--max-depth, at most 64); Cycles gets
                          N total and diffuse bounces (default: 64)
  --out DIR               where the images, statistics and logs go (default: out/bench-cycles)
  --keep-reference        reuse the references in DIR from an earlier run with the same
                          --reference-samples, instead of rendering them again
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

reference_samples=4096 ladder="4 8 16 32 64 128 256" target_samples=64 runs=1 threads=2
max_depth=64 out=out/bench-cycles build=build keep_reference=false
declare -A value_options=([--reference-samples]=reference_samples [--ladder]=ladder
  [--target-samples]=target_samples [--runs]=runs [--threads]=threads [--max-depth]=max_depth
  [--out]=out)
declare -A flag_options=([--keep-reference]=keep_reference)
start_benchmark "$@"
require_count --reference-samples "$reference_samples" 2
require_count --runs "$runs" 1
require_count --threads "$threads" 1
require_count --max-depth "$max_depth" 1
for samples in $ladder; do require_count --ladder "$samples" 1; done
[[ " $ladder " == *" $target_samples "* ]] || die "--target-samples $target_samples is not in the ladder"
command -v blender >/dev/null || die "blender is not installed (scripts/install-deps --cycles)"

scene=examples/cornell-box-measured.yaml
width=512 height=512
# The reference's two halves; a half of an odd count is rounded up.
half=$(((reference_samples + 1) / 2))
# A copy of rise: the build folder may be rebuilt while this runs, and every
# image should come from one program.
cp "$build/rise" "$out/rise"
rise="$out/rise"

# Runs the command, its output to the log $1; prints "wall processor": its
# wall-clock seconds, and the processor seconds (user + system) of it and all
# its threads. On a machine that other work shares, the wall time grows with
# the others' load; the processor time much less (a core shared is not
# counted twice), so the table gives both.
timed() {
  local log="$1" TIMEFORMAT='%3R %3U %3S' times
  shift
  if ! times="$({ time "$@" >"$log" 2>&1; } 2>&1)"; then
    die "$1 failed; see $log"
  fi
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' <<<"$times"
}

# RISE's path tracer: $1 names the run, $2 the samples, $3 the seed, the
# rest are more options. Prints "wall processor render_seconds".
rise_run() {
  local name="$1" samples="$2" seed="$3" wall
  shift 3
  wall="$(timed "$out/$name.log" "$rise" render "$scene" -a path-tracing \
    --width "$width" --height "$height" --samples "$samples" --seed "$seed" \
    --max-depth "$max_depth" --threads "$threads" -o "$out/$name.exr" \
    --stats "$out/$name.json" "$@")"
  echo "$wall $(json_seconds "$out/$name.json" render_seconds)"
}

# Cycles' clock ("Time:MM:SS.CC", or "HH:MM:SS.CC") on the last of Blender's
# status lines in the log $1 that holds $2, in seconds.
cycles_clock() {
  grep -F "$2" "$1" | tail -n 1 | sed -n 's/.*| Time:\([0-9:.]*\) |.*/\1/p' |
    awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; printf "%.3f\n", s }'
}

# Cycles, through bench/cycles/cornell_box.py: the same arguments as
# rise_run, the rest being the script's. Prints "wall processor
# render_seconds trace_seconds": the whole process's two times,
# bpy.ops.render.render (scene sync, BVH and path tracing) and the path
# tracing alone (Cycles' clock from "Sample 0/N" to "Finished").
cycles_run() {
  local name="$1" samples="$2" seed="$3" log="$out/$1.log" wall render sync finished
  shift 3
  wall="$(timed "$log" blender -b --factory-startup -t "$threads" \
    --python bench/cycles/cornell_box.py -- --scene "$scene" --width "$width" \
    --height "$height" --samples "$samples" --seed "$seed" --threads "$threads" \
    --max-bounces "$max_depth" --output "$out/$name.exr" "$@")"
  # Blender exits 0 even when the script failed: the image tells.
  if [[ ! -s "$out/$name.exr" ]] || ! grep -q '^render_seconds ' "$log"; then
    die "Cycles did not render $name; see $log"
  fi
  render="$(sed -n 's/^render_seconds //p' "$log")"
  sync="$(cycles_clock "$log" "| Sample 0/")"
  finished="$(cycles_clock "$log" "| Finished")"
  echo "$wall $render $(awk -v a="$finished" -v b="$sync" 'BEGIN { printf "%.3f", a - b }')"
}

rmse() { python3 bench/cycles/rmse.py "$@"; }
load_average() { cut -d' ' -f1-3 /proc/loadavg; }
load_before="$(load_average)"

echo "0. units and camera: the emitters alone, 64 samples a pixel" >&2
rm -f "$out"/*.exr
cycles_run emitters-cycles 64 1 --emitter-check --rise-scene "$out/emitters.yaml" >/dev/null
scene="$out/emitters.yaml" rise_run emitters-rise 64 1 >/dev/null
emission="$(sed -n 's/^ *emission: *//p' "$out/emitters.yaml" | tr '\n' ' ')"
panel_cycles="$(rmse --brightest "$out/emitters-cycles.exr" | cut -d' ' -f1-3)"
panel_rise="$(rmse --brightest "$out/emitters-rise.exr" | cut -d' ' -f1-3)"
outline_rmse="$(rmse "$out/emitters-rise.exr" "$out/emitters-cycles.exr")"

echo "1. the references, $reference_samples samples a pixel each, in two halves of $half" >&2
reference_seconds() { awk '{ printf "%s s wall, %s s processor\n", $1, $2 }' <<<"$1"; }
declare -A reference_wall
for renderer in rise cycles; do
  for part in 1 2; do
    name="reference-$renderer-$part"
    if $keep_reference && [[ -s "$out/keep/$name-$half.exr" ]]; then
      cp "$out/keep/$name-$half.exr" "$out/$name.exr"
      reference_wall[$name]="(kept)"
      continue
    fi
    echo "   $name" >&2
    # Seeds 1001 and 1002: none of the ladder's.
    times="$("${renderer}_run" "$name" "$half" "100$part")"
    reference_wall[$name]="$(reference_seconds "$times")"
    mkdir -p "$out/keep"
    cp "$out/$name.exr" "$out/keep/$name-$half.exr"
  done
  rmse --average "$out/reference-$renderer-1.exr" "$out/reference-$renderer-2.exr" \
    "$out/reference-$renderer.exr"
done
noise_rise="$(rmse --half-difference "$out/reference-rise-1.exr" "$out/reference-rise-2.exr")"
noise_cycles="$(rmse --half-difference "$out/reference-cycles-1.exr" "$out/reference-cycles-2.exr")"
references_rmse="$(rmse "$out/reference-rise.exr" "$out/reference-cycles.exr")"
mean_rise="$(rmse --mean "$out/reference-rise.exr" | cut -d' ' -f1-3)"
mean_cycles="$(rmse --mean "$out/reference-cycles.exr" | cut -d' ' -f1-3)"
# What the references' noise alone would make of their RMSE.
expected_rmse="$(awk -v a="$noise_rise" -v b="$noise_cycles" 'BEGIN { printf "%.6f", sqrt(a * a + b * b) }')"

# The smallest value of each column of the lines on standard input.
best_of_each() {
  awk 'NF { for (i = 1; i <= NF; ++i) if (NR == 1 || $i < best[i]) best[i] = $i; n = NF }
    END { for (i = 1; i <= n; ++i) printf "%s%s", best[i], i < n ? " " : "\n" }'
}

echo "2. the ladder: $ladder samples a pixel, $runs run(s) each" >&2
declare -A rise_best cycles_best rise_error cycles_error cycles_own_error
for samples in $ladder; do
  rise_times="" cycles_times=""
  for ((run = 1; run <= runs; ++run)); do
    echo "   $samples samples, run $run" >&2
    # Turns: Cycles first in every other run, so that neither gains from the order.
    if ((run % 2 == 0)); then
      cycles_times+="$(cycles_run "cycles-$samples" "$samples" 1)"$'\n'
      rise_times+="$(rise_run "rise-$samples" "$samples" 1)"$'\n'
    else
      rise_times+="$(rise_run "rise-$samples" "$samples" 1)"$'\n'
      cycles_times+="$(cycles_run "cycles-$samples" "$samples" 1)"$'\n'
    fi
  done
  # Each time's best over the runs: the noise of a shared machine only ever adds.
  rise_best[$samples]="$(best_of_each <<<"$rise_times")"
  cycles_best[$samples]="$(best_of_each <<<"$cycles_times")"
  rise_error[$samples]="$(rmse "$out/rise-$samples.exr" "$out/reference-rise.exr")"
  cycles_error[$samples]="$(rmse "$out/cycles-$samples.exr" "$out/reference-rise.exr")"
  cycles_own_error[$samples]="$(rmse "$out/cycles-$samples.exr" "$out/reference-cycles.exr")"
done
load_after="$(load_average)"

# The time to reach an RMSE: the ladder's (seconds, RMSE) points on
# standard input, one a line, the target as $1; interpolated in log-log
# between the two points around it, extrapolated from the last two (or the
# first two) when the ladder does not reach it, which it then says.
time_to_reach() {
  python3 -c '
import math, sys
target = float(sys.argv[1])
points = [tuple(map(float, line.split())) for line in sys.stdin if line.strip()]
def between(a, b):
    (ta, ea), (tb, eb) = a, b
    f = (math.log(ea) - math.log(target)) / (math.log(ea) - math.log(eb))
    return math.exp(math.log(ta) + f * (math.log(tb) - math.log(ta)))
for a, b in zip(points, points[1:]):
    if a[1] >= target >= b[1]:
        print(f"{between(a, b):.3f}")
        break
else:
    ends = points[-2:] if target < points[-1][1] else points[:2]
    print(f"{between(*ends):.3f} (extrapolated)")' "$1"
}
points() {  # $1: rise or cycles; $2: the field of the time (1 wall, 2 processor, 3 render)
  local -n best="${1}_best" error="${1}_error"
  for samples in $ladder; do echo "$(cut -d' ' -f"$2" <<<"${best[$samples]}") ${error[$samples]}"; done
}
target_rmse="${cycles_error[$target_samples]}"
declare -A to_target
for renderer in rise cycles; do
  for field in 1 2 3; do
    to_target[$renderer-$field]="$(points "$renderer" "$field" | time_to_reach "$target_rmse")"
  done
done

echo
echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $threads threads; $(blender --version 2>/dev/null | head -n 1)"
echo "load average (1, 5, 15 min) before the runs: $load_before; after: $load_after"
echo
echo "units: the panel seen directly, emission $emission"
echo "  RISE   $panel_rise"
echo "  Cycles $panel_cycles"
echo "  RMSE of the emitters-only images (their outline): $outline_rmse"
echo
echo "references, $reference_samples samples a pixel, each in two halves of $half:"
for name in reference-rise-1 reference-rise-2 reference-cycles-1 reference-cycles-2; do
  echo "  $name: ${reference_wall[$name]}"
done
echo "  mean R G B: RISE $mean_rise; Cycles $mean_cycles"
echo "  noise left in each (RMSE of its halves / 2): RISE $noise_rise, Cycles $noise_cycles"
echo "  RMSE RISE reference / Cycles reference: $references_rmse (from their noise alone: $expected_rmse)"
echo
echo "| samples | RISE wall (s) | RISE processor (s) | RISE render (s) | RISE RMSE | Cycles wall (s) | Cycles processor (s) | Cycles render (s) | Cycles path tracing (s) | Cycles RMSE | Cycles RMSE against its own reference |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for samples in $ladder; do
  read -r rise_wall rise_cpu rise_render <<<"${rise_best[$samples]}"
  read -r cycles_wall cycles_cpu cycles_render cycles_trace <<<"${cycles_best[$samples]}"
  echo "| $samples | $rise_wall | $rise_cpu | $rise_render | ${rise_error[$samples]} |" \
    "$cycles_wall | $cycles_cpu | $cycles_render | $cycles_trace | ${cycles_error[$samples]} |" \
    "${cycles_own_error[$samples]} |"
done
echo
echo "RMSE against RISE's reference; wall: the whole process, as a user waits; processor: its user"
echo "+ system seconds, all threads; RISE render: its render_seconds; Cycles render:"
echo "bpy.ops.render.render (sync, BVH, path tracing). Each time the best of $runs run(s)."
echo
echo "| target RMSE (Cycles at $target_samples samples) | RISE (s) | Cycles (s) | RISE / Cycles | target |"
echo "|---|---|---|---|---|"
declare -A field_name=([1]="wall time" [2]="processor time" [3]="render time")
declare -A field_target=([1]="<= 1" [2]="-" [3]="-")
for field in 1 2 3; do
  rise_time="${to_target[rise-$field]}" cycles_time="${to_target[cycles-$field]}"
  echo "| $target_rmse, ${field_name[$field]} | $rise_time | $cycles_time |" \
    "$(ratio "${rise_time%% *}" "${cycles_time%% *}") | ${field_target[$field]} |"
done
echo
echo "images, statistics and logs: $out"
