#!/usr/bin/env bash
# Sizes side by side and the runtime's time to grow and mesh (README, "The runtime grows drawable
# trees"; docs/runtime.md, "Meshes"; issue 23 point 5). For each example grammar with an lsystem
# block (or those given): the .rmb (`ramus build --target binary`, plain and with --zstd), the
# .glb of its tree (`ramus build`, LOD0), the same compressed with Draco and with meshoptimizer
# (`--compress draco|meshopt`), the tree's nodes and LOD0 triangles, and the time the runtime's
# example program (examples/runtime/grow_mesh.c) takes to grow and to mesh it on one core
# (`taskset -c 0`, the fastest of REPEAT runs, default 20). Prints a Markdown table.
#   bench/runtime_mesh_sizes.sh [BUILD_DIR] [GRAMMAR.ramus ...]
set -euo pipefail
build="${1:-build/release}"
shift || true
ramus="$build/ramus"
grow_mesh="$build/grow_mesh"
repeat="${REPEAT:-20}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

grammars=("$@")
if [ ${#grammars[@]} -eq 0 ]; then
  for f in $(find examples -name '*.ramus' | sort); do
    grep -q 'lsystem ' "$f" && grammars+=("$f")
  done
fi
size() { stat -c %s "$1"; }
# The bytes of a .glb's embedded pictures (bark base colour and normal map, leaf mask): the same
# in every tree's .glb, and what a client of the runtime fetches once beside the .rmb.
pictures() {
  python3 -c '
import json, struct, sys
b = open(sys.argv[1], "rb").read()
n = struct.unpack_from("<I", b, 12)[0]
g = json.loads(b[20:20 + n])
print(sum(g["bufferViews"][i["bufferView"]]["byteLength"] for i in g.get("images", [])))' "$1"
}

echo "| tree | nodes | triangles | .rmb | .rmb zstd | .glb | Draco .glb | meshopt .glb | pictures in each .glb | grow ms | mesh ms |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for g in "${grammars[@]}"; do
  name="$(basename "${g%.ramus}")"
  "$ramus" -q build "$g" --target binary -o "$work/$name.rmb"
  "$ramus" -q build "$g" --target binary --zstd -o "$work/$name.z.rmb"
  if ! "$ramus" -q build "$g" -o "$work/$name.glb" 2>"$work/build.log"; then
    echo "skipped $g: ramus build made no mesh: $(head -1 "$work/build.log")" >&2
    continue
  fi
  "$ramus" -q build "$g" --compress draco -o "$work/$name.draco.glb"
  "$ramus" -q build "$g" --compress meshopt -o "$work/$name.meshopt.glb"
  # "X.rmb: N nodes, M organs; LOD0 V vertices T triangles; grow A ms, mesh B ms"
  line="$(taskset -c 0 "$grow_mesh" "$work/$name.rmb" --repeat "$repeat")"
  nodes="$(sed -E 's/.*: ([0-9]+) nodes.*/\1/' <<<"$line")"
  triangles="$(sed -E 's/.*LOD0 [0-9]+ vertices ([0-9]+) triangles.*/\1/' <<<"$line")"
  grow="$(sed -E 's/.*grow ([0-9.]+) ms.*/\1/' <<<"$line")"
  mesh="$(sed -E 's/.*mesh ([0-9.]+) ms.*/\1/' <<<"$line")"
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2f | %.2f |\n' "${g#examples/}" \
    "$nodes" "$triangles" "$(size "$work/$name.rmb")" "$(size "$work/$name.z.rmb")" \
    "$(size "$work/$name.glb")" "$(size "$work/$name.draco.glb")" \
    "$(size "$work/$name.meshopt.glb")" "$(pictures "$work/$name.glb")" "$grow" "$mesh"
done
