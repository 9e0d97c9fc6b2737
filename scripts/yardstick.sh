#!/usr/bin/env bash
# The quality yardstick (DESIGN.md section 7, docs/QUALITY.md): builds taa-yardstick, taatool
# and taa-scenegen into ./build (or $TAA_BUILD_DIR), generates the scenes (cached in
# build/yardstick/scenes until the generator changes), runs taatool on each and prints the table.
#
#   bash scripts/yardstick.sh                       # all scenes, all configurations, and
#                                                   # rewrite docs/QUALITY.md
#   TAA_TRUTH_SAMPLES=128 bash scripts/yardstick.sh  # the same against a 128-sample truth
#   bash scripts/yardstick.sh --scenes wires,cut --configs classic \
#        --config reinhard="--bracket taa_reinhard"  # a quick comparison, table printed only
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target taa-yardstick taatool taa-scenegen >/dev/null

args=(--work "$build/yardstick")
command="bash scripts/yardstick.sh"
if [ -n "${TAA_TRUTH_SAMPLES:-}" ]; then
  # A truth of fewer samples than the default 1024 (a machine without the long renders' cache:
  # docs/TUNING.md, "A fresh machine, a 128-sample truth"); the page says which it used.
  args+=(--blender-samples "$TAA_TRUTH_SAMPLES")
  command="TAA_TRUTH_SAMPLES=$TAA_TRUTH_SAMPLES $command"
fi
if [ "$#" -eq 0 ]; then
  # The full run is the one the page records.
  args+=(--doc "$root/docs/QUALITY.md" --command "$command")
fi
"$build/bin/taa-yardstick" "${args[@]}" "$@"
if [ "$#" -eq 0 ]; then
  # The window K sweep's time per frame is measured at 1080p (scripts/benchmark.sh's Blender
  # render), not on the yardstick's small scenes: its section is kept beside the page.
  cat "$root/docs/quality/window-k-sweep.md" >> "$root/docs/QUALITY.md"
fi
