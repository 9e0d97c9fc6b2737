#!/usr/bin/env bash
# Performance benchmark (docs/PERFORMANCE.md). Not a test: it measures, it asserts nothing.
#   1. a 24-frame sequence (moving_object, 1920x1080 by default) as half beauty/motion and float
#      depth, in ZIP, PIZ and uncompressed variants;
#   2. taatool (history mode, default bracket, half ZIP/PIZ/none output as the input) on each,
#      and oiiotool doing only the I/O of the same job in one process: read the three AOVs,
#      write RGBA. Both get the same --compression name; a bare "zip" is level 1 in taatool
#      (io/exr_writer.h) and OpenEXR's level 4 in oiiotool;
#   3. peak RSS of taatool at 4K for 24 and 96 frames, each mode (the 96 reuse 8 rendered frames
#      by links);
#   4. "blender": a real render, the yardstick's fence scene rendered by Blender Cycles at
#      1920x1080, 24 frames, one multilayer ZIP file a frame as Cycles writes it (half colour,
#      float depth, float 4-channel vectors), cached in $TAA_BENCH_CACHE (default
#      ~/.cache/taa/bench; about a minute to render once, 50 s on 2026-11-26): taatool's
#      history and window modes at their defaults against oiiotool reading the same files and
#      writing RGBA;
#   5. "ksweep": the window mode on the same render for K = 1, 2, 4, 8, 12 (docs/QUALITY.md,
#      "Window K sweep"), not run by default;
#   6. "floor": issue 23's speed floor on the same render, not run by default: ROUNDS (default
#      2) rounds, one after another, of the reference the floor was set against (taatool as it
#      was when the issue was filed, commit 520be91, at its default K 4 window: 0.8 frames/s on
#      2026-11-26's machine; built once from the repository's history into
#      ~/.cache/taa/reference-520be91, so a shallow clone cannot run this part), today's K 4
#      window with every later addition off, `--window 4`, the default and `--window 0` (t's
#      own samples: what a run pays at any K), each the whole 24-frame shot; the medians, each
#      against the reference's, and the floor as this machine would have it (2 s a frame where
#      the reference took 1.25, and `--window 4` no slower than the reference).
# Uses Debian's /usr/bin/time, oiiotool (openimageio-tools) and blender. Environment: SIZE,
# FRAMES, COMPRESSIONS (default "zip piz none"), PARTS ("speed memory blender" by default; any).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_BUILD_DIR:-$root/build}"
size="${SIZE:-1920x1080}"
frames="${FRAMES:-24}"
compressions="${COMPRESSIONS:-zip piz none}"
parts="${PARTS:-speed memory blender}"
work="$build/benchmark"
mkdir -p "$work"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target taatool taa-scenegen >/dev/null
taatool="$build/bin/taatool"
scenegen="$build/bin/taa-scenegen"

# Wall seconds, peak RSS (KiB) and CPU seconds (user + system, all threads) of a command, as
# "seconds kib cpu". CPU time is the steadier figure on a shared machine: on 2 cores the best
# wall time of a fully overlapped pipeline is CPU / 2.
measure() {
  /usr/bin/time -f "%e %M %U %S" -o "$work/time.txt" "$@" >/dev/null
  awk '{ printf "%s %s %.2f\n", $1, $2, $3 + $4 }' "$work/time.txt"
}

if [[ " $parts " == *" speed "* ]]; then
  source="$work/source-$size"
  if [ ! -f "$source/beauty.$(printf %04d "$frames").exr" ]; then
    "$scenegen" --scene moving_object --frames "1-$frames" --size "$size" --layout separate \
      --truth-samples 1 --out "$source" >/dev/null
  fi

  echo "taa benchmark: $size, $frames frames, $(nproc) cores, $("$taatool" --info | grep 'GL renderer' | sed 's/ *GL renderer: *//')"
  printf "%-11s %10s %7s %9s %15s %13s %17s\n" compression "taatool s" fps "(CPU s)" \
    "oiiotool I/O s" "(CPU s)" "taatool/oiiotool"
  for compression in $compressions; do
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
    read -r taa_s taa_kib taa_cpu < <(measure "$taatool" -q "$in/beauty.####.exr" --depth "$in/depth.####.exr" \
      --motion "$in/motion.####.exr" --frames "1-$frames" --compression "$compression" \
      --mode history -o "$work/out/r.####.exr")
    read -r io_s io_kib io_cpu < <(measure oiiotool --frames "1-$frames" "$in/beauty.#.exr" \
      "$in/depth.#.exr" "$in/motion.#.exr" --chappend --chappend --ch R,G,B,A -d half \
      --compression "$compression" -o "$work/io/o.#.exr")
    awk -v c="$compression" -v t="$taa_s" -v tc="$taa_cpu" -v n="$frames" -v o="$io_s" \
      -v oc="$io_cpu" 'BEGIN { printf "%-11s %10.2f %7.2f %9.2f %15.2f %13.2f %17.2f\n", \
      c, t, n / t, tc, o, oc, t / o }'
  done
fi

if [[ " $parts " == *" memory "* ]]; then
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
    for mode in history window; do
      rm -rf "$work/out"
      read -r s kib cpu < <(measure "$taatool" -q "$linked/beauty.####.exr" \
        --depth "$linked/depth.####.exr" --motion "$linked/motion.####.exr" --frames "1-$count" \
        --mode "$mode" -o "$work/out/r.####.exr")
      echo "4K, $count frames, $mode: $s s ($cpu s CPU), peak RSS $((kib / 1024)) MiB"
    done
  done
fi

render="${TAA_BENCH_CACHE:-$HOME/.cache/taa/bench}/cycles_fence-1920x1080-1-24"
if [[ " $parts " == *" blender "* || " $parts " == *" ksweep "* || " $parts " == *" floor "* ]]; then
  if [ ! -f "$render/input.0024.exr" ] || [ ! -f "$render/camera.json" ]; then
    blender -b --factory-startup -P "$root/samples/blender/render_scene.py" -- \
      --scene cycles_fence --out "$render" --size 1920x1080 --frames 1-24 \
      --products camera,input --input-depth float >/dev/null
  fi
fi

if [[ " $parts " == *" blender "* ]]; then
  echo "Blender Cycles render (cycles_fence), 1920x1080, 24 frames, multilayer ZIP"
  printf "%-22s %8s %6s %9s %10s %16s\n" run "wall s" fps "CPU s" "peak MiB" "/ oiiotool wall"
  rm -rf "$work/io" && mkdir -p "$work/io"
  read -r io_s io_kib io_cpu < <(measure oiiotool --frames 1-24 "$render/input.#.exr" \
    --ch R=ViewLayer.Combined.R,G=ViewLayer.Combined.G,B=ViewLayer.Combined.B,A=ViewLayer.Combined.A \
    -d half --compression zip -o "$work/io/o.#.exr")
  printf "%-22s %8.2f %6.2f %9.2f %10d %16s\n" "oiiotool I/O only" "$io_s" \
    "$(awk -v s="$io_s" 'BEGIN { print 24 / s }')" "$io_cpu" "$((io_kib / 1024))" "1.00"
  for mode in history window; do
    rm -rf "$work/out"
    read -r s kib cpu < <(measure "$taatool" -q "$render/input.####.exr" --preset cycles \
      --camera-sidecar "$render/camera.json" --frames 1-24 --mode "$mode" --compression zip \
      -o "$work/out/r.####.exr")
    printf "%-22s %8.2f %6.2f %9.2f %10d %16.2f\n" "taatool --mode $mode" "$s" \
      "$(awk -v s="$s" 'BEGIN { print 24 / s }')" "$cpu" "$((kib / 1024))" \
      "$(awk -v s="$s" -v o="$io_s" 'BEGIN { print s / o }')"
  done
  # Peak memory against sequence length: the 24 frames linked to make 24 and 96 (no sidecar:
  # it covers frames 1-24; the motion is wrong where they repeat, which memory does not mind).
  for count in 24 96; do
    linked="$work/blender-$count"
    rm -rf "$linked" && mkdir -p "$linked"
    for f in $(seq 1 "$count"); do
      ln -s "$render/input.$(printf %04d $(( (f - 1) % 24 + 1 ))).exr" \
        "$linked/input.$(printf %04d "$f").exr"
    done
    for mode in history window; do
      rm -rf "$work/out"
      read -r s kib cpu < <(measure "$taatool" -q "$linked/input.####.exr" --preset cycles \
        --frames "1-$count" --mode "$mode" --compression zip -o "$work/out/r.####.exr")
      echo "taatool --mode $mode, $count frames (vectors only): $s s, peak RSS $((kib / 1024)) MiB"
    done
    rm -rf "$linked"
  done
fi
if [[ " $parts " == *" ksweep "* ]]; then
  echo "Blender Cycles render (cycles_fence), 1920x1080, 24 frames: the window mode's K"
  printf "%-4s %8s %6s %13s %10s\n" K "wall s" fps "CPU s/frame" "peak MiB"
  for k in 1 2 4 8 12; do
    rm -rf "$work/out"
    read -r s kib cpu < <(measure "$taatool" -q "$render/input.####.exr" --preset cycles \
      --camera-sidecar "$render/camera.json" --frames 1-24 --mode window --window "$k" \
      --compression zip -o "$work/out/r.####.exr")
    awk -v k="$k" -v s="$s" -v c="$cpu" -v m="$((kib / 1024))" \
      'BEGIN { printf "%-4s %8.2f %6.2f %13.2f %10d\n", k, s, 24 / s, c / 24, m }'
  done
fi
if [[ " $parts " == *" floor "* ]]; then
  rounds="${ROUNDS:-2}"
  # The build the floor was set against, from the repository's own history.
  reference_commit=520be91
  reference_dir="${TAA_REFERENCE_DIR:-$HOME/.cache/taa/reference-$reference_commit}"
  reference_taatool="$reference_dir/build/bin/taatool"
  if [ ! -x "$reference_taatool" ]; then
    if ! git -C "$root" cat-file -e "$reference_commit^{commit}" 2>/dev/null; then
      echo "benchmark.sh: floor: commit $reference_commit (the floor's reference) is not in" \
        "$root's history (a shallow clone?): fetch it, or set TAA_REFERENCE_DIR" >&2
      exit 1
    fi
    rm -rf "$reference_dir/src" && mkdir -p "$reference_dir/src"
    git -C "$root" archive "$reference_commit" | tar -x -C "$reference_dir/src"
    cmake -S "$reference_dir/src" -B "$reference_dir/build" \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
    cmake --build "$reference_dir/build" -j"$(nproc)" --target taatool >/dev/null
  fi
  bare_flags="--window 4 --window-near 0 --window-falloff 0 --window-moving 0"
  bare_flags+=" --window-region-tolerance 0 --window-thin-search 0 --window-strata off"
  bare_flags+=" --window-settle 0"
  names=(reference k4-bare window-4 default window-0)
  programs=("$reference_taatool" "$taatool" "$taatool" "$taatool" "$taatool")
  flags=("--camera-sidecar $render/camera.json --mode window" "$bare_flags" "--window 4" ""
    "--window 0")
  echo "Blender Cycles render (cycles_fence), 1920x1080, 24 frames: issue 23's floor, $rounds rounds"
  printf "%-10s %5s %8s %8s %10s\n" run round "wall s" "CPU s" "peak MiB"
  declare -A walls=()
  for round in $(seq 1 "$rounds"); do
    for i in "${!names[@]}"; do
      rm -rf "$work/out"
      # shellcheck disable=SC2086  # the flags are words
      read -r s kib cpu < <(measure "${programs[$i]}" -q "$render/input.####.exr" \
        --preset cycles --frames 1-24 --compression zip -o "$work/out/r.####.exr" ${flags[$i]})
      printf "%-10s %5d %8.2f %8.2f %10d\n" "${names[$i]}" "$round" "$s" "$cpu" "$((kib / 1024))"
      walls[${names[$i]}]+="$s "
    done
  done
  median() {
    tr ' ' '\n' | grep . | sort -g |
      awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
  }
  reference=$(echo "${walls[reference]}" | median)
  for name in "${names[@]}"; do
    m=$(echo "${walls[$name]}" | median)
    awk -v n="$name" -v m="$m" -v r="$reference" 'BEGIN {
      printf "%-10s median %7.2f s, %5.2f s a frame, %4.2fx the reference\n", n, m, m / 24, m / r }'
  done
  awk -v r="$reference" 'BEGIN {
    printf "the floor here: the default at most %.2f s a frame (1.6x the reference); --window 4 at most %.2f\n",
      1.6 * r / 24, r / 24 }'
fi
rm -rf "$work/out" "$work/io"
