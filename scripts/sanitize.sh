#!/usr/bin/env bash
# Builds the library, CLI, tests and fuzz targets with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer under build-asan/ (scripts/configure-asan.sh)
# and runs the whole test suite there (benchmarks, the Python module and the
# install round trip are skipped). scripts/fuzz.sh then runs the fuzz
# targets built here, so CI builds the library twice, not three times.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/configure-asan.sh
cmake --build build-asan -j "$(nproc)" > /dev/null
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
