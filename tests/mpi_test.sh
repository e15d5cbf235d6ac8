#!/usr/bin/env bash
# rise-mpi on three ranks (oversubscribed on a small machine) draws what rise
# draws alone, value for value: a still image cut into tiles that are not the
# ray tracer's own, and the frames of an animation; the buffers and the
# counters of --aov and --stats; and the folder of `rise compare`, the times
# aside. A rank killed before it starts fails the run, and no file is left
# behind.
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

# The counters of two --stats files, as "name value" lines: the times aside,
# and the BVH's subtrees, which each rank builds as its own rays reach them.
counters() {
  python3 -c 'import json, re, sys
for name, value in json.load(open(sys.argv[1])).items():
    if not re.search(r"seconds?$|^bvh_subtrees_", name): print(name, value)' "$1"
}

# The ray tracer renders a tile's own pixels: with a box filter and tiles of
# whole ray tracer's tiles, the rays of the tiles add up to those of the image.
traced=("$examples/soft-shadows.yaml" --width 64 --height 48 --samples 2 --filter box --threads 1
  --aov "depth,normal,cost")
"$rise" render "${traced[@]}" -o "$work/traced_alone.exr" --stats "$work/traced_alone.json" \
  2>/dev/null
"${ranks[@]}" "$rise_mpi" render "${traced[@]}" --tile-size 32 -o "$work/traced_ranks.exr" \
  --stats "$work/traced_ranks.json" 2>/dev/null
for buffer in "" .depth .normal .cost; do
  cmp "$work/traced_alone$buffer.exr" "$work/traced_ranks$buffer.exr" ||
    fail "the ray tracer's traced_ranks$buffer.exr differs from the one rendered alone"
done
[[ $(counters "$work/traced_ranks.json") == "$(counters "$work/traced_alone.json")" ]] ||
  fail "the ray tracer's counters differ: $(diff <(counters "$work/traced_alone.json") \
    <(counters "$work/traced_ranks.json"))"
grep -q '"primary_rays": 6144' "$work/traced_ranks.json" ||
  fail "the tiles' primary rays do not add up to 64 x 48 x 2"

# The z-buffer draws the whole frame for each tile: its counters are the frame's.
drawn=("$examples/classic.yaml" --width 50 --height 38 --threads 1 -a z-buffer --aov "depth,face")
"$rise" render "${drawn[@]}" -o "$work/drawn_alone.png" --stats "$work/drawn_alone.json" 2>/dev/null
"${ranks[@]}" "$rise_mpi" render "${drawn[@]}" --tile-size 13 -o "$work/drawn_ranks.png" \
  --stats "$work/drawn_ranks.json" 2>/dev/null
for buffer in "" .depth .face; do
  cmp "$work/drawn_alone$buffer.png" "$work/drawn_ranks$buffer.png" ||
    fail "the z-buffer's drawn_ranks$buffer.png differs from the one rendered alone"
done
[[ $(counters "$work/drawn_ranks.json") == "$(counters "$work/drawn_alone.json")" ]] ||
  fail "the z-buffer's counters differ"

# rise compare, the algorithms shared among the ranks: the same images and
# the same table but for the times.
table() {
  python3 -c 'import csv, re, sys
for row in csv.DictReader(open(sys.argv[1])):
    print({name: value for name, value in row.items()
           if not re.search(r"seconds?$|^speedup_over_", name)})' "$1"
}
compared=("$examples/classic.yaml" --width 40 --height 30 --threads 1)
"$rise" compare "${compared[@]}" -o "$work/compare_alone" 2>/dev/null
"${ranks[@]}" "$rise_mpi" compare "${compared[@]}" -o "$work/compare_ranks" 2>/dev/null
for image in "$work"/compare_alone/*.png; do
  cmp "$image" "$work/compare_ranks/${image##*/}" || fail "compare: ${image##*/} differs"
done
[[ $(ls "$work/compare_alone") == "$(ls "$work/compare_ranks")" ]] ||
  fail "compare: the folders hold other files"
[[ $(table "$work/compare_ranks/results.csv") == "$(table "$work/compare_alone/results.csv")" ]] ||
  fail "compare: the counters of results.csv differ"
[[ $(wc -l < "$work/compare_ranks/results.csv") -ge 7 ]] ||
  fail "compare: results.csv has not every algorithm"

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
if "${ranks[@]}" bash -c '[[ $OMPI_COMM_WORLD_RANK == 2 ]] && kill -9 $$; exec "$@"' rank \
  "$rise_mpi" compare "${compared[@]}" -o "$work/killed" >/dev/null 2>&1; then
  fail "a comparison with a killed rank succeeded"
fi
[[ ! -e $work/killed ]] || fail "a comparison with a killed rank wrote files"

# A scene that no rank can load: status 2, its message, no image.
echo "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}" > "$work/broken.yaml"
status=0
output=$("${ranks[@]}" "$rise_mpi" render "$work/broken.yaml" -o "$work/broken.png" 2>&1) ||
  status=$?
[[ $status == 2 ]] || fail "a broken scene ended with status $status, expected 2: $output"
[[ $output == *"objects"* ]] || fail "a broken scene's message does not name what is missing: $output"
[[ ! -e $work/broken.png ]] || fail "a broken scene wrote an image"
status=0
"${ranks[@]}" "$rise_mpi" render "${drawn[@]}" --shadows map --aov shadow-map \
  -o "$work/shadow.png" >/dev/null 2>&1 || status=$?
[[ $status == 2 && ! -e $work/shadow.png ]] ||
  fail "a shadow map cut into tiles was not refused (status $status)"
status=0
output=$("${ranks[@]}" "$rise_mpi" compare "$work/broken.yaml" -o "$work/broken" 2>&1) ||
  status=$?
[[ $status == 2 ]] || fail "a broken scene's comparison ended with status $status: $output"
[[ $output == *"objects"* ]] || fail "a broken comparison's message does not say why: $output"
[[ ! -e $work/broken ]] || fail "a broken scene's comparison wrote files"
echo "mpi_test: passed"
