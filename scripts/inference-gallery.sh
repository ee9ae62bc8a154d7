#!/usr/bin/env bash
# The README's inference gallery: for every bundled scan that ramus reads, the grammars of both
# inference methods, one picture with the scan, its reconstruction and 3 trees grown from each
# grammar (skeleton method brown, wavelet green), and a table row per method of the shape
# measures over seeds 1-5 (`ramus compare`, docs/shape-measures.md).
#   scripts/inference-gallery.sh [RAMUS] [SHARED_DATA] [OUT_DIR]
# Defaults: build/release/ramus, ../shared/data, docs/images/inference. Prints the Markdown
# table on stdout.
set -euo pipefail
ramus=${1:-build/release/ramus}
data=${2:-../shared/data}
out=${3:-docs/images/inference}
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# From a `ramus compare` output: the reconstruction's IoU, B's median IoU, the most pieces and
# the largest axis-locked share of B's trees, and their median height ratio.
summarise() {
  local report=$1 recon iou pieces axis height
  recon=$(awk '/^envelope IoU: B median/ { print $NF }' "$report")
  iou=$(awk '/^envelope IoU: B median/ { print $5 }' "$report")
  pieces=$(awk '/^B seed/ { print $5 }' "$report" | sort -n | tail -1)
  axis=$(awk '/^B seed/ { print $7 }' "$report" | sort -g | tail -1)
  height=$(awk '/^B seed/ { print $8 }' "$report" | sort -g | awk '{ v[NR] = $1 }
    END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  printf '%s | %s | %s | %s | %.2f' "$recon" "$iou" "$pieces" "$axis" "$height"
}

echo "| scan | method | reconstruction IoU | grown IoU (median) | pieces (most) | axis-locked (most) | height ratio (median) |"
echo "|---|---|---:|---:|---:|---:|---:|"
for scan in adtree_tree1.xyz adtree_ahn3_delft.xyz rtwig_cloud.txt plantscan3d_A3B4.asc \
  pytlidar_tree_1.las treels_spruce.laz; do
  name=${scan%.*}
  "$ramus" -q infer "$data/$scan" -o "$work/$name.skeleton.ramus" --method skeleton
  "$ramus" -q infer "$data/$scan" -o "$work/$name.wavelet.ramus" --method wavelet
  for method in skeleton wavelet; do
    "$ramus" -q compare "$data/$scan" "$work/$name.$method.ramus" --seeds 5 >"$work/$method.txt"
    echo "| $scan | $method | $(summarise "$work/$method.txt") |"
  done
  "$ramus" -q compare "$data/$scan" "$work/$name.skeleton.ramus" --seeds 3 \
    --picture "$out/$name.png" --picture-also "$work/$name.wavelet.ramus" >/dev/null
done
