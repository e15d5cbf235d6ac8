#!/usr/bin/env bash
# What the step recorder costs when nobody listens: the same renders by two
# revisions of RISE, the last one without the recorder (--before) and the
# first one with it (--after), or any other two. Each revision is checked out
# into a worktree of its own under the output folder and built there (Release,
# each revision's own defaults); then every row is rendered --runs times, the
# two builds taking turns, and the best time of each counts:
#  1. Whitted's ray tracer on examples/spheres.yaml at 800x600, one sample a
#     pixel and 16 jittered.
#  2. The z-buffer and the scanline, Gouraud, over the raster benchmark's
#     1,000,000 triangles at 1920x1080.
#  3. Depth sort and Warnock's area subdivision on examples/classic.yaml.
# Each build renders its own revision's examples (the script warns when they
# differ) and the same million triangles, made by this checkout's
# bench/raster/make_mesh.py. Both render_seconds (from --stats) and the whole
# process are timed, and the table says whether the two builds made the same
# image.
set -euo pipefail
shopt -s inherit_errexit

usage() {
  cat <<EOF
usage: bench/recorder/run.sh [--before REV] [--after REV] [--runs N] [--threads N] [--jobs N]
                             [--out DIR]
  --before REV  the revision measured first (default: 1afea8b, the last without the recorder)
  --after REV   the revision it is compared with (default: 2ef5930, the recorder's commit)
  --runs N      renders of each row by each build, the best counting (default: 3)
  --threads N   worker threads of every render (default: 2)
  --jobs N      parallel jobs of the two builds (default: 2)
  --out DIR     where the two worktrees and their builds, the mesh, images, statistics and
                logs go (default: out/bench-recorder)
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

before=1afea8b
after=2ef5930
runs=3 threads=2 jobs=2 out=out/bench-recorder build=""
declare -A value_options=([--before]=before [--after]=after [--runs]=runs [--threads]=threads
  [--jobs]=jobs [--out]=out) flag_options=()
parse_options "$@"
[[ -z "$build" ]] || die "takes no build directory: it builds --before and --after itself"
require_count --runs "$runs" 1
require_count --threads "$threads" 1
require_count --jobs "$jobs" 1
enter_repository
mkdir -p "$out"

readonly SIDES=(before after)
declare -A revision=([before]="$before" [after]="$after")

# Checks out the side's revision into $out/SIDE, a worktree made once and
# moved to the revision when it is there already.
check_out() {
  local side="$1" commit
  commit="$(git rev-parse --verify --quiet "${revision[$side]}^{commit}")" ||
    die "--$side ${revision[$side]} is not a revision of this repository"
  if [[ -e "$out/$side/.git" ]]; then
    git -C "$out/$side" checkout --quiet --detach "$commit" ||
      die "cannot move $out/$side to $commit (changes made in it?)"
  else
    git worktree add --quiet --force --detach "$out/$side" "$commit"
  fi
}

# Builds the side's rise in $out/SIDE/build, a Release build with the
# revision's own defaults (through ccache when there is one).
build_release() {
  local side="$1" launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  echo "building $side: $(git -C "$out/$side" log -1 --format='%h %s' | cut -c1-80)" >&2
  cmake -S "$out/$side" -B "$out/$side/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
    >"$out/$side-cmake.log" 2>&1 || die "cmake failed; see $out/$side-cmake.log"
  cmake --build "$out/$side/build" --target rise -j "$jobs" >"$out/$side-build.log" 2>&1 ||
    die "the build failed; see $out/$side-build.log"
}

# Warns when the examples the rows render differ between the revisions: the
# ratios would then compare different work.
compare_examples() {
  local example
  for example in examples/spheres.yaml examples/classic.yaml; do
    cmp -s "$out/before/$example" "$out/after/$example" ||
      echo "warning: $example differs between the revisions" >&2
  done
}

readonly ROWS=(spheres spheres-aa z-buffer scanline depth-sort area-subdivision)
declare -A work=(
  [spheres]="Whitted, spheres.yaml, 800x600, 1 spp"
  [spheres-aa]="same, 16 jittered spp"
  [z-buffer]="z-buffer, Gouraud, 1M triangles, 1920x1080"
  [scanline]="scanline, same"
  [depth-sort]="depth sort, classic.yaml, 640x480"
  [area-subdivision]="Warnock, same"
)

# Prints the row's scene and rise options, one a line, the side's examples
# being $1.
row_arguments() {
  local examples="$1" row="$2"
  case "$row" in
    spheres) printf '%s\n' "$examples/spheres.yaml" -a ray-tracing --width 800 --height 600 ;;
    spheres-aa)
      row_arguments "$examples" spheres
      printf '%s\n' --samples 16 --pattern jittered
      ;;
    z-buffer | scanline)
      printf '%s\n' "$out/million.yaml" -a "$row" --shading gouraud --encoding linear
      ;;
    *) printf '%s\n' "$examples/classic.yaml" -a "$row" ;;
  esac
}

declare -A times
# Renders the row with the side's build; appends "wall render_seconds" to its times.
render_row() {
  local side="$1" row="$2" arguments seconds
  mapfile -t arguments < <(row_arguments "$out/$side/examples" "$row")
  seconds="$(timed_render "$out/$side/build/rise" "$side-$row" "${arguments[@]}")"
  times[$side,$row]+="$seconds"$'\n'
}

# One run of every row by both builds, the first build of the run being $1.
run_rows() {
  local first="$1" second="$2" row
  for row in "${ROWS[@]}"; do
    render_row "$first" "$row"
    render_row "$second" "$row"
  done
}

# The best of the side's runs of the row: the whole process (field 1) or render_seconds (2).
best() { cut -d' ' -f"$3" <<<"${times[$1,$2]}" | grep . | smallest; }

# "yes" when the two builds' last images of the row are the same bytes.
same_image() {
  if cmp -s "$out/before-$1.png" "$out/after-$1.png"; then echo yes; else echo no; fi
}

# The Markdown table: for each row, render_seconds and the whole process.
print_table() {
  local row field timed old new same
  echo "| work | timed | before (s) | after (s) | after/before | same image |"
  echo "|---|---|---|---|---|---|"
  for row in "${ROWS[@]}"; do
    same="$(same_image "$row")"
    for field in 2 1; do
      timed="render_seconds"
      ((field == 1)) && timed="whole process"
      old="$(best before "$row" "$field")"
      new="$(best after "$row" "$field")"
      printf '| %s | %s | %s | %s | %s | %s |\n' "${work[$row]}" "$timed" "$old" "$new" \
        "$(ratio "$new" "$old")" "$same"
    done
  done
}

load() { uptime | sed 's/.*load average: //'; }

for side in "${SIDES[@]}"; do
  check_out "$side"
  build_release "$side"
done
compare_examples
million_triangle_scene

load_at_start="$(load)"
for ((run = 1; run <= runs; ++run)); do
  echo "run $run of $runs" >&2
  if ((run % 2 == 1)); then run_rows before after; else run_rows after before; fi
done
load_at_end="$(load)"

echo
echo "before: $(git -C "$out/before" log -1 --format='%h %s' | cut -c1-80)"
echo "after:  $(git -C "$out/after" log -1 --format='%h %s' | cut -c1-80)"
echo "$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, $threads threads, best of $runs;" \
  "load average $load_at_start at the start, $load_at_end at the end"
echo
print_table
echo
echo "images, statistics and logs: $out/{before,after}-*"
