#!/usr/bin/env python3
"""One ball of Chen's Bearing B (seed 001 ch. 2, eqs. 2-3, 2-14...2-18) integrated by
SciPy's solve_ivp (RK45, the same Dormand-Prince 5(4) pair as rollbench's DOPRI5), with
the same model and inputs as rollbench: the model file is written by
`cargo run --release --example ball_one -- 500 5 1e-8 auto model.json`.

The equations are those of src/bearings/angular_ball/dynamics.rs, written again here
from its documentation (not translated line by line):
  J dw/dt = M - J w_m a x w                      (cage frame (a, r, t), w_m held)
  slice k of a contact: strip load q_k = Q * 3/4 [xi - xi^3/3] between its edges,
  surface normal nu_k turned by phi_k = xi_k a / R_def from the contact normal,
  point p_k = (D/2 - R_def) n + R_def nu_k, R_def = 2 / (2/D + 1/(f D))   (2-17)
  sliding s = P_nu (w_m R_b t + w x p - Omega_race (R_b + p_r) t)           (2-15)
  traction f = -mu(|s|) q s/|s|, heat mu q |s|  (rolling part mu q s_t^2/|s|)  (2-18)
  loads, angles and semi-major axes linear in azimuth between the balls (the load track).

Prints `key=value ...`: wall time of solve_ivp alone (best of `--repeat` runs), the mean
heat over the last orbit (on 90 samples per orbit, as rollbench), the final w, and the
number of RHS evaluations.
"""
import argparse
import json
import math
import time

import numpy as np
from scipy.integrate import solve_ivp


def load_track(model):
    tau = 2.0 * math.pi
    pts = sorted(
        ((b["azimuth_rad"] % tau, b["inner"], b["outer"]) for b in model["track"]),
        key=lambda x: x[0],
    )
    az = np.array([p[0] for p in pts])
    inner = np.array([p[1] for p in pts])
    outer = np.array([p[2] for p in pts])
    # Periodic linear interpolation: append the first point one turn later, and the
    # last one turn earlier.
    az_ext = np.concatenate(([az[-1] - tau], az, [az[0] + tau]))
    inner_ext = np.vstack((inner[-1], inner, inner[0]))
    outer_ext = np.vstack((outer[-1], outer, outer[0]))

    def at(psi):
        psi = psi % tau
        i = [np.interp(psi, az_ext, inner_ext[:, c]) for c in range(3)]
        o = [np.interp(psi, az_ext, outer_ext[:, c]) for c in range(3)]
        return i, o

    return at


def make_rhs(model):
    d = model["diameter_m"]
    rb = model["centre_radius_m"]
    j = model["inertia_kg_m2"]
    wm = model["cage_rad_s"]
    w_in, w_out = model["ring_speeds_rad_s"]
    f_in, f_out = model["groove_curvatures"]
    cu = np.array([p[0] for p in model["curve_points"]])
    cm = np.array([p[1] for p in model["curve_points"]])
    n_sl = model["slices"]
    psi0 = model["start_azimuth_rad"]
    track = load_track(model)
    edges = np.linspace(-1.0, 1.0, n_sl + 1)
    cum = 0.75 * (edges - edges**3 / 3.0)
    share = np.diff(cum)  # q_k / Q
    mid = 0.5 * (edges[:-1] + edges[1:])
    tvec = np.array([0.0, 0.0, 1.0])
    a_axis = np.array([1.0, 0.0, 0.0])
    vc = wm * rb * tvec

    def mu(u):
        return np.interp(u, cu, cm) if len(cu) > 1 else np.full_like(u, cm[0])

    def contact(inner, loads, w):
        load, alpha, semi = loads
        if load <= 0.0 or semi <= 0.0:
            z = np.zeros(3)
            return z, 0.0, 0.0
        s, c = math.sin(alpha), math.cos(alpha)
        if inner:
            n, f, wr = np.array([-s, -c, 0.0]), f_in, w_in
        else:
            n, f, wr = np.array([s, c, 0.0]), f_out, w_out
        tau = np.array([n[1], -n[0], 0.0])
        r_def = 2.0 / (2.0 / d + 1.0 / (f * d))
        phi = mid * semi / r_def
        nu = np.outer(np.cos(phi), n) + np.outer(np.sin(phi), tau)
        p = (0.5 * d - r_def) * n + r_def * nu
        v_race = np.outer(wr * (rb + p[:, 1]), tvec)
        sl = vc + np.cross(w, p) - v_race
        sl = sl - np.sum(sl * nu, axis=1)[:, None] * nu
        u = np.linalg.norm(sl, axis=1)
        q = load * share
        m = mu(u)
        ok = u > 0.0
        fv = np.zeros_like(sl)
        fv[ok] = -(m[ok] * q[ok] / u[ok])[:, None] * sl[ok]
        moment = np.cross(p, fv).sum(axis=0)
        heat = np.sum(m * q * u)
        rolling = np.sum(np.where(ok, m * q * sl[:, 2] ** 2 / np.where(ok, u, 1.0), 0.0))
        return moment, heat, rolling

    def both(t, w):
        li, lo = track(psi0 + wm * t)
        mi, hi, ri = contact(True, li, w)
        mo, ho, ro = contact(False, lo, w)
        return mi + mo, hi + ho, ri + ro

    def rhs(t, w):
        m, _, _ = both(t, w)
        return m / j - wm * np.cross(a_axis, w)

    return rhs, both


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("model", help="model JSON from `cargo run --release --example ball_one`")
    ap.add_argument("--repeat", type=int, default=1)
    args = ap.parse_args()
    with open(args.model) as fh:
        model = json.load(fh)
    rhs, both = make_rhs(model)
    orbits, rtol = model["orbits"], model["rtol"]
    w0 = np.array(model["omega0"], dtype=float)
    period = 2.0 * math.pi / abs(model["cage_rad_s"])
    t_end = orbits * period
    n = max(math.ceil(orbits * 90), 2)
    times = np.minimum(t_end * np.arange(n + 1) / n, t_end)
    atol = rtol * max(np.linalg.norm(w0), 1.0)
    best, sol = math.inf, None
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        sol = solve_ivp(rhs, (0.0, t_end), w0, method="RK45", rtol=rtol, atol=atol, t_eval=times)
        best = min(best, time.perf_counter() - t0)
    if not sol.success:
        raise SystemExit(f"solve_ivp failed: {sol.message}")
    last = [k for k, t in enumerate(sol.t) if t >= t_end - period * min(orbits, 1.0)]
    heat = np.mean([both(sol.t[k], sol.y[:, k])[1] for k in last])
    w = sol.y[:, -1]
    print(
        f"time_s={best:.6e} heat_w={heat:.10e} omega_a={w[0]:.10e} omega_r={w[1]:.10e} "
        f"omega_t={w[2]:.10e} rhs={sol.nfev}"
    )


if __name__ == "__main__":
    main()
