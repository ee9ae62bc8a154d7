#!/usr/bin/env bash
# The meshing benchmark plus the size of the same .glb compressed with Draco by glTF Transform
# (npx @gltf-transform/cli draco), installed into a temporary folder that is removed afterwards.
#   bench/mesh_draco.sh [BUILD_DIR] [SEGMENTS]
set -euo pipefail
build="${1:-build/release}"
segments="${2:-1000000}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$build/bench/bench_mesh" "$work/tree.glb" "$segments" | tee "$work/bench.txt"
triangles="$(awk '/^triangles:/ {print $2}' "$work/bench.txt")"
(cd "$work" && npm install --no-audit --no-fund --silent --prefix "$work/npm" @gltf-transform/cli@4.5.1 >/dev/null)
start=$(date +%s.%N)
if ! "$work/npm/node_modules/.bin/gltf-transform" draco "$work/tree.glb" "$work/tree.draco.glb" >"$work/draco.log" 2>&1; then
  tail -3 "$work/draco.log" >&2
  echo "draco: gltf-transform failed on this file (its WebAssembly encoder is limited to 4 GiB of memory;"
  echo "       the 1M-segment tree is beyond it: try SEGMENTS=100000 and compare bytes/triangle)"
  exit 1
fi
end=$(date +%s.%N)
raw=$(stat -c %s "$work/tree.glb")
draco=$(stat -c %s "$work/tree.draco.glb")
awk -v r="$raw" -v d="$draco" -v t="$triangles" -v s="$start" -v e="$end" 'BEGIN {
  printf "draco glb: %d bytes, %.2f bytes/triangle (%.1f%% of the plain glb), %.1f s to compress\n",
         d, d / t, 100 * d / r, e - s }'
