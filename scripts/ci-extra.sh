#!/usr/bin/env bash
# CI's second half, run by `make test` after the suite (RAMUS_CI_EXTRA=0 skips it; issue 22,
# docs/robustness.md): one clang build with ASan+UBSan (the clang-asan preset,
# build/clang-asan) serves both checks:
#   1. under the sanitizers, the unit tests of the libraries and the runtime, every fuzz corpus
#      replayed through its target's entry point, and the bad-input tests of every other folder
#      (the command line's among them, which run this build's `ramus`); no suppressions: any
#      report fails;
#   2. its `ramus` against GCC's (build/release) on the fixed set of scripts/compare-compilers.sh:
#      any sha256 that differs fails.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
jobs="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
start=$(date +%s)
cmake --preset clang-asan >/dev/null
mapfile -t fuzz < <(cd tests/fuzz && ls fuzz_*.cpp | sed 's/\.cpp$//')
# The folders whose bad-input tests run (below); assets/ and forest/ test external programs
# (browsers, engines, GNU parallel) on good input, layout/ the source tree.
checked=(mesh backends cli pieces skeleton_infer flood wavelet binary reconstruct wood shape lsp)
cmake --build build/clang-asan -j "$jobs" --target ramus test_core test_formats test_grammar \
  test_compiler test_runtime runtime_c_api_smoke grow_mesh "${fuzz[@]}" "${checked[@]/#/test_}"
built=$(date +%s)
echo "ci-extra: clang ASan+UBSan build took $((built - start)) s"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# Unit folders whole; elsewhere the tests about bad input by their names.
unit='^(core|formats|grammar|compiler|runtime|fuzz):'
bad="^($(IFS='|'; echo "${checked[*]}")):.*([Bb]ad |[Bb]roken|damaged|[Tt]runcat|malformed|garbage|refuse|reject|errors?( |$)|limits:|degenerate|no tree)"
(cd build/clang-asan && ctest --output-on-failure -j "$jobs" -R "$unit|$bad")
tested=$(date +%s)
echo "ci-extra: sanitizer tests took $((tested - built)) s"
bash scripts/compare-compilers.sh build/release/ramus build/clang-asan/ramus
echo "ci-extra: byte comparison took $(($(date +%s) - tested)) s; all $(($(date +%s) - start)) s"
