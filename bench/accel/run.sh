#!/usr/bin/env bash
# The acceleration structures' benchmark: primary-ray throughput on meshes of
# 1,280 to 1,310,720 triangles and on the Stanford bunny, for each structure
# this build has; the build times of the BVH and Embree; and the BVH's rays
# per second as a fraction of Embree's. Every benchmark runs three times and
# the best counts. The tables of bench/README.md are printed at the end.
set -euo pipefail
shopt -s inherit_errexit

usage() {
  cat <<EOF
usage: bench/accel/run.sh [--filter REGEX] [--out DIR] [BUILD_DIR]
  BUILD_DIR       RISE's build directory, holding bench/rise_accel_bench (default: build)
  --filter REGEX  only the benchmarks whose names match, e.g. 'bvh|embree'
  --out DIR       where the JSON results go (default: out/bench-accel)
EOF
}

# shellcheck source=bench/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh"

filter="."
out=out/bench-accel
build=build
declare -A value_options=([--filter]=filter [--out]=out)
declare -A flag_options=()
parse_options "$@"

here="$(realpath "$(dirname "${BASH_SOURCE[0]}")")"
enter_repository
benchmark="$build/bench/rise_accel_bench"
[[ -x "$benchmark" ]] ||
  die "no $benchmark: install libbenchmark-dev (scripts/install-deps --bench) and build again"
mkdir -p "$out"

"$benchmark" --benchmark_filter="$filter" --benchmark_repetitions=3 \
  --benchmark_out="$out/results.json" --benchmark_out_format=json
echo
python3 "$here/report.py" "$out/results.json"
