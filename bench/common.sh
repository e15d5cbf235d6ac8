# What the benchmark scripts share; sourced, not run.

die() {
  echo "run.sh: $*" >&2
  exit 1
}

# Makes the caller's BUILD_DIR and output folder absolute (they are relative
# to where the caller stands), then moves to the repository root, where the
# example scenes are.
enter_repository() {
  build="$(realpath -m "$build")"
  out="$(realpath -m "$out")"
  cd "$(dirname "${BASH_SOURCE[0]}")/.."
}
