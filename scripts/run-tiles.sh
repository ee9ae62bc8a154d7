#!/usr/bin/env bash
# Reconstructs every tile of a tiled plot with GNU parallel, then merges them (docs/scale.md):
#   scripts/run-tiles.sh DIR [--jobs N] [-o FOREST] [-- RECONSTRUCT-OPTIONS...]
# DIR is a folder written by `ramus tile`; tile K goes to DIR/K.json, the forest to FOREST
# (default DIR/forest.json). RECONSTRUCT-OPTIONS default to `--bases stems --no-leaves`.
# The ramus executable is $RAMUS, else `ramus` on PATH. Stops at the first failing tile.
set -euo pipefail
usage() { echo "usage: $0 DIR [--jobs N] [-o FOREST] [-- RECONSTRUCT-OPTIONS...]" >&2; exit 2; }
[ $# -ge 1 ] || usage
dir=$1
shift
jobs=2
out=""
while [ $# -gt 0 ]; do
  case $1 in
    --jobs) [ $# -ge 2 ] || usage; jobs=$2; shift 2 ;;
    -o) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --) shift; break ;;
    *) usage ;;
  esac
done
ramus=${RAMUS:-ramus}
options=("$@")
[ ${#options[@]} -gt 0 ] || options=(--bases stems --no-leaves)
manifest="$dir/manifest.json"
[ -f "$manifest" ] || { echo "$0: $manifest does not exist (run ramus tile first)" >&2; exit 1; }
command -v parallel >/dev/null || { echo "$0: GNU parallel is not installed (apt-get install parallel)" >&2; exit 1; }
# Tile ids run from 0 to the number of tiles - 1 (formats/tile_manifest.h).
count=$(grep -o '"id":' "$manifest" | wc -l)
seq 0 $((count - 1)) |
  parallel --will-cite --halt now,fail=1 -j "$jobs" -q \
    "$ramus" -q reconstruct "$manifest" --tile {} -o "$dir/{}.json" "${options[@]}"
"$ramus" merge "$dir" -o "${out:-$dir/forest.json}"
