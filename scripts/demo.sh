#!/usr/bin/env bash
# The main job on a bundled example: check it, derive it, and report where the results went.
set -euo pipefail
ramus="$1"
example="$2"
mkdir -p out
"$ramus" info
# The showcase tree as an asset and a picture.
showcase="${RAMUS_SHOWCASE:-examples/trees/broadleaf.ramus}"
name="$(basename "$showcase" .ramus)"
"$ramus" build "$showcase" -o "out/$name.glb" --lod 2
"$ramus" preview "$showcase" -o "out/$name.png"
echo "demo: wrote out/$name.glb (glTF, LOD0..LOD2) and out/$name.png (front and side view)"
