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
import json
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

    all_rows = read_csv(runs_csv, missing_ok=False)
    rows = [r for r in all_rows if r.get("forcing", "surfaceCorrected") == "surfaceCorrected"]
    cut_rows = [r for r in all_rows if r.get("forcing") == "cutCellFraction"]
    md = ["# Stokes drag of a fixed spheroid: forcing surfaceCorrected (the default)", "",
          "Produced by `validation/stokesDrag/Allrun -plot` from results/runs.csv.", ""]
    metrics = {}
    fits = box_fits(rows, sd.LAMBDA_BOX)

    # 1. viscous number
    lam_rows = sorted((r for r in rows if r["body"] == "sphere" and f(r, "L_over_D") == 4
                       and f(r, "cpd") == 12 and f(r, "lambda") in sd.LAMBDAS),
                      key=lambda r: -f(r, "lambda"))
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
    if len(lam_rows) >= 2:
        ks = [f(r, "Kx") for r in lam_rows]
        spread = (max(ks) - min(ks)) / np.mean(ks) * 100
        metrics["lambda_spread_pct_12"] = round(spread, 4)
        md += ["", f"Spread over lambda = {min(sd.LAMBDAS):g}-{max(sd.LAMBDAS):g}: "
               f"(max - min)/mean = {spread:.3f} % ({len(lam_rows)} runs)."]
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

    # the observed order: |error| = C cpd^-p fitted over the resolutions run,
    # and the self-convergence order of the three finest (no reference needed)
    md += ["## Observed order of convergence", "",
           "p: the slope of log|error| against log(cells/D), least squares over the resolutions "
           "run (error after the box correction). p_self: from the three finest runs alone, "
           "(K2 - K1)/(K3 - K2) = (n1^-p - n2^-p)/(n2^-p - n3^-p), which needs no reference.", "",
           "| body | flow | cells/D | errors | p | p_self |", "|---|---|---|---|---|---|"]
    orders = []
    for body in sd.BODIES:
        rr = [r for r in res_rows if r["body"] == body]
        if len(rr) < 2:
            continue
        n = np.array([float(r["cpd"]) for r in rr])
        for d in ("x",) if body == "sphere" else ("x", "y"):
            e = np.array([abs(float(r[f"error_{d}"])) for r in rr])
            p = -np.polyfit(np.log(n), np.log(np.maximum(e, 1e-12)), 1)[0]
            k = np.array([float(r[f"K{d}_inf"]) for r in rr])
            p_self = float("nan")
            if len(rr) >= 3:
                ratio = (k[-2] - k[-3]) / (k[-1] - k[-2])
                lo, hi = 0.05, 8.0
                g = lambda q: (n[-3] ** -q - n[-2] ** -q) / (n[-2] ** -q - n[-1] ** -q) - ratio
                if g(lo) * g(hi) < 0:
                    for _ in range(200):
                        mid = 0.5 * (lo + hi)
                        lo, hi = (mid, hi) if g(lo) * g(mid) > 0 else (lo, mid)
                    p_self = 0.5 * (lo + hi)
            orders.append(p)
            md.append(f"| {LABEL[body]} | {DIRS[d] if body != 'sphere' else '-'} | "
                      + ", ".join(f"{v:g}" for v in n) + " | "
                      + ", ".join(f"{float(r[f'error_{d}']):+.2%}" for r in rr)
                      + f" | {p:.2f} | {p_self:.2f} |")
    md.append("")
    if orders:
        metrics["min_observed_order"] = round(float(min(orders)), 3)
    for cpd in (12, 16, 24):
        errs = [abs(float(r[f"error_{d}"])) * 100 for r in res_rows if float(r["cpd"]) == cpd
                for d in "xy"]
        if errs:
            metrics[f"max_abs_error_pct_{cpd}"] = round(max(errs), 4)

    # the cut-cell forcing, for comparison (same harness, same box correction)
    cut_res = []
    if cut_rows:
        md += [f"## Forcing cutCellFraction, for comparison (sphere, L/D = 4, lambda = "
               f"{sd.LAMBDA_CUTCELL:g}, box correction of the surfaceCorrected fits)", "",
               "| cells/D_eq | cells | K(4) | K_inf | error | steps | wall [s] | CPU [s] |",
               "|---|---|---|---|---|---|---|---|"]
        for r in sorted(cut_rows, key=lambda r: f(r, "cpd")):
            kinf = correct(f(r, "Kx"), 4, fits[("sphere", "x")]) if ("sphere", "x") in fits \
                else float("nan")
            steps = int(r["steps_stage1"]) + int(r["steps_stage2"])
            md.append(f"| {f(r, 'cpd'):g} | {r['cells']} | {f(r, 'Kx'):.4f} | {kinf:.4f} | "
                      f"{kinf - 1:+.1%} | {steps} | {r['wall_s']} | {r['cpu_s']} |")
            cut_res.append(dict(cpd=f(r, "cpd"), cells=float(r["cells"]), err=kinf - 1,
                                cpu=float(r["cpu_s"]), steps=steps))
        md.append("")

    # the headline trade: what 2 % on the sphere's drag costs with each forcing
    def cost_to(series, target=0.02):
        """(cpd, cells, CPU s, how) at |error| = target: the coarsest run within it, or a
        power-law interpolation/extrapolation of |error|, cells and CPU in cells/D."""
        series = sorted(series, key=lambda r: r["cpd"])
        within = [r for r in series if abs(r["err"]) <= target]
        if within and within[0] is series[0]:
            r = within[0]
            return r["cpd"], r["cells"], r["cpu"], "measured (coarsest run)"
        n = np.log([r["cpd"] for r in series])
        pe = np.polyfit(n, np.log(np.abs([r["err"] for r in series])), 1)
        x = (math.log(target) - pe[1]) / pe[0]
        pc = np.polyfit(n, np.log([r["cells"] for r in series]), 1)
        pt = np.polyfit(n, np.log([r["cpu"] for r in series]), 1)
        how = "interpolated" if n[0] <= x <= n[-1] else "extrapolated"
        return math.exp(x), math.exp(np.polyval(pc, x)), math.exp(np.polyval(pt, x)), how
    sph_new = [dict(cpd=float(r["cpd"]), cells=float(r["cells"]), err=float(r["error_x"]),
                    cpu=float(r["cpu_s"])) for r in res_rows if r["body"] == "sphere"]
    if sph_new and len(cut_res) >= 2:
        md += ["## The cost of 2 % on the sphere's drag", "",
               "| forcing | cells/D | cells (L/D = 4) | CPU to steady state [s] | how |",
               "|---|---|---|---|---|"]
        for label, series in (("cutCellFraction (lambda 0.25)", cut_res),
                              (f"surfaceCorrected (lambda {sd.LAMBDA:g})", sph_new)):
            cpd, cells, cpu, how = cost_to(series)
            md.append(f"| {label} | {cpd:.1f} | {cells:.0f} | {cpu:.0f} | {how} |")
            key = "cutCell" if label.startswith("cut") else "surfaceCorrected"
            metrics[f"sphere_cpd_for_2pct_{key}"] = round(cpd, 2)
            metrics[f"sphere_cells_for_2pct_{key}"] = round(cells)
            metrics[f"sphere_cpu_s_for_2pct_{key}"] = round(cpu, 1)
        md.append("")
    if res_rows:
        write_csv(os.path.join(out, "resolution.csv"), res_rows)
    with open(os.path.join(out, "table.md"), "w") as fh:
        fh.write("\n".join(md) + "\n")
    with open(os.path.join(out, "metrics.json"), "w") as fh:
        json.dump({k: (v if not (isinstance(v, float) and not math.isfinite(v)) else None)
                   for k, v in metrics.items()}, fh, indent=1, sort_keys=True)
        fh.write("\n")
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
        ax[0].loglog(nn, 1.0 * (8 / nn) ** 2, "k:", lw=1, label="slope -2")
        if cut_res:
            ax[0].loglog([r["cpd"] for r in cut_res], [abs(r["err"]) * 100 for r in cut_res],
                         "x:", color="0.5", label=f"sphere, cutCellFraction (lambda "
                         f"{sd.LAMBDA_CUTCELL:g})")
            ax[1].loglog([r["cpd"] for r in cut_res], [r["cpu"] for r in cut_res], "x:",
                         color="0.5", label="sphere, cutCellFraction")
        ax[0].set_xlabel("cells per equal-volume diameter")
        ax[0].set_ylabel("|K_inf / K_analytic - 1|  [%]")
        ax[0].set_title(f"Stokes drag error (box-corrected), lambda = {sd.LAMBDA:g}")
        ax[0].grid(True, which="both", alpha=0.3)
        ax[0].legend(fontsize=8)
        ax[1].set_xlabel("cells per equal-volume diameter")
        ax[1].set_ylabel("solver CPU time [s]")
        ax[1].set_title("cost (L/D = 4, to steady state)")
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
        ax.set_title("Sphere, 12 cells/D: steady drag against the step")
        ax.set_ylim(KH4 * 0.97, KH4 * 1.01)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "dragVsViscousNumber.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results", "runs.csv"),
         sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "results"))
