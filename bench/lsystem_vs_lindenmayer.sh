#!/usr/bin/env bash
# Side by side: ramus's L-system engine against the npm package lindenmayer@1.5.4 on
#   (a)  ABOP fig. 1.24f as a plain string system, n = 10 (6.5 million modules)
#   (b)  the parametric binary tree A(s) -> F(s)[+A(s/1.456)][-A(s/1.456)], n = 21 (16.8 million)
#   (s)  ABOP fig. 1.27, stochastic plain strings F -> (.33) F[+F]F[-F]F | (.33) F[+F]F | (.34)
#        F[-F]F, n = 12 (about 20 million modules; lindenmayer's weighted successors)
#   (p)  (b) with a stochastic choice between two successors, n = 21 (14.7 million modules;
#        lindenmayer's weighted successors that are functions)
#   (c1) the context-sensitive ABOP fig. 1.31a at n = 30
#   (c2) a context-sensitive system of 1.5 million modules (n = 16): internodes F elongate
#        only above a node I (`I < F -> F F`), F ignored by contexts as in ABOP 1.31
# Throughput is modules per second over all steps: the sum of the string lengths after each
# step divided by the derivation time. Ranked by CPU time (user + system of every thread, so a
# busy machine does not skew it); wall-clock rates are shown too, ramus with 2 threads. Memory
# is the peak resident set of each whole process (/usr/bin/time -v). The last lines check the
# targets of issue 23 on this run's CPU ratios: parametric and stochastic parametric (b, p) at
# least 20 x, plain strings (a, s) at least 5 x, at most 12 bytes per parametric module.
#
# usage: bench/lsystem_vs_lindenmayer.sh [BUILD_DIR]   (default: build/release)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build/release}"
bench="$build/bench/bench_lsystem"
[[ -x "$bench" ]] || { echo "missing $bench: build the target bench_lsystem first" >&2; exit 2; }
command -v node >/dev/null || { echo "node is required" >&2; exit 2; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "installing lindenmayer@1.5.4 into $tmp ..." >&2
(cd "$tmp" && npm install --silent --no-audit --no-fund lindenmayer@1.5.4 >/dev/null 2>&1) ||
  { echo "npm install lindenmayer@1.5.4 failed" >&2; exit 2; }
modules="$tmp/node_modules"

# run CMD... -> R_ok R_length R_total R_seconds R_cpu R_bpm R_rss (kB)
run() {
  local out="$tmp/out.txt" err="$tmp/err.txt"
  R_ok=1
  /usr/bin/time -v "$@" >"$out" 2>"$err" || R_ok=0
  R_length=$(awk '$1=="length"{print $2}' "$out")
  R_total=$(awk '$1=="modules_total"{print $2}' "$out")
  R_seconds=$(awk '$1=="seconds"{print $2}' "$out")
  R_cpu=$(awk '$1=="cpu_seconds"{print $2}' "$out")
  R_bpm=$(awk '$1=="bytes_per_parametric_module"{print $2}' "$out")
  R_block=$(awk '$1=="block_offset_bytes_per_module"{print $2}' "$out")
  R_rss=$(awk -F': ' '/Maximum resident set size/{print $2}' "$err")
  [[ -n "$R_total" && -n "$R_cpu" ]] || R_ok=0
}
rate() { awk -v t="$1" -v s="$2" 'BEGIN{printf "%.3g", t / (s > 1e-9 ? s : 1e-9)}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.1f", a / b}'; }
mb() { awk -v k="$1" 'BEGIN{printf "%.0f", k / 1024}'; }

printf "%-3s %3s %9s | %10s %10s %6s | %10s %10s %6s %3s | %8s %8s %6s\n" case n length \
  "ramus cpu" "ramus wall" "MB" "lind. cpu" "lind. wall" "MB" "n'" "x (cpu)" "x (wall)" "mem x"
targets=""  # "case ratio minimum" per case with a target
for spec in "a 10 3 1" "s 12 3 1" "b 21 3 1" "p 21 3 1" "c1 30 200 5" "c2 16 3 1"; do
  set -- $spec
  kase=$1 n=$2 rrep=$3 lrep=$4
  run "$bench" "$kase" "$n" 1 "$rrep"                 # one thread: CPU rate
  r_len=$R_length r_total=$R_total r_cpu=$R_cpu r_bpm=$R_bpm r_block=$R_block
  run "$bench" "$kase" "$n" 2 "$rrep"                 # two threads: wall rate, memory
  r_wall=$R_seconds r_rss=$R_rss
  # lindenmayer keeps one JS object per module in (b); if it runs out of heap, retry with a
  # smaller n and compare per-module throughput (the n' column says which n it managed).
  ln=$n
  while :; do
    run node --max-old-space-size=4096 "$here/lindenmayer_runner.js" "$modules" "$kase" "$ln" "$lrep"
    [[ $R_ok == 1 || $ln -le 2 ]] && break
    ln=$((ln - 1))
  done
  l_total=$R_total l_cpu=$R_cpu l_wall=$R_seconds l_rss=$R_rss l_len=$R_length
  rc=$(rate "$r_total" "$r_cpu"); rw=$(rate "$r_total" "$r_wall")
  lc=$(rate "$l_total" "$l_cpu"); lw=$(rate "$l_total" "$l_wall")
  if [[ $ln == "$n" ]]; then memx=$(ratio "$l_rss" "$r_rss"); else memx="n/a"; fi
  printf "%-3s %3s %9s | %10s %10s %6s | %10s %10s %6s %3s | %7sx %7sx %6s\n" "$kase" "$n" \
    "$r_len" "$rc" "$rw" "$(mb "$r_rss")" "$lc" "$lw" "$(mb "$l_rss")" "$ln" \
    "$(ratio "$rc" "$lc")" "$(ratio "$rw" "$lw")" "$memx"
  if [[ -n "$r_bpm" ]]; then
    echo "    ramus: $r_bpm bytes per parametric module in the string (plus $r_block per module" \
         "of block offsets)"
    bpm_max=$(awk -v a="${bpm_max:-0}" -v b="$r_bpm" 'BEGIN{print (b > a ? b : a)}')
  fi
  case $kase in
    a | s) targets+="$kase $(ratio "$rc" "$lc") 5 "$'\n' ;;
    b | p) targets+="$kase $(ratio "$rc" "$lc") 20 "$'\n' ;;
  esac
  if [[ $ln == "$n" && "$l_len" != "$r_len" ]]; then
    case $kase in
      s | p) echo "    lengths differ (ramus $r_len, lindenmayer $l_len): each draws its own" \
                  "random choices (lindenmayer from Math.random)" ;;
      *) echo "    lengths differ (ramus $r_len, lindenmayer $l_len): lindenmayer's right context" \
              "walks on past the ']' that closes a branch, where ABOP/cpfg/L-Py fail the match" ;;
    esac
  fi
done
echo "rates in modules/s over all steps; x = ramus rate / lindenmayer rate; mem x = peak RSS"
echo "of lindenmayer / peak RSS of ramus (same n only)."
echo "targets (issue 23, CPU ratios of this run):"
printf "%s" "$targets" | awk 'NF == 3 {
  printf "  (%s) %5.1fx >= %2dx: %s\n", $1, $2, $3, ($2 >= $3 ? "met" : "NOT met") }'
awk -v b="${bpm_max:-0}" 'BEGIN{
  printf "  %.2f bytes per parametric module <= 12: %s\n", b, (b <= 12 ? "met" : "NOT met") }'

