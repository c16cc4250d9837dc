#!/usr/bin/env bash
# Proof that a refactor changes no answer: run two rollbench binaries on every shipped deck
# (and --set variants of speeds, loads, clearance and laminae) and compare their
# `run --format json` field by field (benches/json_compare.py, the rule of json-diff in linear time) (1e-9 of each field's largest magnitude;
# wall times and solver statistics aside).
#
#   benches/refactor_check.sh BEFORE_BIN AFTER_BIN [JSON_DIFF]
#
# Build BEFORE_BIN from the commit before the change (git worktree add /tmp/before <rev> &&
# cargo build --release there). Exit 0 when every case agrees.
set -uo pipefail
before=${1:?before binary}; after=${2:?after binary}
diff_tool=${3:-$(dirname "$0")/json_compare.py}
cd "$(dirname "$0")/.."
out=$(mktemp -d)
variants=(
  ""
  "--set operating.inner_speed=5000"
  "--set operating.outer_speed=3000"
  "--set operating.radial_load=100"
  "--set operating.axial_load=2000"
  "--set geometry.diametral_clearance=0"
  "--set solver.laminae=21"
  "--set solver.laminae=151"
  "--set nope=1"
  "--set geometry.roller_count=1"
)
fail=0; n=0
for deck in decks/*.toml; do
  for v in "${variants[@]}"; do
    n=$((n + 1))
    # shellcheck disable=SC2086
    "$before" run "$deck" --format json $v >"$out/b.json" 2>"$out/b.err"; rb=$?
    # shellcheck disable=SC2086
    "$after" run "$deck" --format json $v >"$out/a.json" 2>"$out/a.err"; ra=$?
    if [ "$rb" != "$ra" ]; then
      echo "DIFF exit $rb -> $ra: $deck $v"; fail=$((fail + 1)); continue
    fi
    if [ "$rb" != 0 ]; then
      if ! cmp -s "$out/b.err" "$out/a.err"; then
        echo "DIFF message: $deck $v"; diff "$out/b.err" "$out/a.err" | head -5; fail=$((fail + 1))
      fi
      continue
    fi
    if ! "$diff_tool" "$out/b.json" "$out/a.json" >"$out/d.txt" 2>&1; then
      echo "DIFF json: $deck $v"; head -8 "$out/d.txt"; fail=$((fail + 1))
    fi
  done
done
echo "$n cases, $fail differ"
rm -rf "$out"
[ "$fail" = 0 ]
