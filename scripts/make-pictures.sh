#!/usr/bin/env bash
# Redraws the bundled pictures in docs/ with the built CLI (build/fixel) and
# rsvg-convert (librsvg2-bin, installed by scripts/install-deps.sh).
#   bash scripts/make-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
fixel="${1:-build}/fixel"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for part in example2_rounded blob polygon; do
  "$fixel" region "data/scenes/$part.json" --svg "$tmp/region_$part.svg" --quiet > /dev/null
  rsvg-convert --background-color=white "$tmp/region_$part.svg" -o "docs/region_$part.png"
done
# The README's --guaranteed example: the slice through its impulse.
"$fixel" seat data/scenes/nonunique.json --guaranteed --impulse 29157/10540,-71119/105400,-1169839/263500 \
  --svg "$tmp/guaranteed.svg" > /dev/null
rsvg-convert --background-color=white "$tmp/guaranteed.svg" -o docs/guaranteed_nonunique.png
echo "wrote docs/region_{example2_rounded,blob,polygon}.png and docs/guaranteed_nonunique.png"
