// The sanitizers' options, built into every program of a sanitized build
// (-DRISE_SANITIZE=ON), so that the tests, the command and the fuzzers run
// alike without an environment to set: stop at the first finding, with a
// stack trace, and leave aside the leaks listed in lsan-suppressions.txt.
// RISE_DETECT_LEAKS is "0" for the programs that unload drivers before they
// exit (CMakeLists.txt says why).
//
// intercept_tls_get_addr=0: the sanitizers of clang 14 (fixed in LLVM 17) take a
// thread-local block of a library loaded by dlopen (Embree, Assimp) for one
// of glibc before 2.25 whenever malloc happens to place it 16 bytes past a
// page boundary, read a size and start from the two words before it, and
// LeakSanitizer then dies scanning that range at exit ("Tracer caught signal
// 11"). Without the interception those blocks are ordinary heap blocks,
// reached through the thread's vector of them, and scanned as such.
extern "C" {

const char* __asan_default_options() {
  return "detect_leaks=" RISE_DETECT_LEAKS ":abort_on_error=0:intercept_tls_get_addr=0";
}

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

const char* __lsan_default_options() {
  return "suppressions=" RISE_SANITIZER_DIR "/lsan-suppressions.txt";
}

}  // extern "C"
