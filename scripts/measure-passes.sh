#!/usr/bin/env bash
# Issue 21's measurement on a real render: the every-pass shot (samples/blender/
# render_passes_shot.py: 1 spp through the add-on, truth at 512 spp unjittered, every pass on)
# rendered into a cache, resolved by taatool with its defaults, and measured by
# scripts/measure_passes.py (Debian's /usr/bin/python3). About 10 minutes on 2 cores, most of
# it the truth. Prints Markdown tables (docs/PASSES.md holds the last run's).
#   SHOT     the cache folder (default ~/.cache/taa/blender/passes-320x180)
#   FRAMES   frames measured (default 3-10; the input is rendered two frames beyond each end)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
taatool="${TAATOOL:-$root/build/bin/taatool}"
shot="${SHOT:-$HOME/.cache/taa/blender/passes-320x180}"
frames="${FRAMES:-3-10}"
first="${frames%-*}"; last="${frames#*-}"
stamp="$(cat "$root/samples/blender/render_passes_shot.py" "$root"/samples/blender/taa_scenes/*.py \
         "$root"/plugin/blender/taa_render/*.py | sha256sum | cut -c1-16) $frames"
if [ "$(cat "$shot/stamp" 2>/dev/null)" != "$stamp" ]; then
  rm -rf "$shot"
  blender -b --factory-startup -P "$root/samples/blender/render_passes_shot.py" -- \
    --out "$shot" --frames "$((first - 2))-$((last + 2))" --products input >/dev/null
  blender -b --factory-startup -P "$root/samples/blender/render_passes_shot.py" -- \
    --out "$shot" --frames "$first-$last" --products truth --truth-samples 512 | grep '^truth'
  echo "$stamp" > "$shot/stamp"
fi
rm -rf "$shot/resolved"
"$taatool" --preset cycles "$shot/input.####.exr" -o "$shot/resolved/r.####.exr" -q
/usr/bin/python3 "$root/scripts/measure_passes.py" "$shot" "$shot/resolved" "$first" "$last"
