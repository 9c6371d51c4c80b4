#!/usr/bin/env python3
"""Plot the first four mode shapes of a FemModes JSON (out-of-plane displacement per node).

Usage:
    cargo run --release --example fem_report -- /tmp/modes.json
    python3 scripts/plot_modes.py /tmp/modes.json docs/modes.png

Needs matplotlib + numpy (not a dependency of the crate).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

src, dst = sys.argv[1], sys.argv[2]
d = json.load(open(src))
nodes = np.array(d["nodes"]) * 1e3  # mm
tri = mtri.Triangulation(nodes[:, 0], nodes[:, 1], np.array(d["triangles"]))
fig, axes = plt.subplots(2, 2, figsize=(11, 6.2), constrained_layout=True)
for k, ax in enumerate(axes.flat):
    w = np.array(d["shapes"][k])
    w = w / np.abs(w).max()
    tc = ax.tripcolor(tri, w, shading="gouraud", cmap="RdBu_r", vmin=-1, vmax=1)
    ax.tricontour(tri, w, levels=np.linspace(-0.9, 0.9, 10), colors="k", linewidths=0.4)
    ax.tricontour(tri, w, levels=[0.0], colors="k", linewidths=1.6)
    cl = np.array(d["clamped_nodes"])
    ax.plot(nodes[cl, 0], nodes[cl, 1], "ks", ms=3, label="clamped")
    ax.set_aspect("equal")
    ax.set_title(f"mode {k + 1}: {d['freq_hz'][k]:.1f} Hz ({d['kinds'][k]})")
    ax.set_xlabel("x spanwise (mm)")
    ax.set_ylabel("y chordwise (mm)")
fig.colorbar(tc, ax=axes, shrink=0.8, label="out-of-plane displacement (normalised; thick line = nodal line)")
fig.suptitle(
    "Default wing, 13 % camber, root clamp, 'paper-frequencies' material. "
    "Outline is SYNTHETIC (Manduca-like), not digitised from a specimen.",
    fontsize=10,
)
fig.savefig(dst, dpi=110)
print("wrote", dst)
