#!/usr/bin/python3
"""Table and figures of validation/jefferyOrbit from results/runs.csv and the
time series results/<name>.h5 (called by `jefferyOrbit.py plot`).

Period estimates of a run started at phi = 0 (axis along the gradient):
  T_half_pi = 4 t(phi = pi/2),  T_pi = 2 t(phi = pi)   (Jeffery's curve is
  symmetric: phi = pi/2 at T/4, pi at T/2), and T_fit from a least-squares
  fit of Jeffery's curve tan(phi) = r' tan(2 pi t/T + theta0) with T, r' and
  theta0 free (t > 1).
"""
import json
import math
import os
import sys
from pathlib import Path

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import jeffery  # noqa: E402
from validationTools import read_csv  # noqa: E402

R = 2.5


def read_h5(path):
    import h5py
    with h5py.File(path, "r", locking=False) as f:
        n = min(f[k].shape[0] for k in ("time", "orientation", "angularVelocity"))
        return f["time"][:n], f["orientation"][:n, 0, :], f["angularVelocity"][:n, 0, :]


def main(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = read_csv(os.path.join(results, "runs.csv"), missing_ok=False)
    TJ = jeffery.jeffery_period(R)
    md = [f"## Period (r = {R}, Re = gamma a^2/nu = 0.1; Jeffery: T = 2 pi (r + 1/r)/gamma = "
          f"{TJ:.4f})", "",
          "T: the time at which phi reaches 2 pi (one full period); T(pi/2), T(pi): 4 and 2 "
          "times the crossings of pi/2 and pi; T fit, r': Jeffery's curve fitted with T and "
          "r' free; T_J(r') = 2 pi (r' + 1/r'), Jeffery's period for the fitted aspect ratio.",
          "",
          "| run | cells/minor diameter | cells | gamma dt | T(pi/2) | T(pi) | T | error of T | "
          "T fit | r' | T_J(r') | T / T_J(r') - 1 | steps | CPU [s] |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    orbit_rows = [r for r in rows if r["group"] == "orbit"]
    metrics = {}
    for r in orbit_rows:
        def fmt(k):
            return f"{float(r[k]):.3f}" if r.get(k) else "-"
        T = float(r["T_2pi"]) if r.get("T_2pi") else None
        tj_fit = 2 * math.pi * (float(r["r_fit"]) + 1 / float(r["r_fit"])) if r.get("r_fit") else None
        md.append(f"| {r['name']} | {r['cpd']} | {r['cells']} | {r['dt']} | "
                  f"{fmt('T_half_pi')} | {fmt('T_pi')} | {fmt('T_2pi')} | "
                  + (f"{100 * (T / TJ - 1):+.2f} %" if T else "-") + " | "
                  f"{fmt('T_fit')} | {r.get('r_fit') or '-'} | "
                  + (f"{tj_fit:.3f} | " if tj_fit else "- | ")
                  + (f"{100 * (T / tj_fit - 1):+.2f} %" if T and tj_fit else "-")
                  + f" | {r['steps']} | {r['cpu_s']} |")
        if T:
            metrics["period_error_pct"] = max(metrics.get("period_error_pct", 0.0),
                                              round(abs(100 * (T / TJ - 1)), 3))
            metrics[f"period_error_pct_c{r['cpd']}"] = round(100 * (T / TJ - 1), 3)
            if tj_fit:
                metrics[f"period_error_fitted_r_pct_c{r['cpd']}"] = round(100 * (T / tj_fit - 1), 3)
            periods = float(r["end_time"]) / T
            metrics["periods_simulated"] = round(min(metrics.get("periods_simulated", periods),
                                                     periods), 3)
    md.append("")
    with open(os.path.join(results, "metrics.json"), "w") as fh:
        json.dump(metrics, fh, indent=1, sort_keys=True)
        fh.write("\n")
    rates = {}
    for r in rows:
        if r["group"] == "rates":
            tag = r["name"][len("rates-"):].rsplit("-phi", 1)[0]
            rates.setdefault(tag, {})[r["phi0"]] = r
    if rates:
        md += ["## Rotation rates at phi = 0 and pi/2 (short runs, 200 steps or gamma t = 0.14)", "",
               "dphi/dt = -omega_z = A cos^2 phi + B sin^2 phi through the two (mean over the "
               "last quarter of each run): T = 2 pi/sqrt(A B), r' = sqrt(A/B); Jeffery: "
               f"A = {R * R / (R * R + 1):.4f}, B = {1 / (R * R + 1):.4f}.", "",
               "| case | cells | box | dt | virtualMass | A | B | A error | B error | r' | T | "
               "T error | CPU [s] |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for tag, pair in rates.items():
            if "0" not in pair or "90" not in pair:
                continue
            p0, p9 = pair["0"], pair["90"]
            f1, w1 = float(p0["phi_mean"]), -float(p0["omega_mean"])
            f2, w2 = float(p9["phi_mean"]), -float(p9["omega_mean"])
            M = np.array([[math.cos(f1) ** 2, math.sin(f1) ** 2],
                          [math.cos(f2) ** 2, math.sin(f2) ** 2]])
            A, B = np.linalg.solve(M, [w1, w2])
            T = 2 * math.pi / math.sqrt(A * B)
            Aj, Bj = R * R / (R * R + 1), 1 / (R * R + 1)
            cpu = float(p0["cpu_s"]) + float(p9["cpu_s"])
            md.append(f"| {tag} | {p0['cells']} | {p0['box']} | {p0['dt']} | {p0['virtualMass']} | "
                      f"{A:.4f} | {B:.4f} | {A / Aj - 1:+.1%} | {B / Bj - 1:+.1%} | "
                      f"{math.sqrt(A / B):.3f} | {T:.3f} | {T / TJ - 1:+.1%} | {cpu:.0f} |")
        md.append("")
    stab = [r for r in rows if r["group"] == "stability"]
    if stab:
        md += ["## Stability of the explicit coupling (150 steps from the start-up)", "",
               "growth: the factor per step of the step-to-step alternation of omega_z over "
               "the second half of the run (> 1: the period-2 oscillation grows).", "",
               "| rho_p/rho_f | virtualMass | dt | lambda | penaltyRatio | subSteps | ddt | "
               "nOuterCorrectors | status | growth/step | omega_z end | Jeffery | CPU [s] |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in stab:
            md.append(f"| {r['density_ratio']} | {r['virtualMass']} | {r['dt']} | {r['lambda']} | "
                      f"{r['penaltyRatio']} | {r['subSteps']} | {r['ddt']} | "
                      f"{r.get('nOuterCorrectors') or 1} | {r['status']} | {r['growth_per_step']} | "
                      f"{r['omega_end']} | {r['omega_jeffery_end']} | {r['cpu_s']} |")
        md.append("")
    with open(os.path.join(results, "table.md"), "w") as fh:
        fh.write("\n".join(md) + "\n")
    print("\n".join(md))

    for r in orbit_rows:
        path = os.path.join(results, f"{r['name']}.h5")
        if not os.path.exists(path):
            continue
        t, q, om = read_h5(path)
        phi, pz = jeffery.phi_of(q)
        tt = np.linspace(0, t[-1], 2000)
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.3))
        ax[0].plot(t, np.degrees(phi), "k-", lw=2, label="spheroidFoam")
        ax[0].plot(tt, np.degrees(jeffery.jeffery_phi(tt, R)), "C3--", label=f"Jeffery, r = {R}")
        fit = jeffery.fit_jeffery(t, phi, R)
        if fit:
            ax[0].plot(tt, np.degrees(jeffery.fitted_phi(tt, fit)), "C0:",
                       label=f"fit: r' = {fit['r_eff']:.2f}, T = {fit['T_fit']:.2f}")
        for k in (1, 2):
            ax[0].axhline(90 * k, color="0.7", lw=0.8)
        ax[0].set_xlabel("gamma t")
        ax[0].set_ylabel("phi [deg] (axis from the gradient direction)")
        ax[0].set_title(f"{r['name']}: T_J = {TJ:.3f}")
        ax[0].legend(fontsize=8)
        ax[0].grid(True, alpha=0.3)
        pw = np.mod(phi, math.pi)
        ph = np.linspace(0, math.pi, 400)
        m = t > 0.05
        ax[1].plot(np.degrees(pw[m]), -om[m, 2], "k.", ms=1.5, label="spheroidFoam, -omega_z")
        ax[1].plot(np.degrees(ph), jeffery.jeffery_rate(ph, R), "C3--", label="Jeffery dphi/dt")
        ax[1].set_xlabel("phi mod 180 [deg]")
        ax[1].set_ylabel("dphi/dt / gamma")
        ax[1].legend(fontsize=8)
        ax[1].grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(results, f"{r['name']}.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results"))
