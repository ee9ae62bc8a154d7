#!/bin/bash
# Two runs of bench/reconstruct_suite.sh compared: the way a change of the reconstruction is
# judged (docs/reconstruction.md, Accuracy, "How much one class median moves"). One class median
# of one scan stands on a few limbs and moves by several hundredths of a radius with any change,
# so a change is judged on every class it moves and on the sum over the suite, not on one class.
# Prints each scan where a seen class median from 5 cm, the precision or the recall (within 2 x
# radius; over all and over the seen wood) moved by at least 0.005 or the length over the
# truth's by 0.02, then the sum of the class medians' changes, how many classes got worse or
# better by 0.005 or more, the mean change of the length, and the seen classes above 0.15 r
# before and after. The length is read with the medians: a median is the distance from each
# truth sample to the nearest reconstructed segment, so duplicate chains beside a stem lower it
# (fewer levels of the axis projection did so: docs/reconstruction.md, Accuracy).
# usage: bench/reconstruct_suite_diff.sh BEFORE AFTER
#   BEFORE, AFTER: the outputs of `bench/reconstruct_suite.sh MODE BENCH_RECONSTRUCT > FILE`
#   for the same MODE (scans are matched by their first three words, e.g. "weeping st=1 seed=2").
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 BEFORE AFTER" >&2
  exit 2
fi
for f in "$1" "$2"; do
  if ! grep -q '^scan  *P / R 2r' "$f"; then
    echo "$0: $f: not an output of bench/reconstruct_suite.sh (no table header)" >&2
    exit 1
  fi
done
awk '
  # A table line: three words of key, "P / R", the seen recall, then classes "lo-hi:median".
  function parse(line, side,    w, n, i, key, c) {
    n = split(line, w, " ")
    if (n < 7 || w[5] != "/" || w[4] !~ /^[0-9.]+$/) return
    key = w[1] " " w[2] " " w[3]
    keys[side, key] = 1
    if (side == 2 && !((1, key) in keys)) order_only2[++n2] = key
    if (side == 1) order[++n1] = key
    p[side, key] = w[4]; r[side, key] = w[6]; rs[side, key] = w[7]
    for (i = 8; i <= n; ++i) {
      if (split(w[i], c, ":") != 2) continue
      if (c[1] == "length") { len[side, key] = c[2]; continue }
      if (c[1] == "tips") { tips[side, key] = c[2]; continue }
      cls[side, key, c[1]] = c[2]
      if (side == 1) classes[key] = classes[key] " " c[1]
      if (c[2] + 0 > 0.15) ++above[side]
    }
  }
  FNR == 1 { ++side }
  { parse($0, side) }
  function abs(x) { return x < 0 ? -x : x }
  END {
    printf "%-30s %s\n", "scan", "what moved by 0.005 or more (before -> after)"
    for (i = 1; i <= n1; ++i) {
      key = order[i]
      if (!((2, key) in keys)) { only1 = only1 "  " key "\n"; continue }
      moved = ""
      m = split(classes[key], list, " ")
      for (j = 1; j <= m; ++j) {
        c = list[j]
        if (!((1, key, c) in cls) || !((2, key, c) in cls)) continue
        d = cls[2, key, c] - cls[1, key, c]
        sum += d; ++count
        if (d >= 0.005) ++worse
        if (d <= -0.005) ++better
        if (abs(d) >= 0.005) moved = moved sprintf("%s%s cm %s -> %s", moved == "" ? "" : "; ", c, cls[1, key, c], cls[2, key, c])
      }
      if (abs(p[2, key] - p[1, key]) >= 0.005 || abs(r[2, key] - r[1, key]) >= 0.005 ||
          abs(rs[2, key] - rs[1, key]) >= 0.005)
        moved = moved sprintf("%sP %s -> %s, R %s -> %s, R seen %s -> %s", moved == "" ? "" : "; ",
                              p[1, key], p[2, key], r[1, key], r[2, key], rs[1, key], rs[2, key])
      if (((1, key) in len) && ((2, key) in len)) {
        dl = len[2, key] - len[1, key]
        lsum += dl; ++lcount
        if (abs(dl) >= 0.02)
          moved = moved sprintf("%slength %s -> %s, tips %s -> %s", moved == "" ? "" : "; ",
                                len[1, key], len[2, key], tips[1, key], tips[2, key])
      }
      if (moved != "") printf "%-30s %s\n", key, moved
    }
    printf "class medians: sum of changes %+.3f r over %d classes; worse by 0.005 or more %d, better %d\n",
           sum, count, worse, better
    if (lcount > 0) printf "length / truth: mean change %+.4f over %d scans\n", lsum / lcount, lcount
    printf "seen classes above 0.15 r: before %d, after %d\n", above[1], above[2]
    if (only1 != "") printf "only in BEFORE:\n%s", only1
    for (i = 1; i <= n2; ++i) printf "%s%s\n", i == 1 ? "only in AFTER:\n  " : "  ", order_only2[i]
  }
' "$1" "$2"
