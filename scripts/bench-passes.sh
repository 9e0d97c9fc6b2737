#!/usr/bin/env bash
# The cost of resolving every pass (issue 21): the benchmark's 1080p Cycles render
# (scripts/benchmark.sh's cache) with every pass a Cycles render can write added to each frame
# (light, colour and data passes as copies of the beauty's and depth's values: the values do
# not change the cost, the channel count and types do; 71 channels, typed as Blender 3.4.1 writes
# them with every pass on: light and colour half, data float), resolved with the passes and with the colour alone (--aov '*=drop').
# Prints seconds, frames/s and peak RSS of each. Needs oiiotool and GNU time.
#   FRAMES   frames resolved (default 1-12)
#   STEADY=1 the steady state instead: the cached frames linked forward and back into a
#            64-frame sequence (1-10, 9-2, 1-10, ...), so that every output has a full window
#            (the colour's default reaches 16 frames each side, more than the cache holds);
#            each run resolves frames 17-24 and 17-32 and the figure is the difference over 8
#            (seconds a frame, the start-up and the first window's reads cancelled); beside it
#            the mean and the median time between the 17-32 run's frames 19-32 as they are
#            written (-v's lines, time-stamped): one run's noise moves a difference of two runs
#            far more than either; the mean is the one to quote (the intervals vary along the
#            links, and the median of 13 picked the cheap ones: docs/PERFORMANCE.md, "The ratio
#            over the whole shot"); and the CPU time a frame (user + sys, the difference of the
#            two runs); like the wall's difference it misleads for the colour alone, whose
#            17-24 run fills a ring of 16 frames ahead (docs/PERFORMANCE.md, 2026-12-04)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
taatool="${TAATOOL:-$root/build/bin/taatool}"
source_dir="${BENCH_SOURCE:-$HOME/.cache/taa/bench/cycles_fence-1920x1080-1-24}"
work="${BENCH_PASSES_DIR:-$HOME/.cache/taa/bench/cycles_fence-1920x1080-passes-typed}"
frames="${FRAMES:-1-12}"
[ -f "$source_dir/input.0001.exr" ] || { echo "no render in $source_dir: run PARTS=blender scripts/benchmark.sh first" >&2; exit 1; }
mkdir -p "$work"
L=ViewLayer
channels="$L.Combined.R,$L.Combined.G,$L.Combined.B,$L.Combined.A,$L.Depth.Z,$L.Vector.X,$L.Vector.Y,$L.Vector.Z,$L.Vector.W"
halves=()  # Blender writes light and colour passes as half ("half colour"), data as float
for c in R G B A; do halves+=(-d "$L.Combined.$c=half"); done
for pass in DiffDir DiffInd DiffCol GlossDir GlossInd GlossCol TransDir TransInd TransCol Emit Env AO Shadow; do
  for c in R G B; do channels+=",$L.$pass.$c=$L.Combined.$c"; halves+=(-d "$L.$pass.$c=half"); done
done
for c in X Y Z; do channels+=",$L.Normal.$c=$L.Combined.R,$L.Position.$c=$L.Depth.Z"; done
channels+=",$L.UV.U=$L.Combined.R,$L.UV.V=$L.Combined.G,$L.UV.A=$L.Combined.A"
channels+=",$L.Mist.Z=$L.Depth.Z,$L.IndexOB.X=$L.Combined.A"
for rank in 00 01 02; do
  for c in r g b a; do channels+=",$L.CryptoObject$rank.$c=$L.Depth.Z"; done
done
for input in "$source_dir"/input.*.exr; do
  out="$work/$(basename "$input")"
  [ -f "$out" ] || oiiotool "$input" --ch "$channels" -d float "${halves[@]}" -o "$out"
done
cp -f "$source_dir/camera.json" "$work/" 2>/dev/null || true
echo "input: $(oiiotool --info "$work/input.0001.exr" | head -1)"
run() {
  local name="$1"; shift
  rm -rf "$work/out-$name"
  local start=$SECONDS
  /usr/bin/time -f "%M" -o "$work/rss-$name" "$taatool" --preset cycles "$work/input.####.exr" \
      --frames "$frames" -o "$work/out-$name/r.####.exr" -q "$@"
  local seconds=$((SECONDS - start))
  local count; count=$(ls "$work/out-$name" | wc -l)
  echo "$name: $count frames in ${seconds} s ($(/usr/bin/python3 -c "print(round($count/$seconds,2))") frames/s), peak RSS $(( $(cat "$work/rss-$name") / 1024 )) MiB"
}
# The cached frames linked forward and back into 64 frames (0..n-1, n-2..1, 0.. as indices).
link_steady() {
  linked="$work/steady-input"
  rm -rf "$linked" && mkdir -p "$linked"
  local cached=("$work"/input.*.exr) order=() frame=1
  local count=${#cached[@]}
  while [ ${#order[@]} -lt 64 ]; do
    for ((i = 0; i < count; ++i)); do order+=("$i"); done
    for ((i = count - 2; i > 0; --i)); do order+=("$i"); done
  done
  for index in "${order[@]:0:64}"; do
    ln -s "${cached[$index]}" "$linked/input.$(printf %04d $frame).exr"
    frame=$((frame + 1))
  done
}
# Each line of stdin with the time it arrived (seconds) in front.
stamp_lines() {
  local line
  while IFS= read -r line; do printf '%s %s\n' "$EPOCHREALTIME" "$line"; done
}
steady() {
  local name="$1"; shift
  local short long rss
  for range in 17-24 17-32; do
    rm -rf "$work/out-$name"
    /usr/bin/time -f "%e %M %U %S" -o "$work/time-$name-$range" "$taatool" --preset cycles \
        "$linked/input.####.exr" --frames "$range" -o "$work/out-$name/r.####.exr" -v "$@" |
      stamp_lines > "$work/lines-$name-$range"
  done
  local short_user short_sys long_user long_sys
  read -r short _ short_user short_sys < "$work/time-$name-17-24"
  read -r long rss long_user long_sys < "$work/time-$name-17-32"
  local between
  between=$(/usr/bin/python3 - "$work/lines-$name-17-32" <<'PY'
import statistics, sys
stamps = [float(line.split()[0]) for line in open(sys.argv[1]) if line.split()[1:2] == ['frame']]
gaps = [b - a for a, b in zip(stamps[2:], stamps[3:])]
print(f"mean {sum(gaps) / len(gaps):.2f} s, median {statistics.median(gaps):.2f} s")
PY
)
  echo "$name (steady state): 17-24 ${short} s, 17-32 ${long} s:" \
      "$(/usr/bin/python3 -c "print(round(($long - $short) / 8, 2))") s a frame," \
      "between frames 19-32 ${between}," \
      "CPU (user + sys) $(/usr/bin/python3 -c "print(round(($long_user + $long_sys - $short_user - $short_sys) / 8, 2))") s a frame," \
      "peak RSS $((rss / 1024)) MiB"
}
if [ "${STEADY:-0}" = 1 ]; then
  link_steady
  steady colour-alone --aov '*=drop'
  steady every-pass
  exit 0
fi
run colour-alone --aov '*=drop'
run every-pass
