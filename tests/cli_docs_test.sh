#!/usr/bin/env bash
# docs/cli.md must document every command and every option that --help lists.
set -u
fixel="$1"; doc="$2/docs/cli.md"; fail=0
cmds=$("$fixel" --help | awk '/^Subcommands:/{on=1; next} on && NF {print $1}')
# Guard against a vacuous pass if the help format changes.
[ "$(wc -w <<<"$cmds")" -ge 7 ] || { echo "FAIL: found only '$cmds' in fixel --help"; exit 1; }
for cmd in $cmds; do
  grep -q "^## $cmd\$" "$doc" || { echo "FAIL: docs/cli.md has no section for '$cmd'"; fail=1; }
  for opt in $("$fixel" "$cmd" --help | grep -oE -- '--[a-z][a-z-]*' | sort -u); do
    [ "$opt" = "--help" ] && continue
    grep -qF -- "$opt" "$doc" || { echo "FAIL: docs/cli.md does not mention $cmd $opt"; fail=1; }
  done
done
exit $fail
