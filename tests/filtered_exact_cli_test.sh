#!/usr/bin/env bash
# Issue 12's differential test across the whole command line: every command
# of compare_outputs.sh on every bundled scene gives the same output, byte
# for byte (wall times masked), with the filters on and with every decision
# forced exact (FIXEL_FORCE_EXACT=1).
#   bash tests/filtered_exact_cli_test.sh FIXEL SOURCE_DIR
set -euo pipefail
fixel=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf '#!/usr/bin/env bash\nFIXEL_FORCE_EXACT=1 exec "%s" "$@"\n' "$fixel" > "$tmp/exact_fixel"
chmod +x "$tmp/exact_fixel"
# The comparison must be of two paths: the plain binary certifies decisions
# by its filters, and the wrapper certifies none.
certified() { FIXEL_FILTER_STATS=1 "$1" region "$src/data/scenes/blob32.json" --quiet 2>&1 >/dev/null | grep -Eq ' [1-9][0-9]*/'; }
certified "$fixel" || { echo "FAIL: the filtered binary certified no decision (is FIXEL_FORCE_EXACT set?)"; exit 1; }
if certified "$tmp/exact_fixel"; then echo "FAIL: FIXEL_FORCE_EXACT=1 still certified decisions by filters"; exit 1; fi
bash "$src/tests/compare_outputs.sh" "$tmp/exact_fixel" "$fixel" "$src"
