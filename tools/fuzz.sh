#!/usr/bin/env bash
# Fuzzes the glTF loader and validator for a bounded time (CI: about a minute).
#
#   bash tools/fuzz.sh [SECONDS]        (default 60; $VCT_CORPORA_DIR adds the public corpora as seeds)
#
# Builds tests/fuzz/gltf_fuzzer with clang, libFuzzer, ASan and UBSan into build-fuzz/, seeds it
# with tests/fuzz/seeds, tests/data/fuzz-regressions and every .gltf/.glb of the corpora, and runs
# it. Prints executions per second and in total. Exits non-zero on a finding (crash, sanitizer
# report, uncaught exception, hang, runaway allocation); the input is kept in build-fuzz/findings/
# and belongs, once fixed, in tests/data/fuzz-regressions/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build=build-fuzz

if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends clang libclang-rt-14-dev
fi

# Only the fuzzer's targets are built; the rest of the project is configured but not compiled.
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVCT_FUZZ=ON \
  ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build" --target gltf_fuzzer --parallel 2

# Seeds: only the glTF files of the corpora (their .bin/.png neighbours are not inputs on their own).
seeds="$build/seeds"
rm -rf "$seeds" && mkdir -p "$seeds" "$build/corpus" "$build/findings"
cp tests/fuzz/seeds/* "$seeds/"
if [ -d tests/data/fuzz-regressions ]; then
  find tests/data/fuzz-regressions -type f ! -name '*.md' -exec cp {} "$seeds/" \;
fi
if [ -n "${VCT_CORPORA_DIR:-}" ]; then
  n=0
  while IFS= read -r -d '' file; do
    n=$((n + 1))
    cp "$file" "$seeds/corpus-$n.${file##*.}"
  done < <(find "$VCT_CORPORA_DIR/gltf-validator" "$VCT_CORPORA_DIR/tinygltf-regressions" -type f \
                \( -name '*.gltf' -o -name '*.glb' \) -size -1024k -print0 | sort -z)
  echo "fuzz: $n seed files from $VCT_CORPORA_DIR"
else
  echo "fuzz: VCT_CORPORA_DIR is not set; seeding with the project's own files only"
fi

log="$build/fuzz.log"
status=0
# -timeout: one input taking longer is a hang. -rss_limit_mb/-malloc_limit_mb: a hostile length
# that makes the loader ask for gigabytes is a finding, not a machine out of memory.
"$build/tests/fuzz/gltf_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -malloc_limit_mb=1024 -max_len=65536 -dict=tests/fuzz/gltf.dict -print_final_stats=1 \
  -artifact_prefix="$build/findings/" "$build/corpus" "$seeds" >"$log" 2>&1 || status=$?

execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
echo "fuzz: ${execs:-?} executions in ${seconds} s, ${rate:-?} per second (log: $log)"
if [ "$status" -ne 0 ]; then
  grep -E "^==[0-9]+==ERROR|runtime error|SUMMARY|deadly signal|Test unit written" "$log" | head -20 || true
  echo "fuzz: FINDING (exit $status); inputs in $build/findings/:" && ls "$build/findings/"
  exit 1
fi
