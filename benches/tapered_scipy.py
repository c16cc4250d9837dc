#!/usr/bin/env python3
"""The tapered roller bearing of seed 004 (AFAPL-TR-78-6 Part III, section 2) solved with
numpy/scipy, the same model as rollbench's src/bearings/tapered_roller, for the side by
side of issue 17 ("a SciPy script of the same model takes 5-7 s per case: be >= 1 000x
faster, measured side by side in one run"). The model file is written by
`cargo run --release --example tapered_one -- decks/trb_afapl.toml model.json`; it holds
the roller geometry as rollbench derived it (eqs. 16-35: tau/2, apex distances, crown,
flange angle and contact point, lever, approach ratio, mass, F_c, M_G), the slice law's
compliances, loads and rollbench's answers.

The equations, written again here from the seed and rollbench's documentation:
  contact extent [X_B, X_A] of the crowned roller (eqs. 48-54), n midpoint slices on it;
  slice intrusion Delta_x (eqs. 58-61), slice law D_x, E_x, gamma (eqs. 64-68);
  Lundberg's line contact (eq. 62) inverted for the load per length p at each slice:
      Delta_x = c p (1.8864 + ln(L / (2 b))),  b^2 = c D_x (1 + C gamma) p,  L = X_A - X_B
    (solved for t = Delta_x/(c p): t - ln(t)/2 = 1.8864 + ln(L^2/(4 c D_x (1 + C gamma) Delta_x/c))/2
     by scipy.optimize.newton, vectorised over the slices);
  P = h sum p_k, M = h sum X_k p_k (eqs. 72-73);
  roller (eqs. 43-44, 55-57, 74-83): unknowns (Delta_1, theta_1), Delta_2 = k (Delta - Delta_1),
  theta_2 = Theta - theta_1, flange reaction from the moment balance
      P3 l = -M1 + M2 + M_G + F_c Xbar cos psi - (d/2)(P1 - P2) sin(tau/2),
  force balances (55)-(56) solved by scipy.optimize.fsolve (MINPACK hybrd, its own
  difference Jacobian); a roller whose cup-and-flange equilibrium (121-130) does not reach
  the cone keeps that equilibrium;
  bearing (eqs. 40-42, 92-99): Delta_q, Theta_q of every one of the n rollers at
  phi_q = 2 pi q / n, reactions F' = (cos b sum P1 cos phi, cos b sum P1 sin phi, sin b sum P1),
  M' = (sum (R_m P1 + M1) sin phi, sum (R_m P1 + M1) cos phi); F' = (F_r, 0, F_a) solved
  for (dx, dy, dz) by scipy.optimize.root (hybr) over all rollers (no symmetry shortcut);
  stiffness: K_ij = dR_i/dx_j by central differences of re-solved roller equilibria, step
  1e-5 of the largest roller approach (rotations: that over R_m), as rollbench's check.

Prints `key=value ...`: wall time of the whole case (equilibrium + stiffness) and of the
equilibrium alone, dz, P1, P2, P3 of roller 1, K_xx, K_zz; with --compare, the largest
relative differences against rollbench's answers in the model file.
"""
import argparse
import json
import math
import time

import numpy as np
from scipy.optimize import fsolve, newton, root


class Contact:
    """One race: the crowned roller's contact by n slices (eqs. 48-73)."""

    def __init__(self, model, race):
        g, r, mat = model["geometry"], model["roller"], model["materials"]
        t = r["half_cone_rad"]
        beta = g["cup_angle_rad"]
        if race == "cup":
            self.c_sign, race_angle, self.c = 1.0, beta, mat["cup_compliance_1_pa"]
        else:
            self.c_sign, race_angle, self.c = -1.0, beta - 2.0 * t, mat["cone_compliance_1_pa"]
        self.kl = mat["lundberg_constant"]
        self.half_le = 0.5 * g["effective_length_m"]
        self.half_flat = 0.5 * g["flat_length_m"]
        self.rc = r["crown_radius_m"]
        self.h = r["crown_offset_m"]
        self.v = r["crown_drop_m"]
        self.n = model["solver"]["slices"]
        self.d = g["roller_diameter_m"]
        self.e = g["pitch_diameter_m"]
        self.sb, self.cb = math.sin(beta), math.cos(beta)
        self.cos_race = math.cos(race_angle)
        self.cos_d_psi = self.d * math.cos(beta - t)
        self.tan_t, self.cos_t = math.tan(t), math.cos(t)

    def extent(self, delta, theta):
        """[X_B, X_A] (eqs. 48-54), or None without contact."""
        s, c = math.sin(theta), math.cos(theta)
        a = self.h * c - delta
        # R_c - a without subtracting two crown-sized lengths (R_c - H = (l_F/2)^2/(R_c + H)).
        rc_minus_a = (
            delta
            + self.half_flat**2 / (self.rc + self.h)
            + 2.0 * self.h * math.sin(0.5 * theta) ** 2
        )
        rad = rc_minus_a * (self.rc + a)
        if not rad > 0.0:
            return None
        sq = math.sqrt(rad)
        xa, xb = sq + self.h * s, -sq + self.h * s
        xa_max = self.half_le * c + self.v * s  # eq. 52
        xb_min = -self.half_le * c + self.v * s  # eq. 53
        if xa <= xb_min or xb >= xa_max:
            return None
        f = self.half_flat * c
        if f > 0.0 and theta != 0.0:  # eq. 54 and its mirror: the flat's own root
            r0 = -delta * c / s
            if -f < xb < f and xa > f and xb < r0 < xa:
                xb = r0
            if -f < xa < f and xb < -f and xb < r0 < xa:
                xa = r0
        xa, xb = min(xa, xa_max), max(xb, xb_min)
        return (xb, xa) if xa > xb else None

    def slices(self, delta, theta):
        """Slice positions X_k, intrusions, and loads per length p_k."""
        ext = self.extent(delta, theta)
        if ext is None:
            return None
        xb, xa = ext
        length = xa - xb
        x = xb + (np.arange(self.n) + 0.5) / self.n * length
        s, c = math.sin(theta), math.cos(theta)
        # Intrusion (eqs. 58-61): flat part, crowned part.
        u = x - self.h * s
        crown = delta + (self.half_flat**2 - x * x + 2.0 * x * self.h * s) / (
            np.sqrt((self.rc - u) * (self.rc + u)) + self.h * c
        )
        intr = np.where(np.abs(x) <= self.half_flat * c, delta + x * s / c, crown)
        # Slice law (eqs. 64-68).
        dx = (self.d + 2.0 * x * self.tan_t * self.cos_t) / self.cos_t
        ex = self.e + 2.0 * x * self.sb + self.cos_d_psi - dx * self.cb
        conformity = 1.0 + self.c_sign * dx * self.cos_race / ex
        wf = self.c * dx * conformity  # b^2 = wf * p
        p = np.zeros(self.n)
        on = intr > 0.0
        if np.any(on):
            dd = intr[on] / self.c
            c0 = self.kl + 0.5 * np.log(length * length / (4.0 * wf[on] * dd))
            if np.any(c0 <= 0.5 - 0.5 * math.log(0.5)):
                raise ValueError("a slice is beyond Lundberg's validity (L/(2b) <= 0.25)")
            t = newton(
                lambda t: t - 0.5 * np.log(t) - c0,
                c0 + 0.5 * np.log(c0),
                fprime=lambda t: 1.0 - 0.5 / t,
                tol=1e-14,
                maxiter=50,
            )
            p[on] = dd / t
        return x, intr, p, length / self.n

    def resultants(self, delta, theta):
        """(P, M) of eqs. 72-73."""
        sl = self.slices(delta, theta)
        if sl is None:
            return 0.0, 0.0
        x, _, p, h = sl
        return h * p.sum(), h * (x * p).sum()


class Roller:
    """One roller between cup, cone and flange (eqs. 43-44, 55-57, 121-130)."""

    def __init__(self, model):
        g, r, dy = model["geometry"], model["roller"], model["dynamics"]
        beta, t = g["cup_angle_rad"], r["half_cone_rad"]
        psi, alpha = r["axis_angle_rad"], r["flange_angle_rad"]
        self.cup, self.cone = Contact(model, "cup"), Contact(model, "cone")
        self.cb, self.sb = math.cos(beta), math.sin(beta)
        self.c_cone, self.s_cone = math.cos(beta - 2 * t), math.sin(beta - 2 * t)
        self.s_fl, self.c_fl = math.sin(psi - alpha), math.cos(psi - alpha)
        self.k = r["approach_ratio"]
        self.lever = r["flange_lever_arm_m"]
        self.wedge = 0.5 * g["roller_diameter_m"] * math.sin(t)
        self.fc = dy["centrifugal_force_n"]
        self.speed_moment = (
            dy["gyroscopic_moment_nm"] + self.fc * r["cg_offset_m"] * math.cos(psi)
        )
        # Unknowns scaled to order one for fsolve: micrometres, and microns of tilt at the
        # roller's end.
        self.scale = np.array([1e-6, 1e-6 / (0.5 * g["effective_length_m"])])
        self.cf = self.solve_cup_flange() if (self.fc != 0 or self.speed_moment != 0) else None

    def forces(self, d1, t1, delta, big_theta, with_cone=True):
        p1, m1 = self.cup.resultants(d1, t1)
        d2, t2 = self.k * (delta - d1), big_theta - t1
        p2, m2 = self.cone.resultants(d2, t2) if with_cone else (0.0, 0.0)
        p3 = (-m1 + m2 + self.speed_moment - self.wedge * (p1 - p2)) / self.lever
        res = np.array(
            [
                -p1 * self.cb + p2 * self.c_cone - p3 * self.s_fl + self.fc,
                -p1 * self.sb + p2 * self.s_cone + p3 * self.c_fl,
            ]
        )
        return res, (p1, p2, p3, m1, m2, d2, t2)

    def _fsolve(self, start, delta, big_theta, with_cone):
        def f(z):
            d1, t1 = z * self.scale
            return self.forces(d1, t1, delta, big_theta, with_cone)[0]

        z, info, ier, msg = fsolve(
            f, np.asarray(start) / self.scale, xtol=1e-13, full_output=True
        )
        d1, t1 = z * self.scale
        res, out = self.forces(d1, t1, delta, big_theta, with_cone)
        # fsolve may report "not making good progress" when the residual is already at the
        # round-off of the slice sums (~1e-11 N here); only that case is accepted, and any
        # residual above 1 uN (1e-9 of a roller's ~1 kN load) is an error with its numbers.
        if ier != 1 and np.max(np.abs(res)) > 1e-6:
            raise RuntimeError(
                f"roller fsolve failed at Delta={delta:.4e} m, Theta={big_theta:.3e}: "
                f"{msg} (residual {np.max(np.abs(res)):.3e} N)"
            )
        return (d1, t1) + out

    def solve_cup_flange(self):
        p1 = self.fc / (self.cb + self.sb * self.s_fl / self.c_fl)
        # Start: the aligned cup approach of P1 by one secant step from 1 um.
        p_probe = self.cup.resultants(1e-6, 0.0)[0]
        p_probe2 = self.cup.resultants(1.01e-6, 0.0)[0]
        per_m = (p_probe2 - p_probe) / 1e-8
        start = (max(1e-6 + (abs(p1) - p_probe) / per_m, 1e-7), 0.0)
        return self._fsolve(start, 0.0, 0.0, False)

    def solve(self, delta, big_theta, warm=None):
        """(Delta1, theta1, P1, P2, P3, M1, M2, Delta2, theta2) at ring approach Delta and
        misalignment Theta."""
        if self.cf is not None:
            d1, t1 = self.cf[0], self.cf[1]
            d2, t2 = self.k * (delta - d1), big_theta - t1
            if self.cone.extent(d2, t2) is None:
                return self.cf[:7] + (d2, t2)
            cold = (d1, t1)
        else:
            if delta <= 0.0:
                return (0.0, 0.5 * big_theta, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5 * big_theta)
            cold = (self.k * delta / (1.0 + self.k), 0.5 * big_theta)
        return self._fsolve(warm if warm is not None else cold, delta, big_theta, True)


class Bearing:
    """All rollers around the bearing (eqs. 40-42, 92-99)."""

    def __init__(self, model):
        self.model = model
        g, op = model["geometry"], model["operating"]
        self.roller = Roller(model)
        self.n = g["roller_count"]
        phi = 2.0 * np.pi * np.arange(self.n) / self.n
        self.cos, self.sin = np.cos(phi), np.sin(phi)
        self.beta = g["cup_angle_rad"]
        self.rm = model["roller"]["moment_radius_m"]
        self.clearance = 0.5 * g["diametral_clearance_m"] * math.cos(self.beta)
        self.d0 = np.array(op["initial_displacement_m"])
        self.rot = np.array(op["misalignment_rad"])
        self.load = np.array([op["radial_load_n"], 0.0, op["axial_load_n"]])
        self.warm = [None] * self.n  # each roller's last (Delta1, theta1)

    def state(self, x5):
        """Reactions (F'x, F'y, F'z, M'x, M'y) and the rollers at ring position x5."""
        cb, sb = math.cos(self.beta), math.sin(self.beta)
        px, py, pz = x5[0] + self.d0[0], x5[1] + self.d0[1], x5[2] + self.d0[2]
        tx, ty = x5[3], x5[4]
        reac = np.zeros(5)
        rollers = []
        for q in range(self.n):
            c, s = self.cos[q], self.sin[q]
            delta = (
                cb * c * px + cb * s * py + sb * pz + self.rm * (tx * s + ty * c) - self.clearance
            )
            theta = tx * s + ty * c
            r = self.roller.solve(delta, theta, self.warm[q])
            self.warm[q] = (r[0], r[1])
            p1, m1 = r[2], r[5]
            reac += [cb * c * p1, cb * s * p1, sb * p1, (self.rm * p1 + m1) * s, (self.rm * p1 + m1) * c]
            rollers.append((r, delta, theta))
        return reac, rollers

    def solve(self):
        # Displacements in micrometres for the root finder; start at 10 um of thrust.
        def f(z):
            x5 = np.concatenate((z * 1e-6, self.rot))
            return self.state(x5)[0][:3] - self.load

        sol = root(f, np.array([0.0, 0.0, 10.0]), method="hybr", options={"xtol": 1e-14})
        x = sol.x * 1e-6
        reac, rollers = self.state(np.concatenate((x, self.rot)))
        resid = np.max(np.abs(reac[:3] - self.load))
        tol = self.model["solver"]["force_tolerance"] * max(abs(self.load[0]), abs(self.load[2]))
        if not sol.success and resid > 10.0 * tol:
            raise RuntimeError(f"bearing root failed: {sol.message} (residual {resid:.3e} N)")
        return x, reac, rollers, resid

    def stiffness_fd(self, x, rollers):
        h = 1e-5 * max(max(abs(r[1]) for r in rollers), 1e-9)
        x0 = np.concatenate((x, self.rot))
        k = np.zeros((5, 5))
        for j in range(5):
            hj = h if j < 3 else h / self.rm
            xp, xm = x0.copy(), x0.copy()
            xp[j] += hj
            xm[j] -= hj
            k[:, j] = (self.state(xp)[0] - self.state(xm)[0]) / (2.0 * hj)
        return k


def geometry_check(model):
    """Largest relative residual of the derived roller geometry the model file carries,
    checked against the seed's defining equations (eq. 16 for tau/2, eq. 19 for H0, eq. 43
    for k, eqs. 32-33 for alpha and the lever, eq. 17-18 for the crown, R_m of eq. 40): the
    SciPy model takes rollbench's derived numbers, so they are checked independently here."""
    g, r = model["geometry"], model["roller"]
    d, e, beta = g["roller_diameter_m"], g["pitch_diameter_m"], g["cup_angle_rad"]
    t, half_le, half_flat = r["half_cone_rad"], 0.5 * g["effective_length_m"], 0.5 * g["flat_length_m"]
    rc, h, v = r["crown_radius_m"], r["crown_offset_m"], r["crown_drop_m"]
    alpha, re_, rr = r["flange_angle_rad"], r["big_end_radius_m"], r["flange_contact_radius_m"]
    checks = [
        (math.tan(t), d / e * math.sin(beta - t)),  # eq. 16
        (r["h0_m"], d / (2.0 * math.tan(t))),  # eq. 19
        (r["axis_angle_rad"], beta - t),
        (r["approach_ratio"], math.cos(alpha - t) / math.cos(alpha + t)),  # eq. 43
        (math.sin(alpha), rr / re_),  # eq. 32
        (r["flange_lever_arm_m"], (math.sqrt(re_**2 - rr**2) - r["h2_m"] + r["h0_m"]) * math.sin(alpha)),  # eq. 33
        (h, math.sqrt(rc**2 - half_flat**2)),  # eq. 17
        # eq. 18, V = H - sqrt(R_c^2 - (l_e/2)^2), written without the cancellation of two
        # 2.5 m lengths (it would cost 1e-11 of V's 11 um)
        (v, (half_le**2 - half_flat**2) / (h + math.sqrt(rc**2 - half_le**2))),
        (r["moment_radius_m"], 0.5 * (e * math.sin(beta) + d * math.sin(t))),  # eq. 40
    ]
    if "radius_m" in g["crown"]:
        checks.append((rc, g["crown"]["radius_m"]))
    return max(abs(a - b) / abs(b) for a, b in checks)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("model", help="model JSON from `cargo run --release --example tapered_one`")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--compare", action="store_true", help="print the agreement with rollbench")
    args = ap.parse_args()
    with open(args.model) as fh:
        model = json.load(fh)
    best, best_eq = math.inf, math.inf
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        b = Bearing(model)
        x, reac, rollers, resid = b.solve()
        t1 = time.perf_counter()
        k = b.stiffness_fd(x, rollers)
        t2 = time.perf_counter()
        best, best_eq = min(best, t2 - t0), min(best_eq, t1 - t0)
    r1 = rollers[0][0]
    print(
        f"time_s={best:.6e} time_equilibrium_s={best_eq:.6e} dz_m={x[2]:.15e} "
        f"p1_n={r1[2]:.15e} p2_n={r1[3]:.15e} p3_n={r1[4]:.15e} "
        f"kxx={k[0, 0]:.15e} kzz={k[2, 2]:.15e} residual_n={resid:.3e}"
    )
    if args.compare:
        rb = model["rollbench"]

        def rel(a, b):
            a, b = np.asarray(a, float), np.asarray(b, float)
            return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))

        out = {"geometry": geometry_check(model)}
        if rb["displacement_m"][0] != 0.0:
            out["dx"] = rel(x[0], rb["displacement_m"][0])
        else:  # pure thrust: no radial displacement to scale by
            out["dx_abs_m"] = abs(x[0])
        out["dz"] = rel(x[2], rb["displacement_m"][2])
        for i, name in ((2, "p1"), (3, "p2"), (4, "p3"), (5, "m1"), (6, "m2")):
            out[name] = rel([r[0][i] for r in rollers], [r[f"{name}_n" if i < 5 else f"{name}_nm"] for r in rb["rollers"]])
        ka = np.array(rb["stiffness"])
        out["kxx_vs_analytic"] = rel(k[0, 0], ka[0, 0])
        out["kzz_vs_analytic"] = rel(k[2, 2], ka[2, 2])
        if rb["stiffness_fd"] is not None:
            kf = np.array(rb["stiffness_fd"])
            out["kxx_vs_fd"] = rel(k[0, 0], kf[0, 0])
            out["kzz_vs_fd"] = rel(k[2, 2], kf[2, 2])
        # Whole matrix, scaled to comparable units (rotations as arc at R_m): N/m.
        s = np.diag([1, 1, 1, 1 / b.rm, 1 / b.rm])
        out["k5x5_vs_analytic"] = rel(s @ k @ s, s @ ka @ s)
        print(" ".join(f"{key}={val:.3e}" for key, val in out.items()))


if __name__ == "__main__":
    main()
