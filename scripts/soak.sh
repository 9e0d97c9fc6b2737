#!/usr/bin/env bash
# Soak benchmark (docs/PERFORMANCE.md, "Soak"): a long sequence at 1080p through taatool, peak RSS
# read at frame 100 and at the end. Memory must not grow with the sequence (within 5 %). Not a
# test: it measures and prints; the figures go into docs/PERFORMANCE.md with this command.
#   bash scripts/soak.sh [--mode history|window] [--frames N] [--size WxH] [taatool options...]
# --mode is passed to taatool (the window resolve, when it lands); without it taatool's default.
# 24 rendered frames are linked under N frame numbers (default 1000; the motion is wrong where
# the 24 repeat, which does not matter for memory). Outputs are deleted as they are written.
# Uses Debian's /usr/bin/python3 for the monitor (scripts/soak_monitor.py).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_BUILD_DIR:-$root/build}"
frames=1000 size=1920x1080 extra=()
while [ "$#" -gt 0 ]; do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --mode) extra+=(--mode "$2"); shift 2 ;;
    *) extra+=("$1"); shift ;;
  esac
done
work="$build/soak"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target taatool taa-scenegen >/dev/null

source="$work/source-$size"
if [ ! -f "$source/beauty.0024.exr" ]; then
  "$build/bin/taa-scenegen" --scene moving_object --frames 1-24 --size "$size" --layout separate \
    --truth-samples 1 --out "$source" >/dev/null
fi
linked="$work/linked-$size-$frames"
if [ ! -e "$linked/beauty.$(printf %04d "$frames").exr" ]; then
  rm -rf "$linked"
  mkdir -p "$linked"
  for f in $(seq 1 "$frames"); do
    for aov in beauty depth motion; do
      ln -s "$source/$aov.$(printf %04d $(( (f - 1) % 24 + 1 ))).exr" \
        "$linked/$aov.$(printf %04d "$f").exr"
    done
  done
fi
rm -rf "$work/out"
/usr/bin/python3 "$root/scripts/soak_monitor.py" --frames "$frames" --out "$work/out" -- \
  "$build/bin/taatool" -v "$linked/beauty.####.exr" --depth "$linked/depth.####.exr" \
  --motion "$linked/motion.####.exr" --frames "1-$frames" -o "$work/out/r.####.exr" \
  ${extra[@]+"${extra[@]}"}
rm -rf "$work/out"
