#!/usr/bin/env bash
# The main job on a bundled example: check the grammar, derive it, compile it to a glTF asset
# and draw a picture of it; then say where the results went.
set -euo pipefail
ramus="$1"
example="${2:-examples/trees/broadleaf.ramus}"
name="$(basename "$example" .ramus)"
mkdir -p out
echo "== ramus check $example"
"$ramus" check "$example"
echo "== ramus derive $example --stats"
"$ramus" derive "$example" --stats | grep -E '^(length|count F |steps|time)'
echo "== ramus build $example -o out/$name.glb --lod 2"
"$ramus" build "$example" -o "out/$name.glb" --lod 2
echo "== ramus preview $example -o out/$name.png"
"$ramus" preview "$example" -o "out/$name.png"
echo "demo: wrote out/$name.glb (glTF 2.0, LOD0..LOD2) and out/$name.png (front and side view)"
