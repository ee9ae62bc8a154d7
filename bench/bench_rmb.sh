#!/usr/bin/env bash
# The .rmb size table (docs/binary-format.md, Sizes; issue 8): for each example with an lsystem
# block and for grammars inferred from the scans in ../shared/data, the .ramus bytes, the .rmb
# bytes (exact, quantized with --tolerance 1e-3, exact with --zstd, stripped with --strip, and
# all three: --strip --tolerance 1e-3 --zstd), the .glb of the tree
# it grows (`ramus build`), that .glb compressed with Draco (npx @gltf-transform/cli draco,
# installed into a temporary folder as bench/mesh_draco.sh does), the ratio Draco / .rmb and
# the decoding speed (bench_rmb, full verification). Prints a Markdown table.
#   bench/bench_rmb.sh [BUILD_DIR] [SHARED_DATA_DIR]
# Set GLTF_TRANSFORM to an installed gltf-transform binary to skip the npm install; set
# RMB_SIZES_ONLY=1 to skip the meshes (.glb and Draco columns n/a).
set -euo pipefail
build="${1:-build/release}"
data="${2:-../shared/data}"
ramus="$build/ramus"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
gltf="${GLTF_TRANSFORM:-}"
sizes_only="${RMB_SIZES_ONLY:-0}"
if [ -z "$gltf" ] && [ "$sizes_only" != 1 ]; then
  (cd "$work" && npm install --no-audit --no-fund --silent --prefix "$work/npm" @gltf-transform/cli@4.5.1 >/dev/null)
  gltf="$work/npm/node_modules/.bin/gltf-transform"
fi

grammars=()
for f in $(find examples -name '*.ramus' | sort); do
  grep -q 'lsystem ' "$f" && grammars+=("$f")
done
# Grammars inferred from the scans by both methods (the .rmb holds their lsystem block and a
# wavelet grammar's voxel rules). Scans a method cannot read or that
# take too long are left out and named on stderr.
for scan in "$data"/*.xyz "$data"/*.asc "$data"/*.txt "$data"/*.las; do
  [ -f "$scan" ] || continue
  for method in skeleton wavelet; do
    out="$work/$(basename "${scan%.*}")_$method.ramus"
    if timeout 600 "$ramus" -q infer "$scan" --method "$method" -o "$out" >/dev/null 2>&1 &&
       grep -q 'lsystem ' "$out"; then
      grammars+=("$out")
    else
      echo "skipped $scan: ramus infer --method $method failed or took over 10 min" >&2
    fi
  done
done

echo "| Grammar | .ramus | .rmb v1 | .rmb | .rmb 1e-3 | .rmb zstd | .rmb stripped | stripped 1e-3 zstd v1 | stripped 1e-3 zstd | .glb | Draco .glb | Draco / .rmb | Draco / smallest | decode ns/byte |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for g in "${grammars[@]}"; do
  name="$(basename "${g%.ramus}")"
  if ! "$ramus" -q build "$g" --target binary -o "$work/$name.rmb" 2>"$work/build.log"; then
    echo "skipped $g: ramus build --target binary failed: $(head -1 "$work/build.log")" >&2
    continue
  fi
  "$ramus" -q build "$g" --target binary --tolerance 1e-3 -o "$work/$name.q.rmb"
  "$ramus" -q build "$g" --target binary --zstd -o "$work/$name.z.rmb"
  "$ramus" -q build "$g" --target binary --strip -o "$work/$name.s.rmb"
  "$ramus" -q build "$g" --target binary --strip --tolerance 1e-3 --zstd -o "$work/$name.sqz.rmb"
  # Format version 1 (before the compact layout of version 2), for comparison.
  "$ramus" -q build "$g" --target binary --rmb-version 1 -o "$work/$name.v1.rmb"
  "$ramus" -q build "$g" --target binary --rmb-version 1 --strip --tolerance 1e-3 --zstd \
    -o "$work/$name.sqz.v1.rmb"
  glb=0
  draco=0
  if [ "$sizes_only" != 1 ] && "$ramus" -q build "$g" -o "$work/$name.glb" >/dev/null 2>&1; then  # (param_p42 draws nothing)
    glb=$(stat -c %s "$work/$name.glb")
    if "$gltf" draco "$work/$name.glb" "$work/$name.draco.glb" >"$work/draco.log" 2>&1; then
      draco=$(stat -c %s "$work/$name.draco.glb")
    fi
  fi
  rmb=$(stat -c %s "$work/$name.rmb")
  speed=$("$build/bench/bench_rmb" "$work/$name.rmb" | awk '{print $4}')
  label="$g"
  case "$g" in "$work"/*) label="inferred: $(basename "$g")" ;; esac
  awk -v n="$label" -v s="$(stat -c %s "$g")" -v r="$rmb" -v q="$(stat -c %s "$work/$name.q.rmb")" \
      -v z="$(stat -c %s "$work/$name.z.rmb")" -v st="$(stat -c %s "$work/$name.s.rmb")" \
      -v sqz="$(stat -c %s "$work/$name.sqz.rmb")" -v m="$glb" -v d="$draco" \
      -v v1="$(stat -c %s "$work/$name.v1.rmb")" -v sqz1="$(stat -c %s "$work/$name.sqz.v1.rmb")" \
      -v v="$speed" 'BEGIN {
    ratio = "n/a"; ratio2 = "n/a"; dtext = "n/a"
    if (d > 0) { ratio = sprintf("%.0fx", d / r); ratio2 = sprintf("%.0fx", d / sqz); dtext = d }
    printf "| `%s` | %d | %d | %d | %d | %d | %d | %d | %d | %d | %s | %s | %s | %s |\n", n, s, v1, r, q, z, st, sqz1, sqz, m, dtext, ratio, ratio2, v
  }'
done
