#!/usr/bin/env bash
# Runs one libFuzzer target of build/fuzz until it has spent a given number of CPU seconds,
# in chunks that resume from the corpus the previous chunks grew, and records each chunk.
#
#   scripts/fuzz-hours.sh TARGET CPU_SECONDS [--work DIR] [--chunk WALL_SECONDS] [--fuzz-dir DIR]
#
# TARGET is the short name (parse_check, decode_rmb, ...). Why CPU seconds and chunks: on a
# shared machine a fuzzer started at `nice -n 19` gets only the CPU the other jobs leave, so
# libFuzzer's -max_total_time (wall time) would overstate the hours; this script adds up the
# user + system time of every chunk (GNU time) and stops once the sum reaches CPU_SECONDS. A
# stopped run (killed machine, end of a session) resumes where it was: the work folder keeps the
# grown corpus, the chunk table and the logs, and a new call adds chunks to them.
#
# Work folder (default fuzz-runs/TARGET): corpus/ (new inputs; the seed corpus of
# tests/fuzz/corpus/TARGET is read beside it, never written), chunks.tsv (one line per chunk:
# wall s, CPU s, executions, edges, features, peak RSS MB, exit code), log-N.txt (libFuzzer's
# output), and crash-*/leak-*/timeout-* files when a chunk finds something. The script stops at
# the first chunk that does not exit 0 and exits 1.
set -euo pipefail

usage() { sed -n '4p' "$0" | sed 's/^#   //' >&2; exit 2; }
[[ $# -ge 2 ]] || usage
target=$1
budget=$2
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
work=""
chunk=600
fuzz_dir="$root/build/fuzz"
while [[ $# -gt 0 ]]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --chunk) chunk=$2; shift 2 ;;
    --fuzz-dir) fuzz_dir=$2; shift 2 ;;
    *) usage ;;
  esac
done
[[ $budget =~ ^[0-9]+$ && $chunk =~ ^[0-9]+$ && $chunk -gt 0 ]] || usage
work=${work:-fuzz-runs/$target}
binary="$fuzz_dir/fuzz_$target"
seeds="$root/tests/fuzz/corpus/$target"
[[ -x $binary ]] || { echo "fuzz-hours: no $binary (cmake --preset fuzz && cmake --build build/fuzz)" >&2; exit 2; }
[[ -d $seeds ]] || { echo "fuzz-hours: no seed corpus $seeds" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "fuzz-hours: needs GNU time (/usr/bin/time)" >&2; exit 2; }

# The dictionary of the target's input language, where it has one.
case $target in
  parse_check | format | check_format | roundtrip_rmb) dict=ramus ;;
  read_ply) dict=ply ;;
  read_xyz) dict=xyz ;;
  read_pcd) dict=pcd ;;
  read_skeleton_json) dict=skeleton_json ;;
  piece_obj) dict=obj ;;
  piece_gltf) dict=gltf ;;
  lsp) dict=lsp ;;
  *) dict="" ;;
esac
dict_flag=()
[[ -n $dict ]] && dict_flag=("-dict=$root/tests/fuzz/dict/$dict.dict")

mkdir -p "$work/corpus"
table="$work/chunks.tsv"
[[ -f $table ]] || printf 'chunk\twall_s\tcpu_s\texecutions\tedges\tfeatures\tpeak_rss_mb\texit\n' > "$table"

spent() { awk -F'\t' 'NR > 1 { s += $3 } END { printf "%d", s }' "$table"; }

while (( $(spent) < budget )); do
  n=$(( $(wc -l < "$table") ))
  log="$work/log-$n.txt"
  times="$work/time-$n.txt"
  start=$(date +%s)
  set +e
  /usr/bin/time -f '%U %S' -o "$times" "$binary" "${dict_flag[@]}" -max_total_time="$chunk" \
    -timeout=120 -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$work/" \
    "$work/corpus" "$seeds" > "$log" 2>&1
  code=$?
  set -e
  wall=$(( $(date +%s) - start ))
  cpu=$(awk 'END { printf "%d", $1 + $2 }' "$times")
  execs=$(awk '/stat::number_of_executed_units/ { print $2 }' "$log")
  rss=$(awk '/stat::peak_rss_mb/ { print $2 }' "$log")
  edges=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | awk '{ print $2 }')
  features=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | awk '{ print $2 }')
  printf '%d\t%d\t%d\t%s\t%s\t%s\t%s\t%d\n' "$n" "$wall" "$cpu" "${execs:--}" "${edges:--}" \
    "${features:--}" "${rss:--}" "$code" >> "$table"
  if (( code != 0 )); then
    echo "fuzz-hours: $target chunk $n exited $code; see $log" >&2
    grep -m3 -E 'ERROR|SUMMARY|Test unit written' "$log" >&2 || true
    exit 1
  fi
done

# The totals: CPU and wall time, executions, the last chunk's coverage.
awk -F'\t' -v t="$target" 'NR > 1 { w += $2; c += $3; e += $4; edges = $5; ft = $6;
    if ($7 > r) r = $7; n++ }
  END { printf "%s: %d chunks, %d s wall, %d s CPU (%.2f h), %d executions (%.0f per CPU s), edges %s, features %s, peak RSS %d MB, clean\n",
        t, n, w, c, c / 3600, e, (c > 0 ? e / c : 0), edges, ft, r }' "$table"
