#!/usr/bin/env bash
# Runs each libFuzzer target of tests/fuzz for a bounded time from its committed corpus
# (tests/fuzz/corpus/<target>) under ASan and UBSan (docs/RELIABILITY.md). Builds build-asan/ as
# scripts/sanitize.sh does when needed. A crash, leak or timeout fails the run and leaves the
# input in build-asan/fuzz/crashes/<target>/: make it a regression test in the suite that owns
# the code, and add it to the corpus.
#   FUZZ_SECONDS   seconds per target (default 60)
#   FUZZ_TARGETS   targets to run (default: all six)
#   FUZZ_JOBS      targets run side by side (default: the number of cores)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_ASAN_BUILD_DIR:-$root/build-asan}"
seconds="${FUZZ_SECONDS:-60}"
targets=(${FUZZ_TARGETS:-fuzz_frame_reader fuzz_sequence_pattern fuzz_frame_range
         fuzz_camera_sidecar fuzz_capi_parameters fuzz_farm_script})
jobs="${FUZZ_JOBS:-$(nproc)}"
bash "$root/scripts/install-deps.sh"
source "$root/scripts/sanitizers/environment.sh"
start=$SECONDS
cmake -S "$root" -B "$build" "${asan_cmake_args[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"

# One target: its own working corpus (new inputs; the committed one is only read), its crashes,
# its own TMPDIR, which must be empty again when it ends (the targets' scratch files,
# tests/fuzz/fuzz_scratch_file.h, go with the process).
run_target() {
  local target="$1" work="$build/fuzz/corpus-work/$1" crashes="$build/fuzz/crashes/$1"
  local tmp="$build/fuzz/tmp/$1"
  rm -rf "$tmp"
  mkdir -p "$work" "$crashes" "$tmp"
  # The runtime first: the fuzzers link libFuzzer ahead of it (sanitizers/environment.sh).
  if TMPDIR="$tmp" LD_PRELOAD="${asan_preload%%:*}" "$build/fuzz/$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 \
       -print_final_stats=1 -artifact_prefix="$crashes/" "$work" \
       "$root/tests/fuzz/corpus/$target" >"$build/fuzz/$target.log" 2>&1; then
    if [ -n "$(ls -A "$tmp")" ]; then
      echo "fuzz: $target FAILED: it left files in its TMPDIR: $(ls -A "$tmp" | tr '\n' ' ')"
      return 1
    fi
    echo "fuzz: $target: $(grep -E '^stat::number_of_executed_units' "$build/fuzz/$target.log" |
                           awk '{print $2}') inputs in ${seconds} s, no finding"
  else
    echo "fuzz: $target FAILED (log: $build/fuzz/$target.log; input in $crashes/)"
    tail -n 40 "$build/fuzz/$target.log"
    return 1
  fi
}

failed=0
pids=()
for target in "${targets[@]}"; do
  run_target "$target" &
  pids+=($!)
  if [ "${#pids[@]}" -ge "$jobs" ]; then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
echo "fuzz: ${#targets[@]} targets, $((SECONDS - start)) s in all"
exit "$failed"
