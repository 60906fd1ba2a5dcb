"""Density-ratio study: stability of the explicit body update (validation/densityRatio/Allrun).

Per run (scheme, rho_p/rho_f): status (completed / crashed / unbounded), the largest vertical
speed, the speed at the end, and the odd-even oscillation of the vertical velocity,
max_n |u_n - (u_{n-1} + u_{n+1})/2| over the second half of the run divided by max |u|.
A run is called stable when it completed, stayed bounded (|u| < 1 m/s; the terminal speeds
here are below 0.2 m/s) and its oscillation is below 2 %.
"""
import glob
import json
import os
import sys
from pathlib import Path

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import write_csv  # noqa: E402

# plot.py RUN_ROOT OUT_DIR: the runs are RUN_ROOT/<scheme>-cv<C_v>-<ratio>
run_root = os.path.abspath(sys.argv[1])
here = os.path.abspath(sys.argv[2])
rows = []
CONFIGS = ("Euler, C_v 0", "backward, C_v 0", "backward, C_v 0.5")
fig, axes = plt.subplots(1, len(CONFIGS), figsize=(5 * len(CONFIGS), 4.2))
for d in sorted(glob.glob(os.path.join(run_root, "*-*"))):
    scheme, cv, ratio = os.path.basename(d).split("-", 2)
    scheme = f"{scheme}, C_v {cv[2:]}"
    ratio = float(ratio)
    logp = os.path.join(d, "log.solver")
    log = open(logp).read() if os.path.exists(logp) else ""
    completed = "\nEnd\n" in log
    h5 = os.path.join(d, "postProcessing", "immersedBodies", "bodies.h5")
    t = w = np.zeros(0)
    if os.path.exists(h5):
        with h5py.File(h5, "r", locking=False) as f:
            t = np.asarray(f["time"][:], dtype=float)
            w = np.asarray(f["velocity"][:, 0, 2], dtype=float)
    finite = len(w) > 4 and bool(np.all(np.isfinite(w)))
    umax = float(np.nanmax(np.abs(w))) if len(w) else float("nan")
    bounded = finite and umax < 1.0
    half = w[len(w) // 2:]
    osc = (float(np.max(np.abs(half[1:-1] - 0.5 * (half[:-2] + half[2:])))) / umax
           if bounded and umax > 0 and len(half) > 2 else float("nan"))
    status = "crashed" if not completed else ("unbounded" if not bounded else "completed")
    stable = status == "completed" and osc < 0.02
    rows.append(dict(scheme=scheme, ratio=ratio, status=status, stable=stable, steps=max(len(w) - 1, 0),
                     maxSpeed=umax, finalVelocity=float(w[-1]) if len(w) else float("nan"),
                     oscillation=osc))
    ax = axes[CONFIGS.index(scheme)] if scheme in CONFIGS else axes[-1]
    if len(w):
        ax.plot(t, np.clip(w, -0.5, 0.5), label=f"{ratio:g}")
for ax, s in zip(axes, CONFIGS):
    ax.set_title(f"{s}: vertical velocity of the sphere")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("u_z (m/s), clipped to +-0.5")
    if ax.lines:
        ax.legend(title="rho_p/rho_f", fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(os.path.join(here, "densityRatio.png"), dpi=110)
rows.sort(key=lambda r: (r["scheme"], -r["ratio"]))
os.makedirs(os.path.join(here, "results"), exist_ok=True)
write_csv(os.path.join(here, "results", "runs.csv"), rows)
metrics = {}
with open(os.path.join(here, "results", "summary.md"), "w") as f:
    f.write("| scheme, virtual mass | rho_p/rho_f | status | stable | max speed (m/s) | final u_z (m/s) "
            "| odd-even oscillation |\n|---|---|---|---|---|---|---|\n")
    for r in rows:
        f.write(f"| {r['scheme']} | {r['ratio']:g} | {r['status']} | {'yes' if r['stable'] else 'no'} "
                f"| {r['maxSpeed']:.4f} | {r['finalVelocity']:+.4f} | {100 * r['oscillation']:.2f} % |\n")
    for s in CONFIGS:
        lowest = None   # the lowest ratio such that it and every ratio above it are stable
        for r in sorted((r for r in rows if r["scheme"] == s), key=lambda r: -r["ratio"]):
            if not r["stable"]:
                break
            lowest = r["ratio"]
        if lowest is not None:
            f.write(f"\n{s}: stable for every ratio tested down to rho_p/rho_f = {lowest:g}\n")
        key = s.replace(", C_v ", "_cv").replace(".", "p")
        metrics[f"lowest_stable_ratio_{key}"] = lowest
    for r in rows:
        if r["scheme"] == "backward, C_v 0.5" and r["ratio"] == 0.5:
            metrics["oscillation_pct_default_ratio_0p5"] = round(100 * r["oscillation"], 3)
with open(os.path.join(here, "results", "metrics.json"), "w") as f:
    json.dump(metrics, f, indent=1, sort_keys=True)
    f.write("\n")
print(open(os.path.join(here, "results", "summary.md")).read())
