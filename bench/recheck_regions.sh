#!/usr/bin/env bash
# The sustained regions (J, and J' where it has pushes) of every scene in a
# folder, validated in Box2D at the default engine settings and again on a
# finer engine (docs/physics.md, "Engine settings"): one line per region
# with both counts, then the totals. For the scenes the physics studies
# write with --dump.
#
#   bash bench/recheck_regions.sh FIXEL DIR [PUSHES]
set -euo pipefail
fixel="$1" dir="$2" pushes="${3:-5}"
finer=(--steps-per-h 16000 --velocity-iterations 100 --position-iterations 50)
counts() { "$fixel" region "$@" --quiet 2>/dev/null | sed -n 's/^validation .*iterations): //p'; }
declare -A seated finer_seated total parts
for f in "$dir"/*.json; do
  for target in J "J'"; do
    extra=(); [ "$target" = "J'" ] && extra=(--approach)
    base=(--push sustained "${extra[@]}" --resolution 1/256 --validate "$pushes")
    d=$(counts "$f" "${base[@]}" || true)
    case "$d" in "" | "0 of 0"*) continue ;; esac
    e=$(counts "$f" "${base[@]}" "${finer[@]}")
    echo "$(basename "$f" .json) $target | default: $d | finer: $e"
    read -r s _ n _ <<<"$d"; read -r fs _ _ _ <<<"$e"
    seated[$target]=$((${seated[$target]:-0} + s)); finer_seated[$target]=$((${finer_seated[$target]:-0} + fs))
    total[$target]=$((${total[$target]:-0} + n)); parts[$target]=$((${parts[$target]:-0} + 1))
  done
done
for target in J "J'"; do
  [ -n "${total[$target]:-}" ] || continue
  echo "$target: ${parts[$target]} regions, seated ${seated[$target]} of ${total[$target]} at the default settings, ${finer_seated[$target]} on the finer engine"
done
