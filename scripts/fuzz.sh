#!/usr/bin/env bash
# Builds the two libFuzzer targets with clang (ASan + UBSan) under build-fuzz/
# and runs each for half of FUZZ_SECONDS (default 60, so 30 s each):
#   scene_fuzz       arbitrary bytes into the JSON loader, seat and region;
#                    corpus seeded from data/scenes/ and tests/fuzz_regressions/.
#   structured_fuzz  bytes choose the numbers of a scene that always parses
#                    (fuzz/structured.h), then seat, outcomes, simulate,
#                    seat-and-stay, region, sample and the guaranteed set run;
#                    corpus seeded from data/scenes/ (as raw bytes) and
#                    tests/fuzz_regressions/structured/.
# Crashing inputs are written to build-fuzz/crashes/<target>-*; keep each one
# as a regression input: scene_fuzz ones as tests/fuzz_regressions/*.json,
# structured_fuzz ones as tests/fuzz_regressions/structured/*.bin
# (fuzz_regressions_test replays both).
#
# Measured execution counts per 30 s (2 shared cores, load about 2, -O1,
# ASan + UBSan; docs/performance.md): scene_fuzz 29,000-57,000 (950-1,850/s),
# structured_fuzz 150-375 (5-12/s: the exact pipeline takes 80-200 ms per
# input under the sanitizers). That is far below 10^6 per 60 s CI run, so run
# a nightly-style campaign for that: FUZZ_SECONDS=3600 scripts/fuzz.sh
# (about 1.7-3.3 million + 9,000-22,000 executions at these rates).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-60}"
half=$(( seconds / 2 ))
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1" -DCMAKE_CXX_COMPILER=clang++ -DFIXEL_FUZZ=ON \
  -DFIXEL_BUILD_TESTS=OFF -DFIXEL_BUILD_BENCHMARKS=OFF -DFIXEL_BUILD_CLI=OFF > /dev/null
cmake --build build-fuzz -j "$(nproc)" --target scene_fuzz structured_fuzz > /dev/null
mkdir -p build-fuzz/corpus build-fuzz/corpus-structured build-fuzz/crashes
cp data/scenes/*.json build-fuzz/corpus/
cp data/scenes/*.json build-fuzz/corpus-structured/
[ -d tests/fuzz_regressions ] && cp tests/fuzz_regressions/*.json build-fuzz/corpus/ 2>/dev/null || true
[ -d tests/fuzz_regressions/structured ] && cp tests/fuzz_regressions/structured/* build-fuzz/corpus-structured/ 2>/dev/null || true
status=0
for target in scene_fuzz structured_fuzz; do
  corpus=build-fuzz/corpus; [ "$target" = structured_fuzz ] && corpus=build-fuzz/corpus-structured
  echo "== $target ($half s)"
  ./build-fuzz/fuzz/$target "$corpus" -max_total_time="$half" -timeout=10 -max_len=4096 \
    -artifact_prefix=build-fuzz/crashes/$target- -print_final_stats=1 > build-fuzz/$target.log 2>&1 || status=1
  tail -n 12 build-fuzz/$target.log
done
exit $status
