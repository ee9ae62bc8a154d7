#!/bin/bash
# CPU time of the reconstruction of every bundled scan by two or more bench_reconstruct binaries
# (an older commit's built from `git archive`, and this one's), side by side: on each scan the
# binaries alternate, ROUNDS times, and each keeps
#   cpu  - its least `cpu=` of `bench_reconstruct time --repeat N` (the least CPU time, user +
#          system of all threads, of one reconstruction among N in one process), and
#   mean - its least (user + system) / N of the whole process (/usr/bin/time).
# Ratios are to the first binary. N is 10, 100 for adtree_ahn3_delft (0.02-0.03 s each: /usr/bin/time
# counts in 10 ms), 5 for pytlidar_tree_1 and treels_spruce.
# usage: bench/reconstruct_vs.sh ROUNDS BIN_REFERENCE BIN...
#   DATA   folder of the scans (default ../shared/data)
#   SPRUCE the treels spruce scan to read (default $DATA/treels_spruce.laz; binaries that predate
#          LAZ support, such as d51767c's, need the same points as a .las)
#   SCANS  the scans to run instead of the six (paths)
set -euo pipefail
rounds=$1
shift
data=${DATA:-../shared/data}
spruce=${SPRUCE:-$data/treels_spruce.laz}
printf "%-24s" scan
for b in "$@"; do printf " %24s" "$(basename "$b") cpu/mean"; done
printf "\n"
scans=${SCANS:-"$data/adtree_tree1.xyz $data/adtree_ahn3_delft.xyz $data/rtwig_cloud.txt \
  $data/plantscan3d_A3B4.asc $data/pytlidar_tree_1.las $spruce"}
for s in $scans; do
  n=10
  case $s in *pytlidar* | *spruce*) n=5 ;; *ahn3*) n=100 ;; esac
  declare -A cpu=() mean=()
  for _ in $(seq "$rounds"); do
    for b in "$@"; do
      out=$({ /usr/bin/time -f "TIME %U %S" "$b" time --repeat "$n" "$s"; } 2>&1)
      c=$(grep -o 'cpu=[0-9.]*' <<<"$out" | cut -d= -f2)
      m=$(grep TIME <<<"$out" | awk -v n="$n" '{printf "%.5f", ($2 + $3) / n}')
      if [ -z "${cpu[$b]:-}" ] || awk "BEGIN{exit !($c < ${cpu[$b]})}"; then cpu[$b]=$c; fi
      if [ -z "${mean[$b]:-}" ] || awk "BEGIN{exit !($m < ${mean[$b]})}"; then mean[$b]=$m; fi
    done
  done
  printf "%-24s" "$(basename "$s")"
  ref=$1
  for b in "$@"; do
    printf " %9s/%-7s (%s)" "${cpu[$b]}" "${mean[$b]}" \
      "$(awk "BEGIN{printf \"%.2f/%.2f\", ${cpu[$b]} / ${cpu[$ref]}, ${mean[$b]} / ${mean[$ref]}}")"
  done
  printf "\n"
  unset cpu mean
done
