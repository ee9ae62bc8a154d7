#!/usr/bin/env bash
# Runs two builds of ramus over every example grammar and every bundled scan and compares what
# they write, byte for byte. Used to show that a change which should not change behaviour (a move
# of files, a refactoring) does not:
#   scripts/compare-outputs.sh OLD_RAMUS NEW_RAMUS [SHARED_DIR]
# Exit 0 when every output is identical, 1 otherwise (the differing files are listed).
set -euo pipefail
old="$(realpath "$1")"
new="$(realpath "$2")"
root="$(cd "$(dirname "$0")/.." && pwd)"
shared="$(realpath "${3:-$root/../shared}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# run_all RAMUS OUTDIR: every command whose output is deterministic, its files and its stdout.
run_all() {
  local ramus="$1" out="$2"
  mkdir -p "$out"
  cd "$root"
  for g in examples/abop/*.ramus examples/trees/*.ramus; do
    local n
    n="$(basename "$g" .ramus)"
    "$ramus" check "$g" >"$out/$n.check.txt" 2>&1 || true
    cp "$g" "$out/$n.fmt.ramus" && "$ramus" fmt "$out/$n.fmt.ramus" >/dev/null 2>&1 || true
    "$ramus" derive "$g" --skeleton "$out/$n.skeleton.json" >/dev/null 2>&1 || true
    "$ramus" build "$g" -o "$out/$n.glb" --lod 2 >/dev/null 2>&1 || true
    "$ramus" build "$g" -o "$out/$n.obj" >/dev/null 2>&1 || true
    "$ramus" build "$g" -o "$out/$n.ply" >/dev/null 2>&1 || true
    "$ramus" preview "$g" -o "$out/$n.png" >/dev/null 2>&1 || true
    "$ramus" preview "$g" -o "$out/$n.svg" >/dev/null 2>&1 || true
    "$ramus" build "$g" --target binary -o "$out/$n.rmb" >/dev/null 2>&1 || true
    if [ -f "$out/$n.rmb" ]; then
      "$ramus" dump "$out/$n.rmb" >"$out/$n.dump.txt" 2>&1 || true
      "$ramus" decompile "$out/$n.rmb" >"$out/$n.decompiled.ramus" 2>&1 || true
    fi
  done
  for g in examples/trees/*.ramus; do
    local n
    n="$(basename "$g" .ramus)"
    "$ramus" scan "$g" -o "$out/$n.scan.ply" --truth "$out/$n.truth.json" >/dev/null 2>&1 || true
    "$ramus" infer "$g" -o "$out/$n.inferred.ramus" --method skeleton >/dev/null 2>&1 || true
    "$ramus" propagate "$g" -n 2 -o "$out/$n.propagated" >/dev/null 2>&1 || true
  done
  for g in examples/pieces/*.ramus; do
    local n
    n="$(basename "$g" .ramus)"
    "$ramus" check "$g" >"$out/$n.check.txt" 2>&1 || true
    "$ramus" build "$g" --target pieces -o "$out/$n.pieces.glb" >/dev/null 2>&1 || true
    "$ramus" build "$g" --target binary -o "$out/$n.pieces.rmb" >/dev/null 2>&1 || true
  done
  for s in "$shared"/data/*.*; do
    local n
    n="$(basename "$s")"
    case "$n" in *.md) continue ;; esac
    "$ramus" inspect "$s" >"$out/$n.inspect.txt" 2>&1 || true
    "$ramus" reconstruct "$s" -o "$out/$n.bsg.json" >/dev/null 2>&1 || true
    "$ramus" reconstruct "$s" -o "$out/$n.flood.json" --method flood >/dev/null 2>&1 || true
    "$ramus" classify "$s" -o "$out/$n.classified.ply" >/dev/null 2>&1 || true
    "$ramus" infer "$s" -o "$out/$n.wavelet.ramus" --method wavelet >/dev/null 2>&1 || true
    "$ramus" infer "$s" -o "$out/$n.skeleton.ramus" --method skeleton >/dev/null 2>&1 || true
    "$ramus" compress "$s" >"$out/$n.compress.txt" 2>&1 || true
    "$ramus" symmetrize "$s" -o "$out/$n.symmetrized.ply" >/dev/null 2>&1 || true
  done
}

run_all "$old" "$work/old"
run_all "$new" "$work/new"
count="$(find "$work/old" -type f | wc -l)"
# Timings printed by a command are the only text allowed to differ.
if diff -r -q -I 'time\|[0-9] s$\|seconds' "$work/old" "$work/new" >"$work/diff.txt"; then
  echo "compare-outputs: $count outputs, all identical"
else
  cat "$work/diff.txt"
  echo "compare-outputs: outputs differ"
  exit 1
fi
