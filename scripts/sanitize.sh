#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (docs/RELIABILITY.md):
# clang, in build-asan/ (or $TAA_ASAN_BUILD_DIR), the build scripts/fuzz.sh reuses for its
# targets. Any finding in taa's code fails it; only Mesa's own leaks are suppressed
# (scripts/sanitizers/lsan.supp).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_ASAN_BUILD_DIR:-$root/build-asan}"
bash "$root/scripts/install-deps.sh"
source "$root/scripts/sanitizers/environment.sh"
start=$SECONDS
# The tests' own discovery runs them at build time, so the settings apply to the build too.
cmake -S "$root" -B "$build" "${asan_cmake_args[@]}"
cmake --build "$build" -j"$(nproc)"
echo "sanitize: built in $((SECONDS - start)) s"
cd "$build"
# Left to the plain suite (scripts/test.sh): the Blender tests, whose Blender, a program not
# ours, would run with the preloaded runtime and fail on its embedded Python's leaks at exit;
# and the install test, which asserts that release binaries carry no run path (this build's
# carry the sanitizer runtime's).
LD_PRELOAD="$asan_preload" ctest --output-on-failure -j"$(nproc)" -LE '^(blender|install)$'
echo "sanitize: suite passed under ASan + UBSan, $((SECONDS - start)) s in all"
