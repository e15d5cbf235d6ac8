#!/usr/bin/env bash
# rise-mpi on three ranks (oversubscribed on a small machine) draws what rise
# draws alone, value for value: a still image cut into tiles that are not the
# ray tracer's own, and the frames of an animation. A rank killed before it
# starts fails the run, and no image is left behind.
#   mpi_test.sh RISE RISE_MPI MPIEXEC EXAMPLES
set -euo pipefail
rise=$1 rise_mpi=$2 mpiexec=$3 examples=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ranks=("$mpiexec" --oversubscribe --allow-run-as-root -np 3)
fail() {
  echo "mpi_test: $*" >&2
  exit 1
}

still=("$examples/soft-shadows.yaml" --width 61 --height 45 --samples 4 --filter tent --threads 1)
"$rise" render "${still[@]}" -o "$work/alone.exr" 2>/dev/null
"${ranks[@]}" "$rise_mpi" render "${still[@]}" --tile-size 13 -o "$work/ranks.exr"
cmp "$work/alone.exr" "$work/ranks.exr" || fail "the tiles gathered differ from the image alone"

film=("$examples/animation.yaml" --width 48 --height 36 --threads 1 --frames 0-5)
"$rise" render "${film[@]}" -o "$work/alone_%02d.png" 2>/dev/null
"${ranks[@]}" "$rise_mpi" render "${film[@]}" -o "$work/ranks_%02d.png"
for frame in 00 01 02 03 04 05; do
  cmp "$work/alone_$frame.png" "$work/ranks_$frame.png" || fail "frame $frame differs"
done
cmp -s "$work/ranks_00.png" "$work/ranks_05.png" && fail "the animation does not move"

# The rank is killed before it starts: mpiexec stops the others.
if "${ranks[@]}" bash -c '[[ $OMPI_COMM_WORLD_RANK == 2 ]] && kill -9 $$; exec "$@"' rank \
  "$rise_mpi" render "${still[@]}" -o "$work/killed.exr" >/dev/null 2>&1; then
  fail "a run with a killed rank succeeded"
fi
[[ ! -e $work/killed.exr ]] || fail "a run with a killed rank wrote its image"

# A scene that no rank can load: status 2, its message, no image.
echo "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}" > "$work/broken.yaml"
status=0
output=$("${ranks[@]}" "$rise_mpi" render "$work/broken.yaml" -o "$work/broken.png" 2>&1) ||
  status=$?
[[ $status == 2 ]] || fail "a broken scene ended with status $status, expected 2: $output"
[[ $output == *"objects"* ]] || fail "a broken scene's message does not name what is missing: $output"
[[ ! -e $work/broken.png ]] || fail "a broken scene wrote an image"
echo "mpi_test: passed"
