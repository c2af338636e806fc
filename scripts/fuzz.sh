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
# Measured execution counts (2 shared cores, -O1, ASan + UBSan; see
# docs/performance.md): see the figures there. Both targets together stay far
# below 10^6 executions per 60 s CI run (the structured target runs the exact
# pipeline, milliseconds per input), so run a nightly-style longer campaign
# with e.g. FUZZ_SECONDS=3600 scripts/fuzz.sh.
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
