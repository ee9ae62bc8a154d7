#!/usr/bin/env bash
# CI's second half, run by `make test RAMUS_CI_EXTRA=1` after the suite (issue 22,
# docs/robustness.md): one clang
# build with ASan+UBSan (the clang-asan preset, build/clang-asan) serves both checks:
#   1. under the sanitizers, the unit tests of the libraries, the runtime and every fuzz corpus
#      replayed through its target's entry point (no suppressions: any report fails);
#   2. its `ramus` against GCC's (build/release) on the fixed set of scripts/compare-compilers.sh:
#      any sha256 that differs fails.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
jobs="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
start=$(date +%s)
cmake --preset clang-asan >/dev/null
mapfile -t fuzz < <(cd tests/fuzz && ls fuzz_*.cpp | sed 's/\.cpp$//')
cmake --build build/clang-asan -j "$jobs" --target ramus test_core test_formats test_grammar \
  test_compiler test_runtime runtime_c_api_smoke grow_mesh "${fuzz[@]}"
built=$(date +%s)
echo "ci-extra: clang ASan+UBSan build took $((built - start)) s"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
(cd build/clang-asan && ctest --output-on-failure -j "$jobs" -R '^(core|formats|grammar|compiler|runtime|fuzz):')
tested=$(date +%s)
echo "ci-extra: sanitizer tests took $((tested - built)) s"
bash scripts/compare-compilers.sh build/release/ramus build/clang-asan/ramus
echo "ci-extra: byte comparison took $(($(date +%s) - tested)) s; all $(($(date +%s) - start)) s"
