// The sanitizers' options, built into every program of a sanitized build
// (-DRISE_SANITIZE=ON), so that the tests, the command and the fuzzers run
// alike without an environment to set: stop at the first finding, with a
// stack trace, and leave aside the leaks listed in lsan-suppressions.txt.
// RISE_DETECT_LEAKS is "0" for the programs that unload drivers before they
// exit (CMakeLists.txt says why).
extern "C" {

const char* __asan_default_options() {
  return "detect_leaks=" RISE_DETECT_LEAKS ":abort_on_error=0";
}

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

const char* __lsan_default_options() {
  return "suppressions=" RISE_SANITIZER_DIR "/lsan-suppressions.txt";
}

}  // extern "C"
