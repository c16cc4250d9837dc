#!/usr/bin/env python3
"""Side by side (issue 25, Speed): the cylindrical roller bearing's 2-DOF dynamics
(seed 003 eqs. 1-3, film off) in SciPy's solve_ivp (DOP853), the same model as
src/bearings/cylindrical_roller/dynamics with DynamicsModel::truck(5e-6): m = 12,
M = 50 kg, k_n = 2.0e9 N/m^(10/9), n = 10/9, rho = 5 um (no contact is lost, so no
events are needed), cage 83.26 rad/s, shaft 209 rad/s, 100 shaft revolutions, the last
80 sampled over whole cage cycles at 4096 Hz (rounded to a whole number per cycle),
rtol 1e-8 and atol = rtol * |static offset|.

Prints the wall time and the peaks the Rust example prints
(`cargo run --release --example crb_dynamics_peaks`): the base natural frequency (the
x spectrum's strongest Hann-interpolated peak away from the cage harmonics) and the
roller-1 load harmonics k*f_c by projection over whole cage cycles.

Run: python3 -m venv /tmp/dvenv && /tmp/dvenv/bin/pip install numpy scipy
     /tmp/dvenv/bin/python benches/crb_dynamics_scipy.py [rho_m]
"""
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

M = 50.0
m = 12
kn = 2.0e9
n = 10.0 / 9.0
rho = float(sys.argv[1]) if len(sys.argv) > 1 else 5e-6
C = -rho
wc = 83.26
ws = 209.0
F = np.array([-(1500.0 + 50.0 * 9.81), 0.0])
phases = 2.0 * np.pi * np.arange(m) / m
rtol = 1e-8


def loads(t, x, y):
    th = wc * t + phases
    c, s = np.cos(th), np.sin(th)
    d = 0.5 * (x * c + y * s) - C
    w = np.where(d > 0.0, kn * np.maximum(d, 0.0) ** n, 0.0)
    return w, c, s


def rhs(t, u):
    w, c, s = loads(t, u[0], u[1])
    return [u[2], u[3], (F[0] - np.dot(w, c)) / M, (F[1] - np.dot(w, s)) / M]


def static():
    def res(r):
        w, c, s = loads(0.0, r[0], r[1])
        return [np.dot(w, c) - F[0], np.dot(w, s) - F[1]]

    return fsolve(res, [-8e-6, 0.0], xtol=1e-14)


def hann_peak(x, dt):
    N = len(x)
    win = 0.5 * (1.0 - np.cos(2.0 * np.pi * np.arange(N) / N))
    a = np.abs(np.fft.rfft((x - x.mean()) * win)) * 4.0 / N
    df = 1.0 / (N * dt)
    return a, df


def interp(a, k, df):
    l, c, r = a[k - 1], a[k], a[k + 1]
    alpha, sign = (r / c, 1.0) if r >= l else (l / c, -1.0)
    d = min(max((2 * alpha - 1) / (alpha + 1), 0.0), 0.5)
    return (k + sign * d) * df


def main():
    r_s = static()
    T = 100 * 2 * np.pi / ws
    settle = 20 * 2 * np.pi / ws
    fc = wc / (2 * np.pi)
    per = round(4096.0 / fc)
    dt = 1.0 / (fc * per)
    cycles = int(np.floor((T - settle) * fc + 1e-9))
    times = settle + dt * np.arange(cycles * per)
    t_end = max(T, times[-1])
    atol = rtol * np.hypot(*r_s)
    t0 = time.perf_counter()
    c0 = time.process_time()
    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0, 0.0, 0.0], method="DOP853",
                    rtol=rtol, atol=atol, t_eval=times)
    wall = time.perf_counter() - t0
    cpu = time.process_time() - c0
    x = sol.y[0]
    a, df = hann_peak(x, dt)
    # f_bn: strongest local maximum above fc/2 not within 2 bins of a cage harmonic.
    cand = [k for k in range(1, len(a) - 1) if a[k] > a[k - 1] and a[k] >= a[k + 1]]
    cand.sort(key=lambda k: -a[k])
    fbn = None
    for k in cand:
        f = interp(a, k, df)
        if f < max(0.5 * fc, 2 * df):
            continue
        if any(abs(f - j * fc) <= 2 * df for j in range(1, 2 * m + 1)):
            continue
        fbn = f
        break
    w1 = np.array([loads(t, xi, yi)[0][0] for t, xi, yi in zip(times, sol.y[0], sol.y[1])])
    harm = []
    for k in range(1, 9):
        f = k * fc
        w0 = w1 - w1.mean()
        ph = 2 * np.pi * f * dt * np.arange(len(w1))
        harm.append(2.0 / len(w1) * np.hypot(np.dot(w0, np.cos(ph)), np.dot(w0, np.sin(ph))))
    # CPU time beside the wall time: on a shared machine the wall time of both sides
    # grows with the others' load, the CPU time much less.
    print(f"scipy DOP853: {wall:.3f} s wall, {cpu:.3f} s CPU, {sol.nfev} rhs evaluations, "
          f"rho {rho:g} m")
    print(f"static offset x {r_s[0]:.6e} m")
    print(f"f_bn {fbn:.4f} Hz")
    print("roller-1 load harmonics N: " + " ".join(f"{k + 1}:{h:.4f}" for k, h in enumerate(harm)))


if __name__ == "__main__":
    main()
