#!/usr/bin/env python3
"""Side-by-side: wingbeat vs scipy's solve_ivp(DOP853, rtol=1e-10) on the paper case.

Both solve the same thing: Eq. 13 for the paper's two modes, four right-hand sides each
(Euler, centrifugal, Coriolis, total), 2 s sampled at 10 kHz, zero initial conditions.
The scipy right-hand side is written here independently from the paper's equations.
Prints both median times, their ratio and the largest difference relative to each series' peak.

Usage: python3 benches/scipy_compare.py [path/to/wingbeat]   (needs numpy and scipy)
"""
import json, math, statistics, subprocess, sys, time

import numpy as np
from scipy.integrate import solve_ivp

exe = sys.argv[1] if len(sys.argv) > 1 else "target/release/wingbeat"
REPEAT = 7

fd = 25.0; wd = 2 * math.pi * fd
a0, b0, g0 = 0.8, 0.5, 0.2
modes = [(62.5, (0.7552e-5, 0.0934e-5)), (86.9, (-0.1728e-5, -0.0033e-5))]
t_eval = np.arange(20001) / 10000.0

def rhs_factory(f_hz, a, term):
    w2 = (2 * math.pi * f_hz) ** 2
    ax, ay = a
    bx, by = -ay, ax
    def rhs(t, y):
        s, c = math.sin(wd * t), math.cos(wd * t)
        al_d, al_dd = a0 * wd * c, -a0 * wd * wd * s
        be, be_d, be_dd = b0 * s, b0 * wd * c, -b0 * wd * wd * s
        ga, ga_d = g0 * s, g0 * wd * c
        sb, cb = math.sin(be), math.cos(be)
        ox, oy, oz = al_d * cb, be_d, al_d * sb
        odx = al_dd * cb - al_d * be_d * sb
        ody = be_dd
        fe = -(odx * (ga * ax - bx) + ody * (ga * ay - by))
        fc = -oz * (ox * (ax + ga * bx) + oy * (ay + ga * by))
        fr = -2 * ga_d * (ox * ax + oy * ay)
        f = {"euler": fe, "centrifugal": fc, "coriolis": fr, "total": fe + fc + fr}[term]
        k = w2 - (ox * ox + oy * oy)
        return [y[1], f - k * y[0]]
    return rhs

def run_scipy():
    out = []
    for f_hz, a in modes:
        per = {}
        for term in ["euler", "centrifugal", "coriolis", "total"]:
            sol = solve_ivp(rhs_factory(f_hz, a, term), (0, 2.0), [0.0, 0.0], method="DOP853",
                            rtol=1e-10, atol=1e-20, t_eval=t_eval)
            per[term] = sol.y[0]
        out.append(per)
    return out

times = []
for _ in range(3):
    t0 = time.perf_counter(); ref = run_scipy(); times.append(time.perf_counter() - t0)
scipy_ms = statistics.median(times) * 1e3

res = subprocess.run([exe, "simulate", "--preset", "paper", "--repeat", "201"],
                     check=True, capture_output=True, text=True)
wb = json.loads(res.stdout)
wb_ms = wb["timing_ms"]["median"]

worst = 0.0
for k, per in enumerate(ref):
    for term, y in per.items():
        ours = np.array(wb["modes"][k]["q"][term])
        worst = max(worst, float(np.max(np.abs(ours - y)) / np.max(np.abs(y))))

print(f"scipy solve_ivp DOP853 rtol=1e-10 (8 integrations): median {scipy_ms:9.2f} ms over {len(times)} runs")
print(f"wingbeat simulate (same 8 responses + Floquet):      median {wb_ms:9.3f} ms over {wb['timing_ms']['runs']} runs")
print(f"ratio scipy / wingbeat: {scipy_ms / wb_ms:.0f}x")
print(f"max |difference| / peak, over all 8 series: {worst:.2e}")
