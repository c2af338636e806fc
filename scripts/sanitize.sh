#!/usr/bin/env bash
# Builds the library, CLI and tests with AddressSanitizer and
# UndefinedBehaviorSanitizer under build-asan/ and runs the whole test suite
# there (FIXEL_SANITIZE=ON; benchmarks and the install round trip are skipped).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# -O1 without debug info: the build (CGAL templates) dominates the time.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DFIXEL_SANITIZE=ON \
  -DFIXEL_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build build-asan -j "$(nproc)" > /dev/null
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
