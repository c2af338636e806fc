#!/usr/bin/env bash
# Byte-identity check for refactors: runs every command on every bundled
# scene with two fixel binaries and compares stdout, stderr, exit codes and
# written files. Wall-clock figures ("seconds", "... s") are masked.
#   bash tests/compare_outputs.sh OLD_FIXEL NEW_FIXEL [SOURCE_DIR]
set -u
old=$(realpath "$1"); new=$(realpath "$2"); src=$(realpath "${3:-$(dirname "$0")/..}")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0; count=0
mask() { sed -E 's/"seconds": [0-9.e+-]+/"seconds": X/; s/, [0-9.e+-]+ s$/, X s/'; }
run() {  # run NAME ARGS... with both binaries, in separate directories
  local name="$1"; shift
  count=$((count + 1))
  for which in old new; do
    local bin; bin=$([ "$which" = old ] && echo "$old" || echo "$new")
    mkdir -p "$tmp/$which/$name"
    (cd "$tmp/$which/$name" && "$bin" "$@" > stdout 2> stderr; echo $? > rc)
    mask < "$tmp/$which/$name/stdout" > "$tmp/$which/$name/stdout.m"; rm "$tmp/$which/$name/stdout"
  done
  # OFF triangulations come from CGAL's randomised hull: compare vertex sets.
  local off
  for off in $(find "$tmp/old/$name" "$tmp/new/$name" -name "*.off"); do
    grep -E "^-?[0-9.e+-]+ -?[0-9.e+-]+ -?[0-9.e+-]+$" "$off" | sort > "$off.v"; rm "$off"
  done
  if ! diff -r "$tmp/old/$name" "$tmp/new/$name" > "$tmp/diff" 2>&1; then
    echo "DIFFERS: $*"; head -20 "$tmp/diff"; fail=1
  fi
}
for f in "$src"/data/scenes/*.json; do
  s=$(basename "$f" .json)
  dof=$(grep -o '"dof": *"[23]"' "$f" | grep -o '[23]')
  imp=$([ "$dof" = 2 ] && echo "-1,-1" || echo "-1,-1,-1")
  run "$s-seat" seat "$f"
  run "$s-seat-json" seat "$f" --json --impulse "$imp"
  run "$s-seat-stable" seat "$f" --stable --impulse "$imp"
  run "$s-simulate" simulate "$f" --impulse "$imp" --steps 3 --json
  run "$s-solutions" solutions "$f" --impulse "$imp"
  run "$s-dump" dump "$f" --off out
  if grep -q '"boundary"' "$f"; then
    run "$s-region" region "$f" --resolution 1/256 --svg r.svg
    run "$s-region-json" region "$f" --json --cone paper --resolution 1/128
    run "$s-region-mu" region "$f" --pusher-mu 1/10 --resolution 1/128
    run "$s-sample" sample "$f" --points 16 --json
    run "$s-sustained-region" region "$f" --push sustained --resolution 1/64 --svg j.svg
    run "$s-sustained-region-json" region "$f" --push sustained --resolution 1/64 --json
    run "$s-push" push "$f" --wrench "$imp" --time 2 --json
    run "$s-push-plan" push-plan "$f" --at 0:1/2 --json
  fi
  if grep -q '"boundary"' "$f" && [ "$dof" = 3 ]; then
    run "$s-approach-region" region "$f" --push sustained --approach --resolution 1/64 --json
  fi
  if [ "$dof" = 3 ]; then
    run "$s-sustained" seat "$f" --sustained --wrench -1,-1,0
    run "$s-sustained-json" seat "$f" --sustained --json --wrench 0,1,0
    run "$s-dump-sustained" dump "$f" --off out --sustained
  fi
done
run nonunique-guaranteed seat "$src/data/scenes/nonunique.json" --guaranteed --json
run nonunique-part-region-g region "$src/data/scenes/nonunique_part.json" --guaranteed --resolution 1/64
run nonunique-seat-svg seat "$src/data/scenes/nonunique.json" --guaranteed --svg g.svg --impulse -1,-1,-1
run region-zero-resolution region "$src/data/scenes/blob.json" --resolution 0
run sample-zero-points sample "$src/data/scenes/blob.json" --points 0
run simulate-zero-steps simulate "$src/data/scenes/example2.json" --impulse -1,-1,-1 --steps 0
run dump-bad-length dump "$src/data/scenes/example2.json" --off out --length -1
run verify verify
echo "$count commands compared"
exit $fail
