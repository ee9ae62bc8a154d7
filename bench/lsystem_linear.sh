#!/usr/bin/env bash
# Is derivation linear? CPU time per module of bench_lsystem (one thread) for strings from about
# 1e4 to 1.7e7 modules, on the plain system (a), the parametric tree (b) and its stochastic
# variant (p) of bench/lsystem_vs_lindenmayer.sh, measured two ways, each the same at every
# length:
#   steady state: one untimed derivation first (`--warmup`), then at least three timed ones,
#     repeated until about 3e7 modules are produced: what a program that grows trees again and
#     again spends per module. Shown with its user and system parts (the system part is mostly
#     the kernel supplying fresh pages).
#   first derivation: one derivation in a fresh process, which pays for all of its memory
#     (every page of its strings comes fresh from the kernel) and its cold caches.
# Each point is the median of three runs. Prints a Markdown table and, for each system and way,
# the largest / smallest time per module; with PNG, also draws the plot there (steady state
# solid, first derivation dashed; an SVG rendered by headless Chromium, the browser the test
# suite already uses).
#
# usage: bench/lsystem_linear.sh [BUILD_DIR [PNG]]   (default: build/release, no picture)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build/release}"
png="${2:-}"
bench="$build/bench/bench_lsystem"
[[ -x "$bench" ]] || { echo "missing $bench: build the target bench_lsystem first" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# case n-range: final lengths from ~1e4 to ~1.7e7
specs=("a 6 10" "b 11 21" "p 11 21")
points="$tmp/points.tsv"  # case n length ns_steady user system ns_first
: >"$points"
# median_of_3 CMD...: the run with the middle CPU time -> "length ns_per_module user system"
median_of_3() {
  for run in 1 2 3; do
    "$@" | awk '$1=="length"{l=$2} $1=="modules_total"{t=$2} $1=="cpu_seconds"{c=$2}
                $1=="user_seconds"{u=$2} $1=="system_seconds"{y=$2}
                END{printf "%d %.4f %.4f %.4f\n", l, c / t * 1e9, u / t * 1e9, y / t * 1e9}'
  done | sort -k2 -g | sed -n 2p
}
for spec in "${specs[@]}"; do
  set -- $spec
  kase=$1
  for ((n = $2; n <= $3; ++n)); do
    total=$("$bench" "$kase" "$n" 1 1 | awk '$1=="modules_total"{print $2}')
    repeat=$(awk -v t="$total" 'BEGIN{r = int(3e7 / t); print r < 3 ? 3 : r}')
    steady=$(median_of_3 "$bench" "$kase" "$n" 1 "$repeat" --warmup)
    first=$(median_of_3 "$bench" "$kase" "$n" 1 1 | awk '{print $2}')
    echo "$kase $n $steady $first" >>"$points"
  done
done

echo "| system | n | modules | steady state: ns per module (CPU, 1 thread) | of it user | of it system | first derivation of a process: ns per module |"
echo "|---|---|---|---|---|---|---|"
awk '{printf "| (%s) | %d | %d | %.2f | %.2f | %.2f | %.2f |\n", $1, $2, $3, $4, $5, $6, $7}' "$points"
echo
awk '{ if (!($1 in lo) || $4 < lo[$1]) lo[$1] = $4; if (!($1 in hi) || $4 > hi[$1]) hi[$1] = $4
       if (!($1 in flo) || $7 < flo[$1]) flo[$1] = $7; if (!($1 in fhi) || $7 > fhi[$1]) fhi[$1] = $7 }
     END { for (k in lo) printf "(%s): largest / smallest time per module = %.2f steady state, %.2f first derivation\n",
                                k, hi[k] / lo[k], fhi[k] / flo[k] }' "$points" | sort

[[ -n "$png" ]] || exit 0
command -v chromium >/dev/null || { echo "chromium is required for the picture" >&2; exit 2; }
# The plot: x = string length (log scale, 1e3 .. 1e8), y = ns per module from 0.
awk -v W=800 -v H=480 '
  function X(v) { return 70 + (log(v) / log(10) - 3) / 5 * (W - 100) }
  function Y(v) { return H - 50 - v / ymax * (H - 90) }
  { c[NR] = $1; len[NR] = $3; ns[NR] = $4; fi[NR] = $7; if ($4 > ymax) ymax = $4; if ($7 > ymax) ymax = $7 }
  END {
    ymax = int(ymax * 1.25) + 1
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"13\">\n", W, H
    printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H
    for (d = 3; d <= 8; ++d) {
      x = X(10 ^ d)
      printf "<line x1=\"%.1f\" y1=\"40\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n", x, x, H - 50
      printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">1e%d</text>\n", x, H - 32, d
    }
    step = ymax <= 5 ? 1 : 2
    for (v = 0; v <= ymax; v += step) {
      y = Y(v)
      printf "<line x1=\"70\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", y, W - 30, y
      printf "<text x=\"62\" y=\"%.1f\" text-anchor=\"end\">%d</text>\n", y + 4, v
    }
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">modules in the derived string</text>\n", (W + 40) / 2, H - 10
    printf "<text x=\"18\" y=\"%d\" transform=\"rotate(-90 18 %d)\" text-anchor=\"middle\">ns per module (CPU, one thread)</text>\n", H / 2, H / 2
    printf "<text x=\"%d\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">Derivation time per module against string length</text>\n", W / 2
    col["a"] = "#1f77b4"; col["b"] = "#d62728"; col["p"] = "#2ca02c"
    name["a"] = "(a) plain, ABOP 1.24f"; name["b"] = "(b) parametric tree"; name["p"] = "(p) stochastic parametric"
    for (i = 1; i <= NR; ++i) {
      if (i > 1 && c[i] == c[i - 1])
        printf "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"/>\n", X(len[i - 1]), Y(ns[i - 1]), X(len[i]), Y(ns[i]), col[c[i]]
      printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>\n", X(len[i]), Y(ns[i]), col[c[i]]
      if (i > 1 && c[i] == c[i - 1])
        printf "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.5\" stroke-dasharray=\"5,4\"/>\n", X(len[i - 1]), Y(fi[i - 1]), X(len[i]), Y(fi[i]), col[c[i]]
    }
    n = split("a b p", order, " ")
    for (j = 1; j <= n; ++j) {
      s = order[j]; y = 52 + 20 * (j - 1)
      printf "<rect x=\"%d\" y=\"%d\" width=\"14\" height=\"4\" fill=\"%s\"/>\n", W - 250, y - 5, col[s]
      printf "<text x=\"%d\" y=\"%d\">%s</text>\n", W - 230, y, name[s]
    }
    y = 52 + 20 * n
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#444\" stroke-dasharray=\"5,4\"/>\n", W - 250, y - 3, W - 236, y - 3
    printf "<text x=\"%d\" y=\"%d\">first derivation of a process</text>\n", W - 230, y
    print "</svg>"
  }' "$points" >"$tmp/plot.svg"
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=800,480 \
  --screenshot="$tmp/plot.png" "file://$tmp/plot.svg" >/dev/null 2>&1
[[ -s "$tmp/plot.png" ]] || { echo "chromium wrote no picture" >&2; exit 1; }
mkdir -p "$(dirname "$png")"
cp "$tmp/plot.png" "$png.tmp" && mv "$png.tmp" "$png"
echo "plot: $png"
