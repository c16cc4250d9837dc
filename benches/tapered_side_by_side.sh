#!/usr/bin/env bash
# rollbench against SciPy on the same tapered roller bearing model (issue 17: "A SciPy
# script of the same model takes 5-7 s per case: be >= 1 000x faster, measured side by
# side in one run").
# The AFAPL sample (seed 004 section 3.1, decks/trb_afapl.toml): 37 rollers, 21 slices,
# 20 000 rpm; Load Condition 1 (3 000 lbf thrust) and 2 (plus 700 lbf radial).
# One case = bearing equilibrium + 5x5 stiffness by central differences of re-solved
# roller equilibria (rollbench also computes its analytic stiffness in the same time).
# rollbench: median of 21 cold runs (examples/tapered_one.rs); SciPy: one run
# (benches/tapered_scipy.py: fsolve per roller, root over all 37 rollers).
# Usage: benches/tapered_side_by_side.sh               # LC1 and LC2
#        benches/tapered_side_by_side.sh DECK [--set key=value ...]   # one case
# Needs python3 with numpy and scipy (pip install numpy scipy).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cargo build --release --quiet --example tapered_one
bin=${CARGO_TARGET_DIR:-target}/release/examples/tapered_one

one() {
    local label=$1 deck=$2
    shift 2
    local rb py cmp
    rb=$("$bin" "$deck" "$tmp/model.json" 21 "$@")
    py=$(python3 benches/tapered_scipy.py "$tmp/model.json" --repeat 1 --compare)
    cmp=$(sed -n 2p <<<"$py")
    py=$(sed -n 1p <<<"$py")
    echo "== $label: $deck $*"
    echo "rollbench (median of 21): $rb"
    echo "scipy     (one run):      $py"
    python3 - "$rb" "$py" "$cmp" <<'PY'
import sys
def kv(s):
    return dict(x.split("=", 1) for x in s.split())
r, p, c = kv(sys.argv[1]), kv(sys.argv[2]), kv(sys.argv[3])
tr, tp = float(r["time_s"]), float(p["time_s"])
er, ep = float(r["time_equilibrium_s"]), float(p["time_equilibrium_s"])
print(f"time per case (equilibrium + 5x5 stiffness): rollbench {tr*1e3:.3f} ms, scipy {tp:.3f} s, "
      f"ratio {tp/tr:.0f}x (target >= 1000x)")
print(f"equilibrium alone: rollbench {er*1e3:.3f} ms (with analytic K), scipy {ep:.3f} s, ratio {ep/er:.0f}x")
for key, name in (("dz_m", "dz"), ("p1_n", "P1"), ("p2_n", "P2"), ("p3_n", "P3"), ("kxx", "K_xx"), ("kzz", "K_zz")):
    a, b = float(r[key]), float(p[key])
    print(f"  {name:5s} rollbench {a: .12e}  scipy {b: .12e}  rel. diff {abs(a-b)/abs(b):.2e}")
print("largest rel. differences over all rollers / the matrix (K: scipy's differences vs rollbench's "
      "analytic and its own differences):")
print("  " + " ".join(f"{k}={v}" for k, v in c.items()))
worst = max(float(c[k]) for k in ("geometry", "dz", "p1", "p2", "p3", "kxx_vs_analytic", "kzz_vs_analytic"))
print(f"agreement: {'OK' if worst < 1e-6 else 'FAIL'} (largest {worst:.2e}, required 1e-6)")
PY
}

if [ $# -eq 0 ]; then
    one "Load Condition 1 (3 000 lbf thrust)" decks/trb_afapl.toml
    one "Load Condition 2 (plus 700 lbf radial)" decks/trb_afapl.toml --set operating.radial_load=700
else
    one "case" "$@"
fi
