#!/usr/bin/env bash
# Newcomer command 1: install, build, and resolve the bundled sample sequence with taatool.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TAA_BUILD_DIR:-$root/build}"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"

sample="$build/samples/moving_object"
out="$build/sample-output"
"$build/bin/taatool" --info
"$build/bin/taatool" -v "$sample/beauty.####.exr" \
  --depth "$sample/depth.####.exr" --motion "$sample/motion.####.exr" \
  -o "$out/resolved.####.exr"
echo "Resolved sample written to $out/resolved.####.exr"
