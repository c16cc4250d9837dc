#!/usr/bin/env bash
# Issue 32's speed targets for `rollbench study`, measured on the release binary:
#
#  1. Local parallel speed-up: a 1 000-point study of the race-control ball deck
#     (decks/chen_b.toml: a 25 × 40 speed × preload grid) with RAYON_NUM_THREADS=1
#     against all cores. Wall time is what the target (≥ 1.8× on 2 cores) is about, but
#     it is distorted by other load on a shared machine; user+sys CPU time per point is
#     printed too (load does not distort it).
#  2. Per point against one `run`: the study's CPU time per point against `run` of the
#     same deck (CPU time, mean of R runs), and against `run` less the process start-up
#     and deck reading (`check` of the deck). Target ≤ 1.2×.
#  3. Shard overhead: 10⁴ points of a cheap deck (decks/trb_32007.toml, Monte Carlo of
#     two keys) over 4 shards: the shards' CPU time against the unsharded run's, and the
#     merge's. Target: start-up + merge < 5 % of the compute.
#
# Usage: benches/study_speed.sh [BINARY]   (default target/release/rollbench; build it
#        with `cargo build --release`). R=5 repetitions by default (R=… to change).
# Prints one line per measurement; exits non-zero only if a command fails.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN="${1:-target/release/rollbench}"
BIN="$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")"
[ -x "$BIN" ] || { echo "no binary at $BIN (cargo build --release)" >&2; exit 1; }
R="${R:-5}"
DECKS="$(pwd)/decks"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

# cpu CMD…: runs CMD R times; prints "wall_s cpu_s" (means; cpu = the task clock of all
# its threads, user + sys, from `perf stat`; /usr/bin/time's 10 ms ticks without perf).
cpu() {
    if command -v perf >/dev/null 2>&1; then
        LC_ALL=C perf stat -r "$R" -e task-clock -o "$WORK/perf" -- "$@" >/dev/null 2>&1 \
            || { echo "failed: $*" >&2; exit 1; }
        awk '/task-clock/ {gsub(",", "", $1); c = $1 / 1000}
             /seconds time elapsed/ {w = $1}
             END {printf "%.5f %.5f\n", w, c}' "$WORK/perf"
        return
    fi
    local i w=0 c=0 out
    for ((i = 0; i < R; i++)); do
        /usr/bin/time -f "%e %U %S" -o "$WORK/time" "$@" >/dev/null 2>&1 || { echo "failed: $*" >&2; exit 1; }
        out=$(tail -1 "$WORK/time")
        w=$(awk -v a="$w" -v b="$(echo "$out" | cut -d' ' -f1)" 'BEGIN{print a+b}')
        c=$(awk -v a="$c" -v u="$(echo "$out" | cut -d' ' -f2)" -v s="$(echo "$out" | cut -d' ' -f3)" 'BEGIN{print a+u+s}')
    done
    awk -v w="$w" -v c="$c" -v r="$R" 'BEGIN{printf "%.5f %.5f\n", w/r, c/r}'
}

cat >"$WORK/ball.study.toml" <<EOF
deck = "$DECKS/chen_b.toml"
outputs = ["max_ball_load_n", "max_pressure_pa", "cage_speed_rpm", "heat_w", "l10_bearing_mrev"]
[grid]
operating.inner_speed = "5000:14600:x25"
operating.axial_load = "500:2450:50"
EOF
cat >"$WORK/cheap.study.toml" <<EOF
deck = "$DECKS/trb_32007.toml"
outputs = ["max_flange_load_n", "max_stress_pa", "l10_bearing_mrev"]
max_points = 10000
[sample]
method = "monte-carlo"
samples = 10000
seed = 7
geometry.diametral_clearance = { tolerance = [0.0, 1.0e-5] }
operating.axial_load = { normal = [12000.0, 600.0] }
EOF

echo "rollbench study speed ($BIN; $(nproc) cores; means of $R runs; load $(cut -d' ' -f1-3 /proc/loadavg))"

# 1. Parallel speed-up.
read -r w1 c1 < <(RAYON_NUM_THREADS=1 cpu "$BIN" study "$WORK/ball.study.toml" --format csv --output "$WORK/one.csv")
read -r wn cn < <(cpu "$BIN" study "$WORK/ball.study.toml" --format csv --output "$WORK/all.csv")
cmp -s "$WORK/one.csv" "$WORK/all.csv" || { echo "1 thread and all threads differ" >&2; exit 1; }
awk -v w1="$w1" -v wn="$wn" -v c1="$c1" -v cn="$cn" 'BEGIN{
  printf "1. ball study, 1000 points: 1 thread %.3f s wall, %.3f s CPU; all cores %.3f s wall, %.3f s CPU: speed-up %.2fx (wall); CPU per point %.3f ms (1 thread), %.3f ms (all cores)\n",
    w1, c1, wn, cn, w1/wn, c1, cn}'

# 2. Per point against one run (CPU).
RUNS=$((R * 4))
read -r _ crun < <(R=$RUNS cpu "$BIN" run "$DECKS/chen_b.toml" --format json --no-transient)
read -r _ ccheck < <(R=$RUNS cpu "$BIN" check "$DECKS/chen_b.toml")
awk -v c1="$c1" -v crun="$crun" -v cck="$ccheck" 'BEGIN{
  pp = c1 / 1000;
  printf "2. per point %.3f ms CPU (1 thread) against one run %.3f ms CPU (%.2fx); against run less start-up and reading (check %.3f ms): %.3f ms (%.2fx)\n",
    pp*1e3, crun*1e3, pp/crun, cck*1e3, (crun-cck)*1e3, (crun-cck > 0 ? pp/(crun-cck) : 0)}'

# 3. Shard overhead: 10^4 points over 4 shards, and the merge.
read -r wu cu < <(cpu "$BIN" study "$WORK/cheap.study.toml" --format jsonl --output "$WORK/whole.jsonl")
cs=0
ws=0
for i in 0 1 2 3; do
    rm -f "$WORK/part-$i.jsonl"
    read -r w c < <(R=1 cpu "$BIN" study "$WORK/cheap.study.toml" --shard "$i/4" --output "$WORK/part-$i.jsonl")
    cs=$(awk -v a="$cs" -v b="$c" 'BEGIN{print a+b}')
    ws=$(awk -v a="$ws" -v b="$w" 'BEGIN{print a+b}')
done
read -r wm cm < <(cpu "$BIN" study merge "$WORK"/part-{0,1,2,3}.jsonl --format jsonl --output "$WORK/merged.jsonl")
cmp -s <(tail -n +2 "$WORK/whole.jsonl") <(tail -n +2 "$WORK/merged.jsonl") || { echo "merged rows differ from the unsharded run's" >&2; exit 1; }
# A shard's start-up (reading the study and the deck, the one solve of the unmodified
# deck that checks the outputs, writing the part) measured alone: a 1-point study.
sed -e 's/^samples = 10000/samples = 1/' "$WORK/cheap.study.toml" >"$WORK/one.study.toml"
read -r _ c1p < <(R=$((R * 4)) cpu "$BIN" study "$WORK/one.study.toml" --format jsonl --output "$WORK/one.jsonl")
awk -v cu="$cu" -v cs="$cs" -v cm="$cm" -v wm="$wm" -v c1p="$c1p" 'BEGIN{
  printf "3. 10^4 points: unsharded %.3f s CPU (%.3f ms a point); 4 shards %.3f s CPU together (%+.2f %%, both runs as measured); merge %.3f s CPU (%.3f s wall)\n",
    cu, cu/10, cs, 100*(cs-cu)/cu, cm, wm;
  printf "   start-up of a shard (a 1-point study) %.1f ms CPU: 4 start-ups + merge = %.3f s = %.2f %% of the compute (target < 5 %%)\n",
    c1p*1e3, 4*c1p+cm, 100*(4*c1p+cm)/cu}'
