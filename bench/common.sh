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

# Makes the caller's BUILD_DIR and output folder absolute (they are relative
# to where the caller stands), then moves to the repository root, where the
# example scenes are.
enter_repository() {
  build="$(realpath -m "$build")"
  out="$(realpath -m "$out")"
  cd "$(dirname "${BASH_SOURCE[0]}")/.." || die "cannot enter the repository"
}

# Prints the number under `key` in the JSON file, to the millisecond.
json_seconds() {
  python3 -c 'import json, sys; print("%.3f" % json.load(open(sys.argv[1]))[sys.argv[2]])' \
    "$1" "$2" 2>/dev/null || die "no $2 in $1"
}

# The smallest of the numbers on standard input.
smallest() { sort -g | head -n 1; }

# a / b to two decimals, or "-" when b is not a positive number.
ratio() {
  awk -v a="$1" -v b="$2" 'BEGIN { if (b != "-" && b > 0) printf "%.2f", a / b; else print "-" }'
}
