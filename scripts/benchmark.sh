#!/usr/bin/env bash
# Performance benchmark (docs/PERFORMANCE.md). Not a test: it measures, it asserts nothing.
#   1. a 24-frame sequence (moving_object, 1920x1080 by default) as half beauty/motion and float
#      depth, in ZIP, PIZ and uncompressed variants;
#   2. taatool (default resolve and bracket, half ZIP/PIZ/none output as the input) on each,
#      and oiiotool doing only the I/O of the same job in one process: read the three AOVs,
#      write RGBA;
#   3. peak RSS of taatool at 4K for 24 and 96 frames (the 96 reuse 8 rendered frames by links).
# Uses Debian's /usr/bin/time and oiiotool (openimageio-tools). Environment: SIZE, FRAMES.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_BUILD_DIR:-$root/build}"
size="${SIZE:-1920x1080}"
frames="${FRAMES:-24}"
work="$build/benchmark"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target taatool taa-scenegen >/dev/null
taatool="$build/bin/taatool"
scenegen="$build/bin/taa-scenegen"

# Seconds and peak RSS (KiB) of a command, as "seconds kib".
measure() { /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" >/dev/null; cat "$work/time.txt"; }

source="$work/source-$size"
if [ ! -f "$source/beauty.$(printf %04d "$frames").exr" ]; then
  "$scenegen" --scene moving_object --frames "1-$frames" --size "$size" --layout separate \
    --truth-samples 1 --out "$source" >/dev/null
fi

echo "taa benchmark: $size, $frames frames, $(nproc) cores, $("$taatool" --info | grep 'GL renderer' | sed 's/ *GL renderer: *//')"
printf "%-6s %12s %8s %14s %18s\n" compression "taatool s" "fps" "oiiotool I/O s" "taatool/oiiotool"
for compression in zip piz none; do
  in="$work/$size-$compression"
  if [ ! -f "$in/motion.$(printf %04d "$frames").exr" ]; then
    mkdir -p "$in"
    oiiotool --frames "1-$frames" "$source/beauty.#.exr" -d half --compression "$compression" \
      -o "$in/beauty.#.exr"
    oiiotool --frames "1-$frames" "$source/depth.#.exr" -d float --compression "$compression" \
      -o "$in/depth.#.exr"
    oiiotool --frames "1-$frames" "$source/motion.#.exr" -d half --compression "$compression" \
      -o "$in/motion.#.exr"
  fi
  rm -rf "$work/out" "$work/io"
  mkdir -p "$work/io"  # oiiotool does not create output folders
  read -r taa_s taa_kib < <(measure "$taatool" -q "$in/beauty.####.exr" --depth "$in/depth.####.exr" \
    --motion "$in/motion.####.exr" --frames "1-$frames" --compression "$compression" \
    -o "$work/out/r.####.exr")
  read -r io_s io_kib < <(measure oiiotool --frames "1-$frames" "$in/beauty.#.exr" \
    "$in/depth.#.exr" "$in/motion.#.exr" --chappend --chappend --ch R,G,B,A -d half \
    --compression "$compression" -o "$work/io/o.#.exr")
  awk -v c="$compression" -v t="$taa_s" -v n="$frames" -v o="$io_s" \
    'BEGIN { printf "%-11s %12.2f %8.2f %14.2f %18.2f\n", c, t, n / t, o, t / o }'
done

# Peak memory must not grow with the sequence: 8 rendered 4K frames, linked to make 24 and 96.
uhd="$work/source-3840x2160"
if [ ! -f "$uhd/beauty.0008.exr" ]; then
  "$scenegen" --scene moving_object --frames 1-8 --size 3840x2160 --layout separate \
    --truth-samples 1 --out "$uhd" >/dev/null
fi
for count in 24 96; do
  linked="$work/uhd-$count"
  rm -rf "$linked" "$work/out"
  mkdir -p "$linked"
  for f in $(seq 1 "$count"); do
    for aov in beauty depth motion; do
      ln -s "$uhd/$aov.$(printf %04d $(( (f - 1) % 8 + 1 ))).exr" "$linked/$aov.$(printf %04d "$f").exr"
    done
  done
  read -r s kib < <(measure "$taatool" -q "$linked/beauty.####.exr" --depth "$linked/depth.####.exr" \
    --motion "$linked/motion.####.exr" --frames "1-$count" -o "$work/out/r.####.exr")
  echo "4K, $count frames: $s s, peak RSS $((kib / 1024)) MiB"
done
rm -rf "$work/out" "$work/io"
