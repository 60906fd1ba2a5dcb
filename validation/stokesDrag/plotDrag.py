#!/usr/bin/python3
"""Tables and figures of validation/stokesDrag from results/runs.csv
(called by `stokesDrag.py plot`; Debian's python3 with numpy and matplotlib).

Box-size correction: for each body and flow direction, the box series
(L/D = 4, 6 and for the sphere 8, at 12 cells per D_eq) is fitted with
    1/K(L) = a + b (D/L) + c (D/L)^3          (Hasimoto-type)
with b fixed at Hasimoto's lattice sum (a and c fitted); K_inf = 1/a. The
sphere's three sizes also give b free, the check of b. The correction of a run in a box L is then
    1/K_inf = 1/K(L) - b (D/L) - c (D/L)^3,
applied to the resolution series (one box size, other viscous number):
the leading coefficient b is universal (Hasimoto's lattice sum:
-1.7601 (pi/6)^(1/3) = -1.4187 for any body in a simple cubic array), so the
correction hardly depends on the body's discretisation; the sphere at a
second box size checks it.
"""
import math
import os
import sys
from pathlib import Path

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import stokesDrag as sd  # noqa: E402
from validationTools import read_csv, write_csv  # noqa: E402

LABEL = {"sphere": "sphere", "prolate2": "prolate AR 2", "oblate0.5": "oblate AR 0.5"}
DIRS = {"x": "along the axis", "y": "across the axis"}


def f(r, k):
    return float(r[k])


def box_fits(rows, lam):
    """{(body, d): dict(a, b, c, K_inf, L list, K list, a_fixed_b, c_fixed_b)}"""
    fits = {}
    for body in sd.BODIES:
        series = sorted((r for r in rows if r["body"] == body and f(r, "cpd") == 12
                         and f(r, "lambda") == lam), key=lambda r: f(r, "L_over_D"))
        Ls = sorted({f(r, "L_over_D") for r in series})
        if len(Ls) < 2:
            continue
        for d in "xy":
            x = np.array([1 / f(r, "L_over_D") for r in series])
            y = np.array([1 / f(r, f"K{d}") for r in series])
            # b fixed at Hasimoto's value (the lattice sum, any body): a and c
            # through the box sizes (exact through 2, least squares beyond)
            A2 = np.vstack([np.ones_like(x), x ** 3]).T
            (a2, c2), *_ = np.linalg.lstsq(A2, y - sd.HASIMOTO_B * x, rcond=None)
            fit = dict(a=a2, b=sd.HASIMOTO_B, c=c2, K_inf=1 / a2, a_fixed_b=a2, c_fixed_b=c2,
                       K_inf_fixed_b=1 / a2, L=[1 / v for v in x], K=[1 / v for v in y],
                       b_free=float("nan"), c_free=float("nan"), K_inf_free=float("nan"))
            if len(Ls) >= 3:   # the check: b free (exact through 3 sizes)
                A = np.vstack([np.ones_like(x), x, x ** 3]).T
                (a, b, c), *_ = np.linalg.lstsq(A, y, rcond=None)
                fit.update(b_free=b, c_free=c, K_inf_free=1 / a)
            fits[(body, d)] = fit
    return fits


def correct(K, L, fit):
    """K_inf from K in a box L with a box fit's b and c."""
    x = 1 / L
    return 1 / (1 / K - fit["b"] * x - fit["c"] * x ** 3)


def sphere_radius_from_hasimoto(K, L):
    """The radius r' (D_eq = 1) of the sphere whose simple cubic array
    (Hasimoto/Sangani-Acrivos) has the measured drag: K (normalised by
    r_eq = 0.5) = (r'/0.5) K_H(4/3 pi r'^3/L^3)."""
    lo, hi = 0.3, 0.7
    for _ in range(100):
        r = 0.5 * (lo + hi)
        val = r / 0.5 * sd.hasimoto_K(4 / 3 * math.pi * r ** 3 / L ** 3)
        if val > K:
            hi = r
        else:
            lo = r
    return 0.5 * (lo + hi)


def main(runs_csv, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = read_csv(runs_csv, missing_ok=False)
    md = []
    fits = box_fits(rows, sd.LAMBDA_BOX)

    # 1. viscous number
    lam_rows = sorted((r for r in rows if r["body"] == "sphere" and f(r, "L_over_D") == 4
                       and f(r, "cpd") == 12), key=lambda r: -f(r, "lambda"))
    KH4 = sd.hasimoto_K(math.pi / 6 / 4 ** 3)
    md += ["## Steady drag against the viscous number of a cell (sphere, L/D = 4, 12 cells/D)", "",
           f"Hasimoto/Sangani-Acrivos simple cubic array at L/D = 4 (phi = {math.pi / 6 / 64:.5f}): "
           f"K = {KH4:.4f}.", "",
           "| lambda = nu dt/h^2 | dt | K (x) | K (y) | K/K_Hasimoto - 1 | box-corrected K_inf | "
           "steps (stage 2) | wall [s] | CPU [s] |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in lam_rows:
        kinf = correct(f(r, "Kx"), 4, fits[("sphere", "x")]) if ("sphere", "x") in fits else float("nan")
        md.append(f"| {f(r, 'lambda'):g} | {r['dt']} | {f(r, 'Kx'):.4f} | {f(r, 'Ky'):.4f} | "
                  f"{f(r, 'Kx') / KH4 - 1:+.1%} | {kinf:.4f} | {r['steps_stage2']} | {r['wall_s']} | "
                  f"{r['cpu_s']} |")
    md.append("")

    # 2. box size
    md += [f"## Box size (12 cells per D_eq, lambda = {sd.LAMBDA_BOX:g})", "",
           "1/K = a + b (D/L) + c (D/L)^3 with Hasimoto's b = "
           f"{sd.HASIMOTO_B:.4f} (the lattice sum, any body); a and c through the box sizes; "
           "K_inf = 1/a. For the sphere (three sizes) b free as the check, and c against "
           f"Hasimoto's pi/6 = {math.pi / 6:.4f}.", "",
           "| body | flow | K(4) | K(6) | K(8) | c | K_inf | analytic | error of K_inf | "
           "b free | K_inf (b free) |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    fit_rows = []
    for (body, d), fit in fits.items():
        ka = sd.analytic_K(sd.BODIES[body])["xy".index(d)]
        byL = dict(zip(fit["L"], fit["K"]))
        ks = " | ".join(f"{byL[L]:.4f}" if any(abs(L - l) < 1e-9 for l in byL) else "-"
                        for L in (4.0, 6.0, 8.0))
        md.append(f"| {LABEL[body]} | {DIRS[d]} | {ks} | {fit['c']:.3f} | {fit['K_inf']:.4f} | "
                  f"{ka:.4f} | {fit['K_inf'] / ka - 1:+.1%} | {fit['b_free']:.3f} | "
                  f"{fit['K_inf_free']:.4f} |")
        fit_rows.append(dict(body=body, flow=d, a=f"{fit['a']:.6f}", b=f"{fit['b']:.6f}",
                             c=f"{fit['c']:.6f}", K_inf=f"{fit['K_inf']:.6f}",
                             b_free=f"{fit['b_free']:.6f}", K_inf_free=f"{fit['K_inf_free']:.6f}",
                             K_analytic=f"{ka:.6f}", error=f"{fit['K_inf'] / ka - 1:.5f}"))
    md.append("")
    if fit_rows:
        write_csv(os.path.join(out, "boxFit.csv"), fit_rows)

    # sphere against Hasimoto
    sph = sorted((r for r in rows if r["body"] == "sphere" and f(r, "cpd") == 12),
                 key=lambda r: (f(r, "lambda"), f(r, "L_over_D")))
    md += ["## Sphere against the simple cubic array (Hasimoto 1959; Sangani and Acrivos 1982)",
           "", "r_H: the radius whose array drag equals the measured one (r_eq = 0.5): a box-size "
           "independent r_H means the periodic box behaves as the theory says.", "",
           "| lambda | L/D | phi | K_Hasimoto | K measured | ratio | r_H/r_eq | K box-corrected |",
           "|---|---|---|---|---|---|---|---|"]
    for r in sph:
        if f(r, "lambda") not in (sd.LAMBDA_BOX, sd.LAMBDA):
            continue
        L = f(r, "L_over_D")
        kh = sd.hasimoto_K(math.pi / 6 / L ** 3)
        k = 0.5 * (f(r, "Kx") + f(r, "Ky"))
        rh = sphere_radius_from_hasimoto(k, L)
        kc = correct(k, L, fits[("sphere", "x")]) if ("sphere", "x") in fits else float("nan")
        md.append(f"| {f(r, 'lambda'):g} | {L:g} | {math.pi / 6 / L ** 3:.5f} | {kh:.4f} | {k:.4f} | "
                  f"{k / kh:.4f} | {rh / 0.5:.4f} | {kc:.4f} |")
    md.append("")

    # 3. resolution
    res_rows = []
    md += [f"## Resolution (L/D = 4, lambda = {sd.LAMBDA:g}, box correction of the lambda = "
           f"{sd.LAMBDA_BOX:g} fits)", "",
           "| body | cells/D_eq | cells | K(4) x | K(4) y | K_inf x | K_inf y | analytic x | "
           "analytic y | error x | error y | steps | wall [s] | CPU [s] |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for body in sd.BODIES:
        series = sorted((r for r in rows if r["body"] == body and f(r, "L_over_D") == 4
                         and f(r, "lambda") == sd.LAMBDA), key=lambda r: f(r, "cpd"))
        for r in series:
            ka = sd.analytic_K(sd.BODIES[body])
            kinf = [correct(f(r, f"K{d}"), 4, fits[(body, d)]) if (body, d) in fits else float("nan")
                    for d in "xy"]
            err = [kinf[i] / ka[i] - 1 for i in range(2)]
            steps = int(r["steps_stage1"]) + int(r["steps_stage2"])
            md.append(f"| {LABEL[body]} | {f(r, 'cpd'):g} | {r['cells']} | {f(r, 'Kx'):.4f} | "
                      f"{f(r, 'Ky'):.4f} | {kinf[0]:.4f} | {kinf[1]:.4f} | {ka[0]:.4f} | {ka[1]:.4f} | "
                      f"{err[0]:+.1%} | {err[1]:+.1%} | {steps} | {r['wall_s']} | {r['cpu_s']} |")
            res_rows.append(dict(body=body, cpd=r["cpd"], cells=r["cells"], Kx_box=r["Kx"],
                                 Ky_box=r["Ky"], Kx_inf=f"{kinf[0]:.6f}", Ky_inf=f"{kinf[1]:.6f}",
                                 Kx_analytic=f"{ka[0]:.6f}", Ky_analytic=f"{ka[1]:.6f}",
                                 error_x=f"{err[0]:.5f}", error_y=f"{err[1]:.5f}",
                                 steps=steps, wall_s=r["wall_s"], cpu_s=r["cpu_s"]))
    md.append("")
    if res_rows:
        write_csv(os.path.join(out, "resolution.csv"), res_rows)
    with open(os.path.join(out, "table.md"), "w") as fh:
        fh.write("\n".join(md) + "\n")
    print("\n".join(md))

    # figures: error and CPU time against cells per diameter
    if res_rows:
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.3))
        colors = {"sphere": "k", "prolate2": "C0", "oblate0.5": "C3"}
        for body in sd.BODIES:
            rr = [r for r in res_rows if r["body"] == body]
            if not rr:
                continue
            n = np.array([float(r["cpd"]) for r in rr])
            for d, mk in (("x", "o-"), ("y", "s--")):
                e = np.abs([float(r[f"error_{d}"]) for r in rr]) * 100
                if body == "sphere" and d == "y":
                    continue
                ax[0].loglog(n, e, mk, color=colors[body],
                             label=f"{LABEL[body]}" + ("" if body == "sphere" else f", {DIRS[d]}"))
            ax[1].loglog(n, [float(r["cpu_s"]) for r in rr], "o-", color=colors[body],
                         label=LABEL[body])
        nn = np.array([8, 24])
        ax[0].loglog(nn, 12 * 8 / nn, "k:", lw=1, label="slope -1")
        ax[0].set_xlabel("cells per equal-volume diameter")
        ax[0].set_ylabel("|K_inf / K_analytic - 1|  [%]")
        ax[0].set_title(f"Stokes drag error (box-corrected), lambda = {sd.LAMBDA:g}")
        ax[0].grid(True, which="both", alpha=0.3)
        ax[0].legend(fontsize=8)
        ax[1].set_xlabel("cells per equal-volume diameter")
        ax[1].set_ylabel("solver CPU time [s]")
        ax[1].set_title("cost (L/D = 4, one core, to steady state)")
        ax[1].grid(True, which="both", alpha=0.3)
        ax[1].legend(fontsize=8)
        from matplotlib.ticker import NullFormatter, ScalarFormatter
        for a in ax:
            a.set_xticks([8, 12, 16, 24])
            a.set_xticklabels(["8", "12", "16", "24"])
            a.xaxis.set_minor_formatter(NullFormatter())
            a.yaxis.set_major_formatter(ScalarFormatter())
        fig.tight_layout()
        fig.savefig(os.path.join(out, "errorVsResolution.png"), dpi=120)

    if fits:
        fig, ax = plt.subplots(figsize=(6, 4.3))
        xx = np.linspace(0, 0.26, 100)
        for (body, d), fit in fits.items():
            if body == "sphere" and d == "y":
                continue
            c = {"sphere": "k", "prolate2": "C0", "oblate0.5": "C3"}[body]
            ls = "-" if d == "x" else "--"
            ax.plot([1 / L for L in fit["L"]], [1 / k for k in fit["K"]], "o" if d == "x" else "s",
                    color=c)
            ax.plot(xx, fit["a"] + fit["b"] * xx + fit["c"] * xx ** 3, ls, color=c,
                    label=f"{LABEL[body]}" + ("" if body == "sphere" else f", {DIRS[d]}"))
            ka = sd.analytic_K(sd.BODIES[body])["xy".index(d)]
            ax.plot([0], [1 / ka], "*", color=c, ms=10)
        ax.plot(xx, [1 / sd.hasimoto_K(math.pi / 6 * x ** 3) for x in xx], "k:", lw=1,
                label="Hasimoto, sphere")
        ax.set_xlabel("D_eq / L")
        ax.set_ylabel("1/K")
        ax.set_title(f"Box-size extrapolation (12 cells/D, lambda = {sd.LAMBDA_BOX:g}); * analytic")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "boxSize.png"), dpi=120)

    if lam_rows:
        fig, ax = plt.subplots(figsize=(6, 4.3))
        lam = [f(r, "lambda") for r in lam_rows]
        ax.semilogx(lam, [f(r, "Kx") for r in lam_rows], "o-k", label="measured, L/D = 4")
        ax.axhline(KH4, color="C2", ls="--", label="Hasimoto array, L/D = 4")
        ax.set_xlabel("viscous number of a cell  lambda = nu dt / h^2")
        ax.set_ylabel("K = F / (6 pi mu r U)")
        ax.set_title("Sphere, 12 cells/D: steady drag depends on dt")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "dragVsViscousNumber.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results", "runs.csv"),
         sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "results"))
