#!/usr/bin/env bash
# Builds the CPU-side tests (vct_cpu_tests: glTF loading and validation, file policy, image files,
# path tracer) with AddressSanitizer and UndefinedBehaviorSanitizer into build-asan/ and runs them,
# over the public corpora too when $VCT_CORPORA_DIR is set. Any sanitizer report fails the run.
#
#   bash tools/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
# halt_on_error / abort: a report ends the test binary with a failure instead of scrolling past.
export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:abort_on_error=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

start=$SECONDS
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVCT_SANITIZE=ON ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build" --target vct_cpu_tests --parallel 2
[ -n "${VCT_CORPORA_DIR:-}" ] || echo "sanitize: VCT_CORPORA_DIR is not set; the corpus tests will skip"
# The whole log stays in build-asan/cpu_tests.log; the summary, failures and reports are shown.
"$build/tests/vct_cpu_tests" 2>&1 | tee "$build/cpu_tests.log" |
  grep -E '^\[  (PASSED|FAILED|SKIPPED) |^\[==========\]|Failure$|runtime error|ERROR: (Address|Leak)Sanitizer'
echo "sanitize: vct_cpu_tests passed under ASan+UBSan in $((SECONDS - start)) s (build included)"
