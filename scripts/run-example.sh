#!/usr/bin/env bash
# The README's main-job command: install what is missing, build, and run fixel
# on the bundled Example 2 scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/fixel seat data/scenes/example2.json --impulse -1,-1,-1
