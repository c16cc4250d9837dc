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
# Variants every deck gets (spherical keys; on the other systems they are unknown keys,
# so their error messages are compared too), then each system's own.
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
ball_variants=(
  "--set operating.radial_load=500"
  "--set dynamics.method=quasi-static"
  "--set dynamics.method=time-simulation --set dynamics.orbits=2"
  "--set dynamics.method=time-simulation --set dynamics.orbits=2 --set dynamics.orbit=cage"
  "--set kinematics.race_control=inner --set operating.radial_load=200"
  "--set traction.curve=rheology"
  "--set operating.preload_mode=force"
  "--set geometry.ball_count=7"
)
tapered_variants=(
  "--set operating.inner_speed=38000 --set operating.radial_load=700"
  "--set solver.slices=21"
  "--set geometry.end_play=0.001"
  "--set operating.misalignment_x=0.0005"
  "--set operating.axial_load=-3000"
  "--set pedestal.stiffness_x=1e6"
)
# Cylindrical: the film off (the Nyström pair), the steady film (the pair with the film),
# contact loss (ρ = 0: events), the printed squeeze.
cylindrical_variants=(
  "--set dynamics.film_in_deflection=false"
  "--set dynamics.squeeze=none"
  "--set geometry.radial_interference=0 --set dynamics.film_in_deflection=false"
  "--set dynamics.squeeze=printed --set dynamics.revolutions=40"
)
fail=0; n=0
for deck in decks/*.toml; do
  own=()
  case "$(grep -m1 '^type' "$deck")" in
    *angular-contact-ball*) own=("${ball_variants[@]}") ;;
    *tapered-roller*) own=("${tapered_variants[@]}") ;;
    *cylindrical-roller*) own=("${cylindrical_variants[@]}") ;;
  esac
  for v in "${variants[@]}" "${own[@]}"; do
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
# The other commands' text output: keys tables, templates, stiffness, a sweep.
for cmd in "keys" "keys --type angular-contact-ball" "keys --type tapered-roller" \
  "template" "template --type angular-contact-ball --units si" "template --type tapered-roller" \
  "stiffness decks/trb_afapl.toml" "stiffness decks/aerospace.toml" \
  "sweep decks/trb_afapl.toml --set-range operating.inner_speed=0:20000:5000" \
  "sweep decks/chen_a.toml --set-range operating.axial_load=500:1500:500" \
  "run decks/aerospace.toml --format text" "run decks/chen_b.toml --format csv"; do
  n=$((n + 1))
  # shellcheck disable=SC2086
  "$before" $cmd >"$out/b.txt" 2>&1; rb=$?
  # shellcheck disable=SC2086
  "$after" $cmd >"$out/a.txt" 2>&1; ra=$?
  # wall times differ between runs: drop lines that report them
  if [ "$rb" != "$ra" ] || ! diff <(grep -v -i -E 'time|[0-9] (ms|µs)' "$out/b.txt") <(grep -v -i -E 'time|[0-9] (ms|µs)' "$out/a.txt") >/dev/null; then
    echo "DIFF output: $cmd"; diff "$out/b.txt" "$out/a.txt" | head -5; fail=$((fail + 1))
  fi
done
echo "$n cases, $fail differ"
rm -rf "$out"
[ "$fail" = 0 ]
