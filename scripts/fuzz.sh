#!/usr/bin/env bash
# Builds the libFuzzer target with clang (ASan + UBSan) under build-fuzz/ and
# runs it for FUZZ_SECONDS (default 60) on a corpus seeded from data/scenes/.
# Crashing inputs are written to build-fuzz/crashes/; keep each one as a
# regression test in tests/fuzz_regressions/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-60}"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1" -DCMAKE_CXX_COMPILER=clang++ -DFIXEL_FUZZ=ON \
  -DFIXEL_BUILD_TESTS=OFF -DFIXEL_BUILD_BENCHMARKS=OFF -DFIXEL_BUILD_CLI=OFF > /dev/null
cmake --build build-fuzz -j "$(nproc)" --target scene_fuzz > /dev/null
mkdir -p build-fuzz/corpus build-fuzz/crashes
cp data/scenes/*.json build-fuzz/corpus/
[ -d tests/fuzz_regressions ] && cp tests/fuzz_regressions/* build-fuzz/corpus/ 2>/dev/null || true
./build-fuzz/fuzz/scene_fuzz build-fuzz/corpus -max_total_time="$seconds" -timeout=10 -max_len=4096 \
  -artifact_prefix=build-fuzz/crashes/ -print_final_stats=1 2>&1 | tail -n 25
