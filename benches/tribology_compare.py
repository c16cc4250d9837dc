#!/usr/bin/env python3
"""Issue 7's comparison with the Python `tribology` package's lamina solver.

Runs `tribology.p3can.load_distr_cyl_rol_bear` (ISO/TS 16281-style slicing of a cylindrical
roller bearing under radial load, secant iteration on the ring deflection) and rollbench's
`examples/tribology_case.rs` on the same case, and prints both run times, their ratio and the
roller loads side by side. Nothing of the package is copied into rollbench; it is imported
from an installed copy:

    python3 -m venv /tmp/tvenv && /tmp/tvenv/bin/pip install tribology numpy --no-deps
    /tmp/tvenv/bin/python benches/tribology_compare.py [LAMINAE ...]
    /tmp/tvenv/bin/python benches/tribology_compare.py --cylindrical   (issue 25's CRB solver)

The case (decks/radial_si.toml made cylindrical): Z = 18 rollers, effective length 15 mm,
straight rollers (conforming crowns, zero crown profile), zero clearance, F_r = 20 kN,
Γ uniform slices. With zero clearance the load distribution does not depend on the
contact-stiffness constant (the package uses ISO's 35948·L^(8/9), rollbench Palmgren's
eq. E.1), so both must give Stribeck's distribution; the package stops at 0.05 % of the load.
"""
import importlib.util
import json
import math
import os
import subprocess
import sys
import time

spec = importlib.util.find_spec("tribology")
if spec is None or not spec.submodule_search_locations:
    sys.exit("the tribology package is not installed (see the docstring)")
# The p3can modules import their siblings by bare name.
sys.path.insert(0, os.path.join(spec.submodule_search_locations[0], "p3can"))
from load_distr_cyl_rol_bear import load_distr_cyl_rol_bear  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def theirs(laminae, z=18, length_mm=15.0, load_n=20000.0, runs=60):
    w = length_mm / laminae
    x = [w * (l - (laminae - 1) / 2) for l in range(laminae)]
    import numpy as np

    profile = np.zeros(laminae)  # straight roller
    phis = [2 * math.pi * j / z for j in range(z)]
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        q, _ = load_distr_cyl_rol_bear(phis, z, length_mm, laminae, profile, np.array(x), 0.0, load_n)
        times.append(time.perf_counter() - t)
    times.sort()
    return times[len(times) // 2], times[0], [float(v) for v in q]


def ours(laminae):
    out = subprocess.run(
        ["cargo", "run", "--quiet", "--release", "--example", "tribology_case", "--", str(laminae)],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout
    return json.loads(out.strip().splitlines()[-1])




def theirs_cyl(laminae, clearance_mm, dub_off_mm, runs=20):
    """Seed 003's truck CRB (Z = 12, 22 mm rollers, 50 mm dub-off over `dub_off_mm`),
    F_r = 5 kN, the package's own slicing (drop at each slice centre)."""
    import numpy as np

    length = 22.0
    w = length / laminae
    x = np.array([w * (l - (laminae - 1) / 2) for l in range(laminae)])
    from_end = length / 2 - np.abs(x)
    profile = np.where(from_end < dub_off_mm, (dub_off_mm - from_end) ** 2 / (2 * 50.0), 0.0)
    phis = [2 * math.pi * j / 12 for j in range(12)]
    # The package gives each of its slices c_L(L)/Γ; rollbench's lamina law gives a slice
    # of width l/Γ the share (l/Γ)/L_e of the effective length L_e's constant (which the
    # example matches to c_L(L_e)). Equal per-slice constants: L^(8/9) = L_e^(8/9)·l/L_e.
    l_e = length - 2 * dub_off_mm
    l_pass = l_e * (length / l_e) ** (9 / 8)
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        q, _ = load_distr_cyl_rol_bear(phis, 12, l_pass, laminae, profile, x,
                                       clearance_mm, 5000.0)
        times.append(time.perf_counter() - t)
    times.sort()
    return times[len(times) // 2], [float(v) for v in q]


def ours_cyl(laminae, clearance_mm, dub_off_mm):
    out = subprocess.run(
        ["cargo", "run", "--quiet", "--release", "--example", "cylindrical_case", "--",
         str(laminae), str(clearance_mm), str(dub_off_mm)],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout
    return json.loads(out.strip().splitlines()[-1])


if sys.argv[1:2] == ["--cylindrical"]:
    # Issue 25: the cylindrical roller's own solver (examples/cylindrical_case.rs, its
    # moduli set so that Palmgren's constant equals the package's ISO c_L) against the
    # package. Straight rollers: the same model, loads must agree within 0.1 % (the package
    # stops at 0.05 % of the load). With a dub-off the package samples the drop at slice
    # centres while rollbench integrates it over the slice: they agree as the slices grow.
    for laminae, clearance, dub in [(21, 0.0, 0.0), (21, 0.02, 0.0), (21, 0.02, 3.0),
                                    (161, 0.02, 3.0)]:
        t_py, q_py = theirs_cyl(laminae, clearance, dub)
        r = ours_cyl(laminae, clearance, dub)
        q_rs = r["loads_n"]
        worst = max(abs(a - b) for a, b in zip(q_py, q_rs)) / max(q_rs)
        print(f"CRB Γ = {laminae}, c = {clearance} mm, dub-off {dub} mm: tribology "
              f"{t_py * 1e3:.3f} ms, rollbench {r['solver_median_s'] * 1e3:.3f} ms "
              f"({t_py / r['solver_median_s']:.0f}×); largest roller-load difference "
              f"{worst * 100:.3f} % of Q_max (W_max {max(q_py):.2f} / {max(q_rs):.2f} N)")
    sys.exit(0)

for laminae in [int(a) for a in sys.argv[1:]] or [21, 61]:
    t_py, t_py_min, q_py = theirs(laminae)
    r = ours(laminae)
    q_rs = r["loads_n"]
    worst = max(abs(a - b) for a, b in zip(q_py, q_rs)) / max(q_rs)
    print(f"Γ = {laminae}: tribology {t_py * 1e3:.3f} ms (fastest {t_py_min * 1e3:.3f}), rollbench solver "
          f"{r['solver_median_s'] * 1e3:.3f} ms ({t_py / r['solver_median_s']:.0f}×), "
          f"rollbench full pipeline {r['pipeline_median_s'] * 1e3:.3f} ms "
          f"({t_py / r['pipeline_median_s']:.0f}×); largest roller-load difference "
          f"{worst * 100:.3f} % of Q_max")
    for j, (a, b) in enumerate(zip(q_py, q_rs)):
        if a > 0 or b > 0:
            print(f"  roller {j + 1:2d}: tribology {a:10.2f} N   rollbench {b:10.2f} N")
