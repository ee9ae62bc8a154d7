#!/usr/bin/env bash
# Renders a preview of every bundled example to docs/images/<name>.png (the pictures the README
# shows) and checks that each grows into a .glb the glTF-Validator accepts.
#   scripts/render-previews.sh [RAMUS] [SIZE]
set -euo pipefail
ramus="${1:-build/release/ramus}"
size="${2:-900x600}"
mkdir -p docs/images
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for f in examples/*/*.ramus; do
  name="$(basename "$f" .ramus)"
  if "$ramus" --quiet preview "$f" -o "docs/images/$name.png" --size "$size" 2>"$work/err" &&
     "$ramus" --quiet build "$f" -o "$work/$name.glb" 2>>"$work/err"; then
    echo "docs/images/$name.png"
  elif grep -q "no geometry" "$work/err"; then
    echo "skipped $f: its turtle draws nothing (not a plant)"
  else
    cat "$work/err" >&2
    echo "FAILED: $f" >&2
    status=1
  fi
done
if [ -d tools/node_modules/gltf-validator ] && ls "$work"/*.glb >/dev/null 2>&1; then
  node tests/gltf/validate.js "$work"/*.glb || status=1
fi
exit $status
