#!/usr/bin/env bash
# Newcomer command 2: install, build, and run the whole test suite through CTest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_BUILD_DIR:-$root/build}"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
cd "$build"
# Every test without a TIMEOUT of its own (the Python, shell and fixture tests) gets 1200 s:
# a hung one fails under its name rather than holding the run to CI's limit.
ctest --output-on-failure --timeout 1200 -j"$(nproc)"
