#!/usr/bin/env bash
# The README's main-job command: install what is missing, build, and compute
# the pushing region of the bundled Example 2 part (rounded rectangle),
# printing it and drawing it to example2_rounded.svg.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/fixel region data/scenes/example2_rounded.json --resolution 1/4096 --svg example2_rounded.svg
