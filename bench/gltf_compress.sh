#!/usr/bin/env bash
# Size and load time of the demo tree (examples/trees/broadleaf.ramus --lod 2, as `make demo`
# writes it) uncompressed and with --compress draco / meshopt: the time ramus takes to write
# each file, and the time three.js's GLTFLoader (with DRACOLoader / MeshoptDecoder) takes to
# load it in headless Chromium (tests/pieces/browser/load_in_three.js: fetch from localhost,
# decode, build the scene), the median of RUNS loads.
#   bench/gltf_compress.sh [BUILD_DIR] [RUNS] [EXTRA BUILD OPTIONS...]
set -euo pipefail
build="${1:-build/release}"
runs="${2:-5}"
shift $(( $# > 2 ? 2 : $# ))
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
printf '%-8s %12s %8s %10s %14s\n' encoding bytes ratio "write s" "load ms (med)"
raw=0
for c in none draco meshopt; do
  out="$work/broadleaf_$c.glb"
  opts=(--lod 2 "$@")
  [ "$c" = none ] || opts+=(--compress "$c")
  start=$(date +%s.%N)
  "$build/ramus" -q build examples/trees/broadleaf.ramus -o "$out" "${opts[@]}"
  end=$(date +%s.%N)
  size=$(stat -c %s "$out")
  [ "$c" = none ] && raw=$size
  files=()
  for _ in $(seq 1 "$runs"); do files+=("$out"); done
  load=$(node tests/pieces/browser/load_in_three.js "${files[@]}" |
         grep -o '"loadMs":[0-9.]*' | cut -d: -f2 | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  awk -v c="$c" -v s="$size" -v r="$raw" -v t0="$start" -v t1="$end" -v l="$load" 'BEGIN {
    printf "%-8s %12d %7.1f%% %10.2f %14.1f\n", c, s, 100 * s / r, t1 - t0, l }'
done
