#!/usr/bin/python3
"""Table, metrics and figures of validation/periodicArray from
DIR/results/runs.csv (called by `periodicArray.py plot` and after `run`;
Debian's python3 with numpy and matplotlib):

  results/table.md          the reference check (expansion against Zick and
                            Homsy), every run, the error per fraction and
                            resolution with the observed order, the straddle
                            comparison, the cost of the runs still to do
  results/metrics.json      flat: max_abs_error_pct_N (N = 8, 12, 16: the
                            largest |error| over phi <= 0.2 at N cells/D,
                            null without runs), error_pct_phiX_N and K_phiX_N
                            per run, observed_order_phiX, straddle_difference_pct
                            (largest |K_corner/K_centre - 1| in %, null until
                            the corner runs exist)
  results/dragVsFraction.png    K and the error against phi
  results/errorVsResolution.png |error| against cells per D
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
import periodicArray as pa  # noqa: E402
from validationTools import read_csv  # noqa: E402

MARKERS = {8: "^", 12: "s", 16: "D"}
COLOURS = {8: "tab:red", 12: "tab:blue", 16: "tab:green"}


def fnum(r, k):
    return float(r[k])


def fmt(x, spec):
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else format(x, spec)


def observed_order(points):
    """Slope -d log|e|/d log n of the errors e at cells per D n (least
    squares), or None with fewer than two resolutions or a change of sign."""
    if len(points) < 2:
        return None
    n = np.array([p[0] for p in points])
    e = np.array([p[1] for p in points])
    if np.any(e == 0) or not (np.all(e > 0) or np.all(e < 0)):
        return None
    return float(-np.polyfit(np.log(n), np.log(np.abs(e)), 1)[0])


def gap_cells(r):
    """The narrowest gap between neighbouring spheres, L - D, in cells."""
    return (fnum(r, "L_over_D") - 1) * fnum(r, "cpd_eff")


def radius_error_pct(r):
    """The relative error of the sphere's effective radius that accounts for
    the run's error in K (to first order): error / (d ln K/d ln a)."""
    return fnum(r, "error_pct") / pa.radius_sensitivity(fnum(r, "phi"))


def cost_model(rows, column):
    """column (cpu_s or wall_s) = a segments + c cells steps, fitted (least
    squares) to the measured array runs; None with fewer than two runs."""
    if len(rows) < 2:
        return None
    A = np.array([[fnum(r, "segments"), fnum(r, "cells") * (fnum(r, "steps_stage1")
                                                           + fnum(r, "steps_stage2"))]
                  for r in rows])
    y = np.array([fnum(r, column) for r in rows])
    (a, c), *_ = np.linalg.lstsq(A, y, rcond=None)
    return dict(a=float(a), c=float(c))


def stage_times(r):
    """Simulated times of the two stages of a run in units of tau_box = L^2/(4 pi^2 nu)."""
    tau = fnum(r, "L_over_D") ** 2 / (4 * math.pi ** 2)
    dt1 = min(0.01, 1.44 / fnum(r, "cpd_eff") ** 2)
    return fnum(r, "steps_stage1") * dt1 / tau, fnum(r, "steps_stage2") * fnum(r, "dt") / tau


def estimate(phi, cpd, measured):
    """(cells, steps, segments) of a run not made yet: its mesh from the mesh
    recipe; its stage lengths in tau_box from the measured run at the
    smallest fraction with the same cells per D (the convergence of a dilute
    box is set by tau_box)."""
    plan = pa.mesh_plan(phi, cpd)
    nx, ny, nz = pa.mesh_counts(plan)
    same = [r for r in measured if int(r["cpd"]) == cpd] or measured
    ref = min(same, key=lambda r: fnum(r, "phi"))
    T1, T2 = stage_times(ref)
    tau = plan["box"] ** 2 / (4 * math.pi ** 2)
    h = 1 / plan["cpd_eff"]
    dt1, dt = min(0.01, 1.44 * h * h), pa.LAMBDA * h * h
    return nx * ny * nz, T1 * tau / dt1 + T2 * tau / dt, (T1 + T2) / 0.4


def cost(model, cells, steps, segments):
    return model["a"] * segments + model["c"] * cells * steps


def main(out):
    results = os.path.join(out, "results")
    csv_path = os.path.join(results, "runs.csv")
    rows = read_csv(csv_path)
    if not rows:
        raise pa.UserError(f"no runs in {csv_path}: run `Allrun -group core` (or -quick) first")
    array = [r for r in rows if not r["name"].startswith("straddle-")]
    straddle = [r for r in rows if r["name"].startswith("straddle-")]
    phis = sorted({fnum(r, "phi") for r in array})
    cpds = sorted({int(r["cpd"]) for r in array} | set(pa.CPDS))

    metrics = {}
    for n in cpds:
        errs = [abs(fnum(r, "error_pct")) for r in array
                if int(r["cpd"]) == n and fnum(r, "phi") <= pa.PHI_TARGET + 1e-12]
        if n in pa.CPDS or errs:
            metrics[f"max_abs_error_pct_{n}"] = round(max(errs), 4) if errs else None
    for r in sorted(array, key=lambda r: (fnum(r, "phi"), int(r["cpd"]))):
        key = f"phi{pa.tag(fnum(r, 'phi'))}_{int(r['cpd'])}"
        metrics[f"error_pct_{key}"] = round(fnum(r, "error_pct"), 4)
        metrics[f"K_{key}"] = round(fnum(r, "K"), 5)
    orders = {}
    for phi in phis:
        pts = sorted((fnum(r, "cpd_eff"), fnum(r, "error_pct")) for r in array
                     if fnum(r, "phi") == phi)
        orders[phi] = observed_order(pts)
        if orders[phi] is not None:
            metrics[f"observed_order_phi{pa.tag(phi)}"] = round(orders[phi], 3)
    pairs = []
    for c in (r for r in straddle if r["position"] == "centre"):
        k = [r for r in straddle if r["position"] == "corner" and r["phi"] == c["phi"]
             and r["cpd"] == c["cpd"]]
        pairs.append((c, k[0] if k else None))
    diffs = [100 * (fnum(k, "K") / fnum(c, "K") - 1) for c, k in pairs if k is not None]
    metrics["straddle_difference_pct"] = (round(max(abs(d) for d in diffs), 5) if diffs
                                          else None)
    with open(os.path.join(results, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1)
        f.write("\n")

    # -- table.md
    md = ["# Stokes drag of a simple cubic array of spheres", "",
          "Written by `validation/periodicArray/Allrun -plot` from results/runs.csv. "
          "K = F/(6 pi mu a U), U the superficial velocity; error = K/K_ref - 1.", "",
          "## The references", "",
          "Dilute expansion (Hasimoto 1959; Sangani and Acrivos 1982) against Zick and "
          "Homsy's table (1982):", "",
          "| phi | Zick-Homsy K | expansion K | expansion / Z-H - 1 | "
          "Z-H K / (1 - phi): Z-H's K were their U the interstitial velocity |",
          "|---|---|---|---|---|"]
    for p, k in pa.ZICK_HOMSY.items():
        md.append(f"| {p:g} | {k:g} | {pa.expansion_K(p):.4f} | "
                  f"{100 * (pa.expansion_K(p) / k - 1):+.3f} % | {k / (1 - p):.3f} |")
    md += ["", "## Runs", "",
           "| run | phi | L/D | mesh | cells/D | cells | gap (cells) | K | K (grad p) | K_ref | "
           "source | error | dlnK/dln a | a_eff/a - 1 | steps | CPU s | wall s | commit |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: (r["name"].startswith("straddle-"), fnum(r, "phi"),
                                         int(r["cpd"]), r["position"])):
        md.append(f"| {r['name']} | {r['phi']} | {fnum(r, 'L_over_D'):.4f} | {r['mesh']} | "
                  f"{fnum(r, 'cpd_eff'):.2f} | {r['cells']} | {gap_cells(r):.1f} | "
                  f"{fnum(r, 'K'):.4f} | {fnum(r, 'K_gradP'):.4f} | {fnum(r, 'K_ref'):.4g} | "
                  f"{r['ref_source']} | {fnum(r, 'error_pct'):+.2f} % | "
                  f"{pa.radius_sensitivity(fnum(r, 'phi')):.2f} | {radius_error_pct(r):+.3f} % | "
                  f"{int(r['steps_stage1']) + int(r['steps_stage2'])} | {r['cpu_s']} | "
                  f"{r['wall_s']} | {r['commit']} |")
    md += ["", "## Error per fraction and resolution", "",
           "a_eff: the relative error of the sphere's radius that accounts for the error in K "
           "to first order, error / (d ln K/d ln a), d ln K/d ln a = 1 + 3 d ln K_ref/d ln phi "
           "(expansion for phi <= 0.2, Zick and Homsy interpolated above).", "",
           "| phi | K_ref | " + " | ".join(f"{n} cells/D" for n in cpds)
           + " | observed order |", "|---|---|" + "---|" * len(cpds) + "---|"]
    for phi in phis:
        cells = []
        for n in cpds:
            r = [r for r in array if fnum(r, "phi") == phi and int(r["cpd"]) == n]
            cells.append(f"{fnum(r[0], 'error_pct'):+.2f} % (K {fnum(r[0], 'K'):.4f}; "
                         f"a_eff {radius_error_pct(r[0]):+.2f} %)" if r else "-")
        md.append(f"| {phi:g} | {pa.reference_K(phi)[0]:.4g} | " + " | ".join(cells)
                  + f" | {fmt(orders[phi], '.2f')} |")
    md += ["", "Largest |error| over phi <= 0.2: " + ", ".join(
        (f"{metrics[f'max_abs_error_pct_{n}']:.2f} %" if metrics[f"max_abs_error_pct_{n}"]
         is not None else "not run") + f" at {n} cells/D" for n in pa.CPDS) + ".", "",
        "## Straddle: the sphere centred on a box corner", ""]
    if pairs:
        md += ["| phi | cells/D | K centred | K corner | corner / centred - 1 |",
               "|---|---|---|---|---|"]
        for c, k in pairs:
            md.append(f"| {c['phi']} | {fnum(c, 'cpd_eff'):.2f} | {fnum(c, 'K'):.5f} | "
                      + (f"{fnum(k, 'K'):.5f} | {100 * (fnum(k, 'K') / fnum(c, 'K') - 1):+.4f} % |"
                         if k else "not run | - |"))
    else:
        md.append("Not run.")

    # the cost of the campaign's runs not made yet
    measured = [r for r in array if r["group"] != "quick"]
    cpu_model, wall_model = cost_model(measured, "cpu_s"), cost_model(measured, "wall_s")
    names = {r["name"] for r in rows}
    todo = [(g, n, s) for g, n, s in pa.campaign()
            if not g.startswith("straddle") and n not in names]
    todo = list({n: (g, n, s) for g, n, s in todo}.values())
    md += ["", "## Runs still to do (groups c8, c12, c16) and their estimated cost", ""]
    if cpu_model is None:
        md.append("No cost model (fewer than two measured runs).")
    elif not todo:
        md.append("None.")
    else:
        md += [f"Cost models fitted to the {len(measured)} measured runs: CPU = "
               f"{cpu_model['a']:.2f} s x segments + {cpu_model['c'] * 1e6:.3f} us x cells x "
               f"steps; wall = {wall_model['a']:.2f} s x segments + "
               f"{wall_model['c'] * 1e6:.3f} us x cells x steps (the solver's start-up in "
               "every segment, on the loaded machine of the measured runs); the stage "
               "lengths in tau_box of the measured run at the smallest fraction with the "
               "same cells/D.", "",
               "| run | cells | steps | segments | CPU s | wall s |", "|---|---|---|---|---|---|"]
        total_cpu = total_wall = 0.0
        for _, name, s in sorted(todo, key=lambda t: (t[2]["cpd"], t[2]["phi"])):
            cells, steps, segments = estimate(s["phi"], s["cpd"], measured)
            c, w = cost(cpu_model, cells, steps, segments), cost(wall_model, cells, steps,
                                                                 segments)
            total_cpu += c
            total_wall += w
            md.append(f"| {name} | {cells} | {steps:.0f} | {segments:.0f} | {c:.0f} | {w:.0f} |")
        md += ["", f"Total: {total_cpu:.0f} s of CPU ({total_cpu / 3600:.1f} h), "
               f"{total_wall:.0f} s of wall time ({total_wall / 3600:.1f} h), serial."]
    with open(os.path.join(results, "table.md"), "w") as f:
        f.write("\n".join(md) + "\n")

    plot(array, phis, cpds, orders, results)
    print(f"wrote {results}/table.md, metrics.json, dragVsFraction.png, "
          "errorVsResolution.png")
    print(json.dumps({k: v for k, v in metrics.items() if k.startswith(("max_", "straddle"))}))


def plot(array, phis, cpds, orders, results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.4))
    p = np.logspace(-3, math.log10(0.4), 200)
    low = p <= pa.PHI_TARGET
    ax.plot(p[low], [pa.expansion_K(x) for x in p[low]], "k-", lw=1,
            label="dilute expansion (Sangani & Acrivos 1982)")
    ax.plot(p[~low], [pa.expansion_K(x) for x in p[~low]], "k:", lw=1)
    zh = sorted(pa.ZICK_HOMSY.items())
    ax.plot([a for a, _ in zh], [b for _, b in zh], "ko", mfc="none", ms=8,
            label="Zick & Homsy 1982")
    for n in cpds:
        rs = sorted((r for r in array if int(r["cpd"]) == n), key=lambda r: fnum(r, "phi"))
        if not rs:
            continue
        x = [fnum(r, "phi") for r in rs]
        ax.plot(x, [fnum(r, "K") for r in rs], MARKERS.get(n, "o"), color=COLOURS.get(n),
                ms=5, label=f"spheroidFoam, {n} cells/D")
        ax2.plot(x, [fnum(r, "error_pct") for r in rs], MARKERS.get(n, "o") + "-",
                 color=COLOURS.get(n), ms=5, label=f"{n} cells/D")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_yticks([1, 2, 5, 10, 20, 50])
    ax.yaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("solid fraction phi")
    ax.set_ylabel("K = F / (6 pi mu a U)")
    ax.set_title("simple cubic array of spheres, Stokes flow")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax2.axhspan(-2, 2, color="0.9", label="target +-2 % (phi <= 0.2)")
    ax2.axvline(pa.PHI_TARGET, color="0.6", lw=0.8)
    ax2.axhline(0, color="k", lw=0.6)
    ax2.set_xscale("log")
    ax2.set_xlabel("solid fraction phi")
    ax2.set_ylabel("K / K_ref - 1 (%)")
    ax2.set_title("error against Zick & Homsy (expansion at untabulated phi <= 0.2)",
                  fontsize=9)
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "dragVsFraction.png"), dpi=120)
    plt.close(fig)

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.4))
    for phi in phis:
        rs = sorted((r for r in array if fnum(r, "phi") == phi), key=lambda r: fnum(r, "cpd_eff"))
        n = [fnum(r, "cpd_eff") for r in rs]
        e = [abs(fnum(r, "error_pct")) for r in rs]
        lab = f"phi {phi:g}" + (f" (order {orders[phi]:.2f})" if orders[phi] is not None else "")
        ax.plot(n, e, "o-", ms=4, label=lab)
    ax.plot([8, 16], [2.0, 0.5], "k--", lw=0.8, label="second order")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks([6, 8, 12, 16])
    ax.set_xticklabels(["6", "8", "12", "16"])
    ax.set_xticks([], minor=True)
    ax.set_yticks([0.2, 0.5, 1, 2, 5, 10])
    ax.yaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("cells per diameter (near the sphere)")
    ax.set_ylabel("|K / K_ref - 1| (%)")
    ax.set_title("error against resolution")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    for n in cpds:
        rs = sorted((r for r in array if int(r["cpd"]) == n), key=lambda r: fnum(r, "phi"))
        if rs:
            ax2.plot([gap_cells(r) for r in rs], [radius_error_pct(r) for r in rs],
                     MARKERS.get(n, "o") + "-", color=COLOURS.get(n), ms=5,
                     label=f"{n} cells/D")
            for r in rs:
                ax2.annotate(f"{fnum(r, 'phi'):g}", (gap_cells(r), radius_error_pct(r)),
                             fontsize=6, xytext=(3, 3), textcoords="offset points")
    ax2.axhline(0, color="k", lw=0.6)
    ax2.set_xscale("log")
    ax2.set_xticks([1, 2, 5, 10, 20])
    ax2.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax2.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax2.set_xlabel("gap between neighbouring spheres L - D (cells); labels: phi")
    ax2.set_ylabel("effective radius a_eff / a - 1 (%)")
    ax2.set_title("error / (d ln K / d ln a): the radius that explains it", fontsize=9)
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "errorVsResolution.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    try:
        main(os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else HERE)
    except pa.UserError as e:
        sys.exit(f"plotPeriodicArray.py: {e}")
