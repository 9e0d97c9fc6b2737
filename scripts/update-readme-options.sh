#!/usr/bin/env bash
# Rewrites the options table in README.md from the registry (taatool --list-options), the table
# that tests/unit/cli_options_test.cpp (CliOptions.ReadmeTableIsTheRegistry) compares against.
# Usage: bash scripts/update-readme-options.sh [build-dir]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
taatool="${1:-$root/build}/bin/taatool"
table="$(mktemp)"
trap 'rm -f "$table"' EXIT
"$taatool" --list-options > "$table"
awk -v table="$table" '
  /<!-- options:begin -->/ { print; while ((getline line < table) > 0) print line; skipping = 1; next }
  /<!-- options:end -->/   { skipping = 0 }
  !skipping { print }
' "$root/README.md" > "$root/README.md.tmp"
mv "$root/README.md.tmp" "$root/README.md"
