# Sanitizer settings shared by scripts/sanitize.sh and scripts/fuzz.sh (sourced, not run).
# abort_on_error: a finding fails the process (and so the test) instead of going unnoticed;
# detect_stack_use_after_return catches returned pointers to locals. Leaks are checked at exit,
# Mesa's own suppressed (lsan.supp) by the library that allocated them. Not fast_unwind_on_malloc=0:
# its unwinder takes libgcc's lock inside malloc, which deadlocks against llvmpipe's JIT
# registering its frames (found running the GL tests).
sanitizers="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# intercept_tls_get_addr=0: up to LLVM 16 the runtime's __tls_get_addr interceptor takes a dynamic
# TLS block that malloc placed 16 bytes into a page for a glibc 2.19 block and reads the two words
# before it as the block's bounds; LeakSanitizer's tracer then scans that made-up range and dies
# at exit ("Tracer caught signal 11", address 0x3800 in CI's run of 18b6af7, the same test on all
# three tries: the placement repeats on a machine, so it is not a flake a retry cures). Without
# the interceptor the blocks are still found: glibc mallocs them, and the thread's DTV that points
# at them is scanned (google/sanitizers issue 1322).
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# For the tests (not the build: the compiler's own leaks are not ours): the sanitizer runtime,
# for the programs that lack it (a shell the tests start), and Mesa's DRI driver, which Mesa's
# loader would unload before exit, leaving LSan unable to name the library of its leaks.
asan_preload="$(clang++-14 -print-file-name=libclang_rt.asan-x86_64.so)"
asan_preload+=":$(ls /usr/lib/*/dri/swrast_dri.so | head -n 1)"
# -O1 and line tables only: what ASan's stacks need, a sixth less compile time than -O2 -g.
asan_cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14
                 -DCMAKE_CXX_COMPILER=clang++-14 -DTAA_SANITIZE=address,undefined -DTAA_FUZZ=ON
                 "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only"
                 "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only")
