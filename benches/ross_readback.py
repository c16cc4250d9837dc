#!/usr/bin/env python3
"""Read a `rollbench stiffness DECK --export ross` file back with ROSS (issue 29 item 4).

Loads the file with ROSS's own loader, `ross.BearingElement.load` (petrobras/ross,
`ross/element.py`), and checks its K matrix at frequency 0 against the JSON stiffness
rollbench writes for the same deck (`rollbench stiffness DECK --format json`, SI): kxx,
kyy, kxy, kyx, kzz to rtol 1e-12, and C = 0 (no rollbench system computes damping).

Not part of CI (CI needs no pip). Usage:
    pip install ross-rotordynamics        # 2.3.0 checked; 'plotly<6' if its import fails
    rollbench stiffness decks/chen_a.toml --export ross --output /tmp/a.toml
    rollbench stiffness decks/chen_a.toml --format json --output /tmp/a.json
    python3 benches/ross_readback.py /tmp/a.toml /tmp/a.json
Prints one line per term and exits 1 on any mismatch.
"""
import json
import sys

import numpy as np
import ross as rs


def main(ross_file, json_file):
    bearing = rs.BearingElement.load(ross_file)
    with open(json_file) as f:
        k = json.load(f)["stiffness"]
    cols = k["columns"]
    m = k["matrix"]

    def term(a, b):
        return m[cols.index(a)][cols.index(b)] if a in cols and b in cols else 0.0

    K = bearing.K(0)
    C = bearing.C(0)
    want = {
        "kxx": (K[0, 0], term("x", "x")),
        "kyy": (K[1, 1], term("y", "y")),
        "kxy": (K[0, 1], term("x", "y")),
        "kyx": (K[1, 0], term("y", "x")),
        "kzz": (K[2, 2], term("z", "z")),
    }
    ok = True
    for name, (got, expect) in want.items():
        good = bool(np.isclose(got, expect, rtol=1e-12, atol=0.0))
        ok &= good
        print(f"{name}: ROSS {got!r} N/m, rollbench {expect!r} N/m {'ok' if good else 'MISMATCH'}")
    damping_zero = bool(np.all(C == 0.0))
    ok &= damping_zero
    print(f"C all zero: {damping_zero}; ROSS {rs.__version__}, node n = {bearing.n}, tag {bearing.tag!r}")
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
