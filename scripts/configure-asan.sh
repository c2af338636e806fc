#!/usr/bin/env bash
# Configures build-asan/: the one instrumented tree of CI. clang with
# AddressSanitizer + UndefinedBehaviorSanitizer on everything, libFuzzer's
# coverage on everything (FIXEL_FUZZ=ON; only the fuzz/ targets link
# libFuzzer's main), -O1 without debug info (the CGAL templates dominate the
# build time). scripts/sanitize.sh builds it all and runs the suite there;
# scripts/fuzz.sh runs the fuzz targets from the same tree. No benchmarks,
# no Python module (an instrumented module cannot be loaded by the system
# interpreter), no install round trip.
set -euo pipefail
cd "$(dirname "$0")/.."
# A tree configured with another compiler (GCC, before) cannot switch in place.
if [ -f build-asan/CMakeCache.txt ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' build-asan/CMakeCache.txt; then
  rm -rf build-asan
fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++ -DFIXEL_FUZZ=ON -DFIXEL_BUILD_BENCHMARKS=OFF -DFIXEL_BUILD_PYTHON=OFF "$@" > /dev/null
