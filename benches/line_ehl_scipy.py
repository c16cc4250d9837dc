#!/usr/bin/env python3
"""references.md's isothermal line-EHL case (E' 2.21e11 Pa, eta0 0.02 Pa s, u 1.5 m/s,
w 5e4 N/m, R 0.02 m, G 5000; flooded domain -4.5b ... 1.5b) solved by a straightforward
NumPy/SciPy Newton solver of the same discretisation as rollbench's line-EHL solver
(src/physics/ehl/line.rs), written again from its documentation:

  Hertz scaling X = x/b, P = p/p_H, H = hR/b^2; Roelands/Houpert viscosity at T0,
  Dowson-Higginson density; H = H0 + X^2/2 + sum_j K_|i-j| P_j with the exact
  piecewise-constant log kernel; Reynolds d/dX(eps dP/dX) - d(rho H)/dX = 0 with eps at
  mid-points and second-order upwind wedge; Swift-Stieber as min(P, -r) = 0 (semismooth
  Newton); the load balance sum P dX = pi/2 closing H0; rows scaled by
  dX/(1 + (eps+ + eps-)/dX); the exact dense Jacobian factorised by scipy.linalg.lu_factor
  (LAPACK dgetrf) at every iteration; backtracking line search on ||Phi||.

This is rollbench's reference path (NewtonStrategy::Full) in Python: the same iterates
to round-off. Prints `key=value ...`: the best CPU time of `--repeat` cold solves,
iterations, h_c, h_min, p_max. Run with OPENBLAS_NUM_THREADS=1 (benches/line_ehl_side_by_side.sh
does) so that LAPACK uses one core like rollbench.
"""
import argparse
import math
import time

import numpy as np
import scipy.linalg as sla

E_PRIME = 2.21e11
R = 0.02
ETA0 = 0.02
U = 1.5
W = 5e4
G = 5000.0
RHO0 = 870.0
ROELANDS_P = 5.1e-9
LN_ETA_INF = 9.67


def kernel_row(n, dx):
    def f(t):
        with np.errstate(divide="ignore", invalid="ignore"):
            v = t * np.log(np.abs(t)) - t
        return np.where(t == 0.0, 0.0, v)

    t = np.arange(n) * dx
    return -(f(t + 0.5 * dx) - f(t - 0.5 * dx)) / math.pi


def solve(nodes, tol=1e-8, max_iterations=100):
    alpha_pv = G / E_PRIME
    b = math.sqrt(8.0 * W * R / (math.pi * E_PRIME))
    p_h = 2.0 * W / (math.pi * b)
    n = nodes
    x = np.linspace(-4.5, 1.5, n)
    dx = x[1] - x[0]
    krow = kernel_row(n, dx)
    idx = np.arange(n)
    kfull = krow[np.abs(idx[:, None] - idx[None, :])]
    lam = 12.0 * ETA0 * U * R * R / (b**3 * p_h)
    l_coef = math.log(ETA0) + LN_ETA_INF
    z = alpha_pv / (ROELANDS_P * l_coef)
    film_scale = b * b / R

    def fluid(p):
        pd = np.maximum(p_h * p, 0.0)
        pos = p_h * p >= 0.0
        rho = 1.0 + 0.6e-9 * pd / (1.0 + 1.7e-9 * pd)
        rho_p = np.where(pos, 0.6e-9 / (1.0 + 1.7e-9 * pd) ** 2 * p_h, 0.0)
        growth = np.exp(z * np.log1p(ROELANDS_P * pd))
        eta = np.exp(l_coef * (-1.0 + growth))
        slope = l_coef * z * ROELANDS_P * np.exp((z - 1.0) * np.log1p(ROELANDS_P * pd))
        eta_log_p = np.where(pos, slope * p_h, 0.0)
        return rho, rho_p, eta, eta_log_p

    def residual(p, h0, want_jac):
        rho, rho_p, eta, eta_log_p = fluid(p)
        h = h0 + 0.5 * x * x + kfull @ p
        clamped = h < 0.0
        h = np.where(clamped, 0.0, h)
        eps = rho * h**3 / (eta * lam)
        q = rho * h
        i = np.arange(1, n - 1)
        e_plus = 0.5 * (eps[i] + eps[i + 1])
        e_minus = 0.5 * (eps[i - 1] + eps[i])
        pois = (e_plus * (p[i + 1] - p[i]) - e_minus * (p[i] - p[i - 1])) / dx**2
        # Upwind wedge: second order from i = 2, first order at i = 1.
        w0 = np.where(i >= 2, 1.5, 1.0) / dx
        w1 = np.where(i >= 2, -2.0, -1.0) / dx
        w2 = np.where(i >= 2, 0.5, 0.0) / dx
        q2 = q[np.maximum(i - 2, 0)]
        wedge = w0 * q[i] + w1 * q[i - 1] + w2 * q2
        c = 1.0 / (1.0 + (e_plus + e_minus) / dx)
        r = (pois - wedge) * dx * c
        cav = p[i] < -r
        phi = np.empty(n + 1)
        phi[0] = p[0]
        phi[n - 1] = p[n - 1]
        phi[i] = np.where(cav, p[i], -r)
        load = p.sum() * dx / (0.5 * math.pi) - 1.0
        phi[n] = load
        if not want_jac:
            return phi, load, h
        m = n + 1
        jac = np.zeros((m, m))
        jac[0, 0] = 1.0
        jac[n - 1, n - 1] = 1.0
        jac[n, :n] = dx / (0.5 * math.pi)
        s = np.where(cav, 0.0, -dx * c)
        jac[i, i] += np.where(cav, 1.0, 0.0)
        jac[i, i + 1] += s * e_plus / dx**2
        jac[i, i] -= s * (e_plus + e_minus) / dx**2
        jac[i, i - 1] += s * e_minus / dx**2
        g = 0.5 * (p[i + 1] - p[i]) / dx**2
        fm = 0.5 * (p[i] - p[i - 1]) / dx**2
        # (column offset k - i, coefficient) of eps_k and of q_k.
        eps_terms = [(-1, -fm), (0, g - fm), (1, g)]
        q_terms = [(0, -w0), (-1, -w1), (-2, -w2)]
        d_eps = eps * (rho_p / rho - eta_log_p)
        film_ok = ~clamped & (h > 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            eps_h = np.where(film_ok, 3.0 * eps / np.where(h > 0.0, h, 1.0), 0.0)
        terms = [(off, coef, True) for off, coef in eps_terms]
        terms += [(off, coef, False) for off, coef in q_terms]
        for off, coef, is_eps in terms:
            k = np.maximum(i + off, 0)
            if is_eps:
                local = s * coef * d_eps[k]
                via_h = s * coef * eps_h[k]
            else:
                local = s * coef * rho_p[k] * h[k]
                via_h = s * coef * rho[k]
            jac[i, k] += local
            jac[i, :n] += via_h[:, None] * kfull[k, :]
            jac[i, n] += via_h
        return phi, load, h, jac

    # Start: Hertz pressure carrying the load, H0 from Pan-Hamrock's central film.
    p = np.sqrt(np.maximum(1.0 - x * x, 0.0))
    p[0] = p[-1] = 0.0
    p *= 0.5 * math.pi / (p.sum() * dx)
    u_g, g_g, w_g = ETA0 * U / (E_PRIME * R), alpha_pv * E_PRIME, W / (E_PRIME * R)
    hc_ph = 2.922 * R * u_g**0.692 * g_g**0.470 * w_g ** (-0.166)
    h0 = hc_ph / film_scale - np.interp(0.0, x, kfull @ p)
    for iteration in range(1, max_iterations + 1):
        phi, _, _, jac = residual(p, h0, True)
        norm = np.linalg.norm(phi)
        delta = sla.lu_solve(sla.lu_factor(jac, check_finite=False), -phi, check_finite=False)
        largest = np.max(np.abs(delta[:n]))
        alpha = 1.0 / largest if largest > 1.0 else 1.0
        for _ in range(12):
            tp, th = p + alpha * delta[:n], h0 + alpha * delta[n]
            tphi, tload, th_film = residual(tp, th, False)
            tn = np.linalg.norm(tphi)
            if np.isfinite(tn) and tn < (1.0 - 1e-4 * alpha) * norm:
                break
            alpha *= 0.5
        else:
            tp, th = p + alpha * delta[:n], h0 + alpha * delta[n]
            tphi, tload, th_film = residual(tp, th, False)
        p, h0 = tp, th
        h_c = max(np.interp(0.0, x, th_film), 1e-12)
        full_step = max(largest, abs(delta[n]) / h_c)
        if full_step < tol and abs(tload) <= 0.005:
            h_film = th_film * film_scale
            return {
                "iterations": iteration,
                "hc_m": np.interp(0.0, x, h_film),
                "hmin_m": h_film.min(),
                "pmax_pa": max(p.max(), 0.0) * p_h,
            }
    raise RuntimeError("not converged")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nodes", type=int, default=401)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    best = math.inf
    out = None
    for _ in range(a.repeat):
        t = time.process_time()
        out = solve(a.nodes)
        best = min(best, time.process_time() - t)
    print(
        f"time_s={best:.6f} iterations={out['iterations']} hc_m={out['hc_m']:.9e} "
        f"hmin_m={out['hmin_m']:.9e} pmax_pa={out['pmax_pa']:.9e}"
    )


if __name__ == "__main__":
    main()
