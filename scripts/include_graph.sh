#!/usr/bin/env bash
# Draws docs/architecture.svg from the real include graph (units, layers as
# in docs/architecture.md). Needs graphviz (`dot`, Debian package graphviz).
set -euo pipefail
cd "$(dirname "$0")/.."
doc=docs/architecture.md
declare -A layer alias
while read -r n units; do n=${n%:}; for u in $units; do layer[$u]=$n; done; done \
  < <(sed -n '/^<!-- layers -->$/,/^<!-- \/layers -->$/p' "$doc" | grep -E '^    [0-9]+:')
for pair in $(sed -n '/^<!-- aliases -->$/,/^<!-- \/aliases -->$/p' "$doc" | grep -oE '[a-z_0-9]+=[a-z_0-9]+'); do
  alias[${pair%=*}]=${pair#*=}
done
unit_of() { local b; b=$(basename "$1"); b=${b%.*}; echo "${alias[$b]:-$b}"; }
{
  echo 'digraph fixel { rankdir=BT; node [shape=box, fontname="sans-serif", fontsize=11]; edge [color="#888888"];'
  for n in $(printf '%s\n' "${layer[@]}" | sort -un); do
    echo "  subgraph cluster_$n { label=\"layer $n\"; style=dashed; color=\"#bbbbbb\"; fontsize=10;"
    for u in "${!layer[@]}"; do [ "${layer[$u]}" = "$n" ] && echo "    \"$u\";"; done
    echo "  }"
  done
  for f in include/fixel/*.h include/fixel/internal/*.h src/*.cpp src/cli/*.cpp; do
    u=$(unit_of "$f")
    for dep in $(grep -oE '#include "fixel/[a-z_/0-9]+\.h"' "$f" | sed -E 's/#include "(fixel\/)?//; s/"$//'); do
      d=$(unit_of "$dep"); [ "$d" != "$u" ] && echo "  \"$u\" -> \"$d\";"
    done
  done | sort -u
  echo '}'
} > build-include-graph.dot
dot -Tsvg build-include-graph.dot -o docs/architecture.svg
rm build-include-graph.dot
echo "wrote docs/architecture.svg"
