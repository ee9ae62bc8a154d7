#!/bin/bash
# The reconstruction harness over many scans, one line per scan (docs/reconstruction.md, Accuracy):
#   azimuths  the six harness trees (8 m, 14 m, thick_oak, broadleaf, conifer, weeping), each
#             turned to azimuths 0, 60, ..., 300 and scanned from one station, and from three at 0:
#             the 42 scans the reconstruction's parameters were chosen on
#   seeds     the same trees grown from seeds 1-5 (--tree-seed; the conifer's own is 3), one
#             station and three: trees no parameter was chosen on
#   densities the six trees as grown, scanned at 1000, 1500, 3000 (the default every parameter
#             was chosen at) and 6000 points per square metre, one station and three: whether
#             the results hold at the spacings real scans have (3.2 down to 1.3 cm)
# Each line: tree, stations, azimuth or seed, precision / recall within 2 x radius, the recall
# over the seen wood, the seen centre-line medians / radius of the classes from 5 cm, and the
# skeleton's length over the truth's and its tips (reconstructed / true); then the classes above
# 0.15 r. The length belongs with the medians: a median is the distance from each truth sample to
# the nearest reconstructed segment, so a second chain beside a stem can lower it.
# usage: bench/reconstruct_suite.sh azimuths|seeds|densities BENCH_RECONSTRUCT [FLAGS...]
#   FLAGS go to every `bench_reconstruct accuracy` run (--opt k=v, the scan flags; words without
#   spaces);
#   JOBS runs at once (default 2);
#   SEEDS the seeds of `seeds` (default "1 2 3 4 5"; 6-10 are a second set no parameter was
#   chosen on, kept apart when 1-5 had been looked at);
#   DENSITIES the densities of `densities` (default "1000 1500 3000 6000").
# Two outputs (before and after a change) are compared by bench/reconstruct_suite_diff.sh.
set -euo pipefail
usage="usage: $0 azimuths|seeds|densities BENCH_RECONSTRUCT [FLAGS...]"
if [ $# -lt 2 ] || { [ "$1" != azimuths ] && [ "$1" != seeds ] && [ "$1" != densities ]; }; then
  echo "$usage" >&2
  exit 2
fi
mode=$1
bench=$(realpath "$2")
shift 2
here=$(cd "$(dirname "$0")/.." && pwd)
trees="thick-small thick $here/examples/trees/thick_oak.ramus $here/examples/trees/broadleaf.ramus \
  $here/examples/trees/conifer.ramus $here/examples/trees/weeping.ramus"
out=$(mktemp -d)
table=$(mktemp)
trap 'rm -rf "$out" "$table"' EXIT
for t in $trees; do
  case $mode in
    azimuths)
      for a in 0 60 120 180 240 300; do echo "$t 1 --azimuth $a"; done
      echo "$t 3 --azimuth 0"
      ;;
    seeds) for s in ${SEEDS:-1 2 3 4 5}; do echo "$t 1 --tree-seed $s" && echo "$t 3 --tree-seed $s"; done ;;
    densities)
      for d in ${DENSITIES:-1000 1500 3000 6000}; do
        echo "$t 1 --density $d" && echo "$t 3 --density $d"
      done
      ;;
  esac
done | RS_FLAGS="$*" xargs -P "${JOBS:-2}" -L 1 bash -c '
  key="$(basename "$0" .ramus) st=$1 ${2#--}=$3"
  # shellcheck disable=SC2086 # the flags are words
  "'"$bench"'" accuracy --stations "$1" "$2" "$3" $RS_FLAGS "$0" > "'"$out"'/$key" 2>&1 ||
    echo "FAILED" >> "'"$out"'/$key"'
printf "%-28s %-13s %-13s %s\n" scan "P / R 2r" "R 2r (seen)" \
  "seen median / r from 5 cm, length / truth, tips"
failed=0
for f in "$out"/*; do
  key=$(basename "$f")
  if grep -q FAILED "$f"; then
    echo "$key: failed" >&2 && cat "$f" >&2 && failed=1 && continue
  fi
  p=$(grep -o 'precision(2r)=[0-9.]*' "$f" | head -1 | cut -d= -f2)
  r=$(grep -o ' recall(2r)=[0-9.]*' "$f" | head -1 | cut -d= -f2)
  rs=$(grep -o 'recall(2r, seen)=[0-9.]*' "$f" | cut -d= -f2)
  cls=$(grep 'seen=' "$f" | grep -o '\[[0-9]*-[0-9]* cm: [0-9.]*' | grep -v '\[2-5 ' |
    sed 's/\[//; s/ cm: /:/' | tr '\n' ' ' | sed 's/ $//')
  len=$(grep -o ' length=[0-9.]*' "$f" | head -1 | cut -d= -f2)
  tips=$(grep -o ' tips=[0-9/]*' "$f" | head -1 | cut -d= -f2)
  printf "%-28s %-13s %-13s %s length:%s tips:%s\n" "$key" "$p / $r" "$rs" "$cls" "$len" "$tips" \
    >> "$table"
done
cat "$table"
echo "seen classes above 0.15 r:"
awk '{for (i = 1; i <= NF; ++i) if ($i ~ /^[0-9]+-[0-9]+:/) {
       split($i, c, ":")
       if (c[2] + 0 > 0.15) print "  " $1, $2, $3, c[1] " cm", c[2]
     }}' "$table"
exit "$failed"
