#!/usr/bin/env bash
# The speed benchmark against POV-Ray 3.7. Both renderers trace the same
# Whitted scene (examples/spheres.yaml for RISE, bench/spheres/spheres.pov for
# POV-Ray) at 800x600 on two threads, three times each, and the best time of
# each is compared. Only the rendering is timed: RISE's "render_seconds" from
# its --stats JSON, POV-Ray's "Trace Time" from its statistics; neither counts
# start-up or scene parsing. Both images are kept for a side-by-side look.
set -euo pipefail
shopt -s inherit_errexit

readonly RUNS=3
readonly WIDTH=800
readonly HEIGHT=600
readonly THREADS=2

usage() {
  cat <<EOF
usage: bench/spheres/run.sh [--aa] [--only rise|povray] [--out DIR] [BUILD_DIR]
  BUILD_DIR      RISE's build directory, holding the rise executable (default: build)
  --aa           anti-alias both: RISE with 16 jittered samples a pixel,
                 POV-Ray with +A0.0 +AM1 +R4 +J (16 jittered samples a pixel)
  --only WHICH   time only RISE or only POV-Ray
  --out DIR      where images, statistics and logs go (default: out/bench-spheres)
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

antialias=false
only=""
out=out/bench-spheres
build=build
declare -A value_options=([--only]=only [--out]=out)
declare -A flag_options=([--aa]=antialias)
parse_options "$@"
case "$only" in
  "" | rise | povray) ;;
  *) die "--only takes rise or povray, not '$only'" ;;
esac

# Paths given by the caller are relative to where it stands; the renders run
# from the repository root, where the scene paths are.
enter_repository
mkdir -p "$out"

if $antialias; then
  suffix="-aa"
  rise_antialiasing=(--samples 16 --pattern jittered)
  povray_antialiasing=(+A0.0 +AM1 +R4 +J)
  mode="16 samples a pixel, jittered"
else
  suffix=""
  rise_antialiasing=()
  povray_antialiasing=(-A)
  mode="no anti-aliasing"
fi

# Prints the render seconds of one RISE run, to the millisecond like POV-Ray's.
time_rise() {
  local image="$out/rise$suffix.png" stats="$out/rise$suffix.json" log="$out/rise$suffix.log"
  if ! "$build/rise" render examples/spheres.yaml -o "$image" --width "$WIDTH" \
    --height "$HEIGHT" --threads "$THREADS" --stats "$stats" "${rise_antialiasing[@]}" \
    >"$log" 2>&1; then
    die "RISE failed; see $log"
  fi
  json_seconds "$stats" render_seconds
}

# Prints the trace seconds of one POV-Ray run, from the statistics it writes
# to stderr.
time_povray() {
  local image="$out/povray$suffix.png" log="$out/povray$suffix.log"
  if ! povray +Ibench/spheres/spheres.pov +O"$image" +FN File_Gamma=sRGB +W"$WIDTH" \
    +H"$HEIGHT" +WT"$THREADS" -D "${povray_antialiasing[@]}" >"$log" 2>&1; then
    die "POV-Ray failed; see $log"
  fi
  povray_seconds "$log" Trace
}

# Prints the smallest of RUNS timings made by the function named $1.
best_of_runs() {
  local run times=()
  for ((run = 1; run <= RUNS; ++run)); do
    times+=("$("$1")")
    echo "  $2 run $run: ${times[-1]} s" >&2
  done
  printf '%s\n' "${times[@]}" | smallest
}

rise_seconds="-"
povray_seconds="-"
ratio="-"
images=()
echo "spheres ${WIDTH}x${HEIGHT}, $THREADS threads, $mode, best of $RUNS" >&2
if [[ "$only" != povray ]]; then
  [[ -x "$build/rise" ]] || die "no RISE executable at $build/rise (build it, or pass BUILD_DIR)"
  rise_seconds="$(best_of_runs time_rise RISE)"
  images+=("$out/rise$suffix.png")
fi
if [[ "$only" != rise ]]; then
  command -v povray >/dev/null || die "povray is not installed (apt-get install povray)"
  povray_seconds="$(best_of_runs time_povray POV-Ray)"
  images+=("$out/povray$suffix.png")
fi
if [[ -z "$only" ]]; then
  ratio="$(ratio "$povray_seconds" "$rise_seconds")"
fi

echo
printf '| %-9s | %-12s | %-15s |\n' "RISE (s)" "POV-Ray (s)" "POV-Ray / RISE"
printf '|%s|%s|%s|\n' "-----------" "--------------" "-----------------"
printf '| %-9s | %-12s | %-15s |\n' "$rise_seconds" "$povray_seconds" "$ratio"
echo
echo "images: ${images[*]}"
