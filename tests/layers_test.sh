#!/usr/bin/env bash
# The include graph has no upward arrow: every unit includes only units of
# its own layer or below, in the order documented in docs/architecture.md
# (the indented "N: units" block and the "alias=unit" line there).
#   bash tests/layers_test.sh [SOURCE_DIR]
set -u
src="${1:-$(dirname "$0")/..}"; doc="$src/docs/architecture.md"; fail=0
declare -A layer alias
while read -r n units; do
  n=${n%:}
  for u in $units; do layer[$u]=$n; done
done < <(sed -n '/^<!-- layers -->$/,/^<!-- \/layers -->$/p' "$doc" | grep -E '^    [0-9]+:')
for pair in $(sed -n '/^<!-- aliases -->$/,/^<!-- \/aliases -->$/p' "$doc" | grep -oE '[a-z_0-9]+=[a-z_0-9]+'); do
  alias[${pair%=*}]=${pair#*=}
done
[ "${#layer[@]}" -ge 10 ] || { echo "FAIL: could not read the layer table of $doc"; exit 1; }
unit_of() { local b; b=$(basename "$1"); b=${b%.*}; echo "${alias[$b]:-$b}"; }
files=$(cd "$src" && ls include/fixel/*.h include/fixel/internal/*.h src/*.cpp src/cli/*.cpp)
edges=0
for f in $files; do
  u=$(unit_of "$f")
  [ -n "${layer[$u]:-}" ] || { echo "FAIL: $f (unit $u) has no layer in docs/architecture.md"; fail=1; continue; }
  for dep in $(grep -oE '#include "fixel/[a-z_/0-9]+\.h"' "$src/$f" | sed -E 's/#include "(fixel\/)?//; s/"$//'); do
    d=$(unit_of "$dep")
    edges=$((edges + 1))
    [ -n "${layer[$d]:-}" ] || { echo "FAIL: $f includes $dep (unit $d) with no layer"; fail=1; continue; }
    if [ "${layer[$d]}" -gt "${layer[$u]}" ]; then
      echo "FAIL: upward include: $f (unit $u, layer ${layer[$u]}) includes $dep (unit $d, layer ${layer[$d]})"
      fail=1
    fi
  done
done
[ "$edges" -ge 50 ] || { echo "FAIL: only $edges includes found"; exit 1; }
[ $fail -eq 0 ] && echo "layers: $edges includes checked, none upward"
exit $fail
