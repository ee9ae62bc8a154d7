#!/usr/bin/env bash
# Same bytes everywhere (issue 22 point 6): builds ramus with GCC (build/release) and with clang
# (the clang-release preset, build/clang), runs both over a fixed set of commands and compares
# the sha256 of what they write: every example's .glb, .rmb and `derive --print`, every pieces
# example's .glb, a reconstruction and two inferences (wavelet and skeleton) of a bundled scan.
#   scripts/compare-compilers.sh [GCC_RAMUS CLANG_RAMUS]   (default: build both)
# Exit 0 when every output is identical, 1 otherwise (the differing outputs are listed).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
shared="$(realpath "${RAMUS_SHARED_DIR:-$root/../shared}")"
jobs="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
if [ $# -ge 2 ]; then
  gcc_ramus="$(realpath "$1")"
  clang_ramus="$(realpath "$2")"
else
  cmake --preset release >/dev/null
  cmake --build build/release -j "$jobs" --target ramus
  cmake --preset clang-release >/dev/null
  start=$(date +%s)
  cmake --build build/clang -j "$jobs" --target ramus
  echo "compare-compilers: clang build of ramus took $(($(date +%s) - start)) s"
  gcc_ramus="$root/build/release/ramus"
  clang_ramus="$root/build/clang/ramus"
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# run_set RAMUS OUTDIR: the fixed set; a command that fails leaves its output missing, which
# shows as a difference only when the other compiler's build succeeded.
run_set() {
  local ramus="$1" out="$2" g n
  mkdir -p "$out"
  for g in examples/abop/*.ramus examples/trees/*.ramus; do
    n="$(basename "$g" .ramus)"
    "$ramus" build "$g" -o "$out/$n.glb" >/dev/null 2>&1 || echo "failed: build $g" >>"$out/failures.txt"
    "$ramus" build "$g" --target binary -o "$out/$n.rmb" >/dev/null 2>&1 ||
      echo "failed: build --target binary $g" >>"$out/failures.txt"
    "$ramus" derive "$g" --print >"$out/$n.derive.txt" 2>&1 || echo "failed: derive $g" >>"$out/failures.txt"
  done
  for g in examples/pieces/*.ramus; do
    n="$(basename "$g" .ramus)"
    "$ramus" build "$g" --target pieces -o "$out/$n.pieces.glb" >/dev/null 2>&1 ||
      echo "failed: build --target pieces $g" >>"$out/failures.txt"
  done
  local scan="$shared/data/adtree_tree1.xyz"
  "$ramus" reconstruct "$scan" -o "$out/reconstruct.json" >/dev/null 2>&1 || echo "failed: reconstruct" >>"$out/failures.txt"
  "$ramus" infer "$scan" --method wavelet -o "$out/infer_wavelet.ramus" >/dev/null 2>&1 ||
    echo "failed: infer wavelet" >>"$out/failures.txt"
  "$ramus" infer examples/trees/conifer.ramus --method skeleton -o "$out/infer_skeleton.ramus" >/dev/null 2>&1 ||
    echo "failed: infer skeleton" >>"$out/failures.txt"
  (cd "$out" && sha256sum -- * >"../$(basename "$out").sha256")
}

run_set "$gcc_ramus" "$work/gcc"
run_set "$clang_ramus" "$work/clang"
count="$(wc -l <"$work/gcc.sha256")"
if [ -f "$work/gcc/failures.txt" ]; then
  echo "compare-compilers: commands failed with GCC's build:"
  cat "$work/gcc/failures.txt"
fi
if diff "$work/gcc.sha256" "$work/clang.sha256" >"$work/diff.txt"; then
  echo "compare-compilers: $count outputs, identical sha256 from GCC and clang"
else
  echo "compare-compilers: outputs differ between GCC (<) and clang (>):"
  cat "$work/diff.txt"
  exit 1
fi
