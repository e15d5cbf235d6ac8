# shellcheck shell=bash
# What the benchmark scripts share; sourced, not run.

die() {
  echo "run.sh: $*" >&2
  exit 1
}

# Reads the command line into the caller's variables: each option of the
# associative array value_options (option -> variable) takes the next word as
# its value, each of flag_options sets its variable to true, and a word that is
# not an option is the build directory. The caller defines usage().
parse_options() {
  while (($# > 0)); do
    if [[ -v "value_options[$1]" ]]; then
      (($# >= 2)) || die "$1 needs a value"
      printf -v "${value_options[$1]}" '%s' "$2"
      shift
    elif [[ -v "flag_options[$1]" ]]; then
      printf -v "${flag_options[$1]}" '%s' true
    else
      case "$1" in
        -h | --help)
          usage
          exit 0
          ;;
        -*) die "unknown option $1 (see --help)" ;;
        *) build="$1" ;;
      esac
    fi
    shift
  done
}

# Dies unless the option's value is a count, at least `minimum` (0 or 1).
require_count() {
  local option="$1" value="$2" minimum="$3"
  if ! [[ "$value" =~ ^[0-9]+$ ]] || ((value < minimum)); then
    die "$option takes a count of at least $minimum, not '$value'"
  fi
}

# Makes the caller's BUILD_DIR (when it has one) and output folder absolute (they are relative
# to where the caller stands), then moves to the repository root, where the
# example scenes are.
enter_repository() {
  [[ -z "$build" ]] || build="$(realpath -m "$build")"
  out="$(realpath -m "$out")"
  cd "$(dirname "${BASH_SOURCE[0]}")/.." || die "cannot enter the repository"
}

# What every benchmark does first: reads the command line (parse_options),
# enters the repository, dies unless RISE is built in $build, and makes the
# output folder.
start_benchmark() {
  parse_options "$@"
  enter_repository
  [[ -x "$build/rise" ]] || die "no RISE executable at $build/rise (build it, or pass BUILD_DIR)"
  mkdir -p "$out"
}

# Prints the value under `key` in the JSON file $1: as it is, or a number
# with $3 decimals.
json_value() {
  python3 -c 'import json, sys
value = json.load(open(sys.argv[1]))[sys.argv[2]]
print(value if sys.argv[3] == "" else "%.*f" % (int(sys.argv[3]), value))' \
    "$1" "$2" "${3-}" 2>/dev/null || die "no $2 in $1"
}

# Prints the number under `key` in the JSON file, to the millisecond.
json_seconds() { json_value "$1" "$2" 3; }

# The smallest of the numbers on standard input.
smallest() { sort -g | head -n 1; }

# a / b to two decimals, or "-" when b is not a positive number.
ratio() {
  awk -v a="$1" -v b="$2" 'BEGIN { if (b != "-" && b > 0) printf "%.2f", a / b; else print "-" }'
}

# Runs the command, its output to the log $1; prints its wall-clock seconds.
wall_seconds() {
  local log="$1" start end
  shift
  start="$(date +%s%N)"
  "$@" >"$log" 2>&1 || die "$1 failed; see $log"
  end="$(date +%s%N)"
  awk -v ns="$((end - start))" 'BEGIN { printf "%.3f\n", ns / 1e9 }'
}

# The seconds POV-Ray's statistics (its log, $1) give a stage ($2: Parse,
# Bounding, Trace): the number in parentheses on the line "$2 Time:".
povray_seconds() {
  local seconds
  seconds="$(sed -n "s/.*$2 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$1")"
  [[ -n "$seconds" ]] || die "no '$2 Time' in POV-Ray's statistics; see $1"
  echo "$seconds"
}

# Renders with the rise executable $1 into $out/$2.png on $threads threads,
# the rest being rise's arguments; prints "wall render_seconds".
# shellcheck disable=SC2154 # threads is the caller's, as out is.
timed_render() {
  local rise="$1" name="$2" wall
  shift 2
  wall="$(wall_seconds "$out/$name.log" "$rise" render -o "$out/$name.png" --threads "$threads" \
    --stats "$out/$name.json" "$@")"
  echo "$wall $(json_seconds "$out/$name.json" render_seconds)"
}

# Makes the mesh of bench/raster/make_mesh.py (its options after the file)
# unless the file is there.
make_mesh_once() {
  [[ -f "$1" ]] || python3 bench/raster/make_mesh.py "$@" >&2
}

# A 1920x1080 scene of the mesh $out/$1.ply, from the camera, and with the
# material, of the Embree and OSMesa programs, under the lights $2 (a YAML list).
mesh_scene() {
  local name="$1" lights="$2"
  cat <<YAML
image: {width: 1920, height: 1080, background: [0.05, 0.05, 0.1]}
camera: {position: [0.6, 0.9, -2.6], look_at: [0, 0, 0], up: [0, 1, 0], fov: 45}
ambient: [0.1, 0.1, 0.1]
lights: $lights
materials:
  clay: {color: [0.8, 0.55, 0.35], ka: 1.0, kd: 0.8, ks: 0.3, n: 20}
objects:
  - mesh: {file: $name.ply, material: clay}
YAML
}

# The raster benchmark's million triangles under one point light, as
# raster/osmesa_gouraud.cpp sees them: makes $out/bumpy-sphere.ply once and
# writes $out/million.yaml.
million_triangle_scene() {
  make_mesh_once "$out/bumpy-sphere.ply"
  local light="{point: {position: [-3, 4, -4], color: [1, 1, 1]}}"
  mesh_scene bumpy-sphere "[$light]" >"$out/million.yaml"
}
