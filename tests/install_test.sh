#!/usr/bin/env bash
# Install-and-consume round trip: install the built tree to a temporary
# prefix, build examples/consumer against it with find_package(fixel), run it.
set -euo pipefail
build="$1"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > /dev/null
# Installed headers must not mention the build or source tree.
if grep -rl -e "$src" -e "$build" "$tmp/prefix/include" > /dev/null 2>&1; then
  echo "FAIL: installed headers mention the build tree"; exit 1
fi
# CGAL, Box2D, FLINT and Arb stay inside the library's sources: no installed
# header includes them (a consumer would then need their headers).
if grep -rEn '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"](CGAL/|box2d/|flint/|arb|acb|fmpz|fmpq)' "$tmp/prefix/include"; then
  echo "FAIL: an installed header includes CGAL, Box2D, FLINT or Arb"; exit 1
fi
test -f "$tmp/prefix/include/fixel/region.h"  # the grep above read the headers
cmake -S "$src/examples/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$tmp/consumer" -j 2 > /dev/null
out=$("$tmp/consumer/consumer")
echo "$out"
grep -q "impulse (-1, -1, -1) is in S" <<<"$out"
grep -q "right edge: " <<<"$out"
test -x "$tmp/prefix/bin/fixel"
# CGAL is private to the library's .cpp files: the installed package neither
# looks for it nor names its target, and a consumer builds and runs on a
# machine view where CGAL's CMake files are hidden and find_package(CGAL) is
# disabled (it would fail if the config still asked for CGAL).
if cat "$tmp/prefix"/lib*/cmake/fixel/*.cmake | grep -v '^ *#' | grep "CGAL"; then
  echo "FAIL: the installed CMake package uses CGAL"; exit 1
fi
# Every directory holding CGALConfig.cmake, also through the /lib -> /usr/lib link.
hide=""
for d in $(find /usr/lib /usr/share /usr/local -name CGALConfig.cmake -exec dirname {} \; 2>/dev/null); do
  hide="$hide;$d;${d#/usr}"
done
cmake -S "$src/examples/consumer" -B "$tmp/consumer-nocgal" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release \
  --no-warn-unused-cli -DCGAL_DIR=/nonexistent -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON \
  -DCMAKE_IGNORE_PATH="${hide#;}" -DCMAKE_IGNORE_PREFIX_PATH="${hide#;}" > /dev/null
if grep -q "^CGAL_DIR:PATH=/" "$tmp/consumer-nocgal/CMakeCache.txt"; then
  echo "FAIL: the consumer found CGAL"; exit 1
fi
cmake --build "$tmp/consumer-nocgal" -j 2 > /dev/null
"$tmp/consumer-nocgal/consumer" | grep -q "impulse (-1, -1, -1) is in S"
echo "consumer without CGAL's CMake files: configured, built and ran"
# pkg-config, without CMake: the same program from the installed fixel.pc alone.
pc_dir=$(dirname "$(find "$tmp/prefix" -name fixel.pc)")
c++ -std=c++17 -O1 -o "$tmp/consumer-pc" "$src/examples/consumer/main.cpp" $(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs fixel)
"$tmp/consumer-pc" | grep -q "impulse (-1, -1, -1) is in S"
echo "consumer built with pkg-config: ran"
# The Python package, when built, is installed and importable from the prefix.
pkg=$(find "$tmp/prefix/lib" -path '*dist-packages/fixel' -type d 2>/dev/null | head -1)
if [ -n "$pkg" ]; then
  (cd "$tmp" && PYTHONPATH=$(dirname "$pkg") /usr/bin/python3 -c \
    "import fixel; S = fixel.seating_set(fixel.Scene.load('$src/data/scenes/example2.json')); assert S.contains((-1, -1, -1)); print('python: import fixel from', fixel.__file__)")
fi
# Added by a parent with add_subdirectory and no build type, fixel's own
# sources get -O2 (CMakeLists.txt); the parent keeps its empty build type and
# its own targets get no -O flag. Configured only: the flags are in the
# generated files.
mkdir -p "$tmp/parent"
printf 'int main() { return 0; }\n' > "$tmp/parent/main.cpp"
cat > "$tmp/parent/CMakeLists.txt" <<PARENT
cmake_minimum_required(VERSION 3.16)
project(parent LANGUAGES CXX)
add_subdirectory("$src" fixel)
add_executable(parent_main main.cpp)
target_link_libraries(parent_main PRIVATE fixel::fixel)
PARENT
CXXFLAGS= cmake -S "$tmp/parent" -B "$tmp/parent-build" -G "Unix Makefiles" -DFIXEL_BUILD_PYTHON=OFF -DFIXEL_BUILD_CLI=OFF > /dev/null
grep -q "^CMAKE_BUILD_TYPE:STRING=$" "$tmp/parent-build/CMakeCache.txt"
grep -q -- "-O2" "$tmp/parent-build/fixel/CMakeFiles/fixel.dir/flags.make"
if grep -q -- "-O[0-9s]" "$tmp/parent-build/CMakeFiles/parent_main.dir/flags.make"; then
  echo "FAIL: the parent's own target got an -O flag"; exit 1
fi
# A parent that chose its own -O flag keeps it for fixel too.
CXXFLAGS= cmake -S "$tmp/parent" -B "$tmp/parent-o0" -G "Unix Makefiles" -DFIXEL_BUILD_PYTHON=OFF -DFIXEL_BUILD_CLI=OFF \
  -DCMAKE_CXX_FLAGS="-O0 -g" > /dev/null
if grep -q -- "-O2" "$tmp/parent-o0/fixel/CMakeFiles/fixel.dir/flags.make"; then
  echo "FAIL: fixel overrode the parent's own -O0"; exit 1
fi
echo "add_subdirectory without a build type: fixel's library at -O2, the parent's untouched; a parent's -O0 kept"
