#!/usr/bin/python3
"""Tables, metrics and the figure of validation/finiteReynoldsDrag from
results/runs.csv and results/<name>.dat (called by `finiteReynoldsDrag.py plot`)."""
import os

import numpy as np

import references as ref

HEADLINE_CPD = 16


def pct(value, reference):
    return 100.0 * (value / reference - 1.0)


def sphere_tables(rows, metrics):
    md = ["## Sphere", "",
          "Reference: the standard drag curve (Clift, Grace & Weber 1978); also Schiller-Naumann "
          "and Johnson & Patel (1999, body-fitted). Change: C_D(t_end) - C_D(t_end - 10 D/U), "
          "relative (how steady the answer is).", "",
          "| Re | cells/D | cells | C_D | standard curve | error | Schiller-Naumann | error | "
          "Johnson & Patel | error | change | CPU [s] |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    sphere = sorted((r for r in rows if r["shape"] == "sphere"), key=lambda r: (r["Re"], r["cpd"]))
    worst = 0.0
    for r in sphere:
        re, cd = r["Re"], r["C_D"]
        std, sn = ref.standard_drag_curve(re), ref.schiller_naumann(re)
        jp = ref.JOHNSON_PATEL.get(int(re))
        md.append(f"| {re:g} | {r['cpd']} | {r['cells']} | {cd:.4f} | {std:.4f} | "
                  f"{pct(cd, std):+.2f} % | {sn:.4f} | {pct(cd, sn):+.2f} % | "
                  + (f"{jp:.2f} | {pct(cd, jp):+.2f} %" if jp else "- | -")
                  + f" | {r['C_D_change_pct']:+.4f} % | {r['cpu_s']} |")
        if r["cpd"] == HEADLINE_CPD:
            metrics[f"sphere_error_pct_Re{re:g}_{HEADLINE_CPD}"] = round(pct(cd, std), 3)
            worst = max(worst, abs(pct(cd, std)))
    if any(r["cpd"] == HEADLINE_CPD for r in sphere):
        metrics[f"sphere_max_abs_error_pct_{HEADLINE_CPD}"] = round(worst, 3)
    # resolution series at Re 50: the observed order against the standard curve
    series = [r for r in sphere if r["Re"] == 50]
    if len(series) >= 2:
        h = np.array([1.0 / r["cpd"] for r in series])
        e = np.array([pct(r["C_D"], ref.standard_drag_curve(50)) for r in series])
        order = float(np.polyfit(np.log(h), np.log(np.abs(e)), 1)[0])
        metrics["sphere_observed_order_Re50"] = round(order, 3)
        md += ["", f"Re 50 over {', '.join(str(r['cpd']) for r in series)} cells/D: errors "
               + ", ".join(f"{x:+.2f} %" for x in e)
               + f" against the standard curve; observed order {order:.2f} (least-squares "
               "slope of log|error| against log h)."]
    return md


def spheroid_tables(rows, metrics):
    md = ["", "## Prolate spheroid AR 2.5", "",
          "Reference: Zastawny et al. (2012) for the drag and the lift (their lift correlation, "
          "references.py); for the lift also the linear-resistance "
          "estimate |C_L| = (C_D90 - C_D0) sin(phi) cos(phi) from Zastawny's C_D0 and C_D90 "
          "(exact in Stokes flow, an estimate at finite Re).", "",
          "| Re | incidence | cells/D | cells | C_D | Zastawny | error | abs(C_L) | Zastawny | "
          "error | linear-resistance estimate | ratio | change | CPU [s] |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    worst = None
    for r in sorted((r for r in rows if r["shape"] == "prolate"),
                    key=lambda r: (r["Re"], r["incidence"])):
        re, phi, cd, cl = r["Re"], r["incidence"], r["C_D"], r["C_L"]
        z = ref.zastawny_drag(re, phi)
        lift = ref.linear_resistance_lift(re, phi)
        z_lift = ref.zastawny_lift(re, phi)
        ratio = f"{cl / lift:.3f}" if lift > 1e-9 else "-"
        z_lift_error = f"{pct(cl, z_lift):+.2f} %" if z_lift > 1e-9 else "-"
        md.append(f"| {re:g} | {phi} | {r['cpd']} | {r['cells']} | {cd:.4f} | {z:.4f} | "
                  f"{pct(cd, z):+.2f} % | {cl:.4f} | {z_lift:.4f} | {z_lift_error} | "
                  f"{lift:.4f} | {ratio} | {r['C_D_change_pct']:+.4f} % | {r['cpu_s']} |")
        if r["cpd"] == HEADLINE_CPD:
            worst = max(worst or 0.0, abs(pct(cd, z)))
            metrics[f"spheroid_error_pct_Re{re:g}_i{phi}_{HEADLINE_CPD}"] = round(pct(cd, z), 3)
            if phi == 45:
                metrics[f"spheroid_lift45_Re{re:g}_{HEADLINE_CPD}"] = round(cl, 4)
                metrics[f"spheroid_lift45_ratio_to_estimate_Re{re:g}_{HEADLINE_CPD}"] = \
                    round(cl / lift, 4)
                metrics[f"spheroid_lift45_vs_zastawny_pct_Re{re:g}_{HEADLINE_CPD}"] = \
                    round(pct(cl, z_lift), 3)
    if worst is not None:
        metrics[f"spheroid_max_abs_error_pct_{HEADLINE_CPD}"] = round(worst, 3)
    # the shape of the angle dependence, from the runs alone: C_D(45) against
    # (C_D0 + C_D90)/2 (the sin^2 law of Zastawny's form, a0 = 2) and |C_L(45)| against
    # (C_D90 - C_D0)/2 (the linear-resistance lift)
    for re in sorted({r["Re"] for r in rows if r["shape"] == "prolate"}):
        by = {r["incidence"]: r for r in rows if r["shape"] == "prolate" and r["Re"] == re
              and r["cpd"] == HEADLINE_CPD}
        if all(k in by for k in (0, 45, 90)):
            c0, c45, c90 = by[0]["C_D"], by[45]["C_D"], by[90]["C_D"]
            sin2 = pct(c45, 0.5 * (c0 + c90))
            lift = pct(by[45]["C_L"], 0.5 * (c90 - c0))
            metrics[f"spheroid_sin2_law_error_pct_Re{re:g}_{HEADLINE_CPD}"] = round(sin2, 3)
            md += ["", f"Re {re:g}, the runs' own angle dependence: C_D(45) = {c45:.4f} against "
                   f"(C_D0 + C_D90)/2 = {0.5 * (c0 + c90):.4f} ({sin2:+.2f} %: the sin^2 law of "
                   f"Zastawny's form holds); |C_L(45)| = {by[45]['C_L']:.4f} against "
                   f"(C_D90 - C_D0)/2 = {0.5 * (c90 - c0):.4f} ({lift:+.2f} %)."]
    r0, r90 = ref.zastawny_stokes_check()
    k0, k90 = ref.stokes_prolate_k(2.5)
    metrics["zastawny_over_exact_stokes_0"] = round(r0, 4)
    metrics["zastawny_over_exact_stokes_90"] = round(r90, 4)
    md += ["", "The reference checked at its own lower end: at Re 0.1 the correlation gives "
           f"{100 * (r0 - 1):+.1f} % (along) and {100 * (r90 - 1):+.1f} % (across) against the "
           f"exact Stokes drag of the AR 2.5 spheroid (24/Re times K = {k0:.4f} and {k90:.4f}, "
           "Oberbeck's formulas, which validation/stokesDrag reproduces within 0.2 % at 16 "
           "cells/D for AR 2)."]
    m0, m90 = ref.zastawny_stokes_check(re_scale=1.0 / 2.5 ** (1.0 / 3.0))
    metrics["zastawny_minor_diameter_re_over_exact_stokes_0"] = round(m0, 4)
    metrics["zastawny_minor_diameter_re_over_exact_stokes_90"] = round(m90, 4)
    md += [f"Read with Re on the minor diameter 2b (0.737 Re) it gives {100 * (m0 - 1):+.1f} % "
           f"(along) and {100 * (m90 - 1):+.1f} % (across) there."]
    for incidence in (45, 90):
        md += resolution_series(rows, incidence, metrics)
    return md


def resolution_series(rows, incidence, metrics):
    """The prolate spheroid at Re 100 and incidence on three or more meshes: C_D and |C_L|
    on each and their second-order Richardson extrapolation from the two finest."""
    series = sorted((r for r in rows if r["shape"] == "prolate" and r["Re"] == 100
                     and r["incidence"] == incidence), key=lambda r: r["cpd"])
    if len(series) < 3:
        return []
    f1, f2 = series[-2], series[-1]
    q = (f2["cpd"] / f1["cpd"]) ** 2
    cd_inf = f2["C_D"] + (f2["C_D"] - f1["C_D"]) / (q - 1)
    cl_inf = f2["C_L"] + (f2["C_L"] - f1["C_L"]) / (q - 1)
    # the order observed over the three finest meshes, where their ratios allow it
    h = [1.0 / r["cpd"] for r in series[-3:]]
    d1, d2 = series[-2]["C_D"] - series[-3]["C_D"], series[-1]["C_D"] - series[-2]["C_D"]
    order = "-"
    if d1 * d2 > 0:
        from scipy.optimize import brentq
        ratio = d1 / d2

        def mismatch(p):
            return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - ratio
        try:
            p = brentq(mismatch, 0.2, 8.0)
            order = f"{p:.2f}"
            metrics[f"spheroid_Re100_i{incidence}_observed_order"] = round(p, 2)
        except ValueError:
            pass
    key = f"spheroid_Re100_i{incidence}"
    metrics[f"{key}_richardson_C_D"] = round(cd_inf, 5)
    for r in series:
        metrics[f"{key}_richardson_change_pct_{r['cpd']}"] = round(100 * (r["C_D"] / cd_inf - 1), 3)
    cds = ", ".join(f"{r['C_D']:.4f}" for r in series)
    lift = ""
    if incidence != 90:
        cls = ", ".join(f"{r['C_L']:.4f}" for r in series)
        lift = (f"; |C_L| {cls}, extrapolated {cl_inf:.4f} "
                f"({100 * (f2['C_L'] / cl_inf - 1):+.2f} % at {f2['cpd']})")
    return ["", f"Resolution, Re 100 at {incidence} degrees, "
            f"{', '.join(str(r['cpd']) for r in series)} cells/D: C_D {cds}; observed order over "
            f"the three finest {order}. Extrapolated (second order from the two finest): C_D "
            f"{cd_inf:.4f} ({100 * (f2['C_D'] / cd_inf - 1):+.2f} % at {f2['cpd']})" + lift + "."]


def tables(rows, metrics):
    return (["# Finite-Reynolds-number drag of a fixed sphere and prolate spheroid", "",
             "Produced by `validation/finiteReynoldsDrag/Allrun -plot` from results/runs.csv. "
             "C_D = F_x/(rho U^2/2 pi D_eq^2/4), C_L = |F_y|/(same); Euler steps dt = h/U to "
             "t = 40 D_eq/U; the library's defaults (forcing surfaceCorrected)."]
            + [""] + sphere_tables(rows, metrics) + spheroid_tables(rows, metrics))


def figure(rows, path, body_fitted=None):
    """body_fitted: {(ar, Re, incidence): (C_D, C_L)} of the body-fitted reference
    (bodyFitted.py)."""
    body_fitted = body_fitted or {}
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    res = np.linspace(20, 110, 200)
    a = ax[0, 0]
    a.plot(res, [ref.standard_drag_curve(x) for x in res], "k-", label="standard curve (CGW 1978)")
    a.plot(res, [ref.schiller_naumann(x) for x in res], "k:", label="Schiller-Naumann")
    a.plot(list(ref.JOHNSON_PATEL), list(ref.JOHNSON_PATEL.values()), "ks", mfc="none",
           label="Johnson & Patel 1999")
    for cpd, m in ((8, "v"), (12, "^"), (16, "o")):
        pts = [(r["Re"], r["C_D"]) for r in rows if r["shape"] == "sphere" and r["cpd"] == cpd]
        if pts:
            a.plot(*zip(*sorted(pts)), m, color="C3", label=f"spheroidFoam, {cpd} cells/D")
    pts = sorted((re, cd) for (ar, re, inc), (cd, _) in body_fitted.items()
                 if ar == 1.0 and inc == 0)
    if pts:
        a.plot(*zip(*pts), "k*", ms=9, mfc="none", label="body-fitted (bodyFitted.py)")
    a.set_xlabel("Re = U D / nu")
    a.set_ylabel("C_D")
    a.set_title("Fixed sphere")
    a.legend(fontsize=8)
    a.grid(True, alpha=0.3)

    phis = np.linspace(0, 90, 91)
    for k, re in enumerate(sorted({r["Re"] for r in rows if r["shape"] == "prolate"})):
        pts = sorted((r["incidence"], r["C_D"], r["C_L"]) for r in rows
                     if r["shape"] == "prolate" and r["Re"] == re)
        c = f"C{k}"
        ax[0, 1].plot(phis, [ref.zastawny_drag(re, p) for p in phis], "-", color=c,
                      label=f"Zastawny et al. 2012, Re {re:g}")
        ax[0, 1].plot([p[0] for p in pts], [p[1] for p in pts], "o", color=c,
                      label=f"spheroidFoam, Re {re:g}")
        bf = sorted((inc, cd, cl) for (ar, r, inc), (cd, cl) in body_fitted.items()
                    if ar == 2.5 and r == re)
        if bf:
            ax[0, 1].plot([b[0] for b in bf], [b[1] for b in bf], "*", ms=11, mfc="none",
                          color=c, label=f"body-fitted (bodyFitted.py), Re {re:g}")
            ax[1, 0].plot([b[0] for b in bf if b[0] == 45], [b[2] for b in bf if b[0] == 45],
                          "*", ms=11, mfc="none", color=c,
                          label=f"body-fitted (bodyFitted.py), Re {re:g}")
        ax[1, 0].plot(phis, [ref.linear_resistance_lift(re, p) for p in phis], "--", color=c,
                      label=f"(C_D90 - C_D0) sin cos, Re {re:g}")
        ax[1, 0].plot([p[0] for p in pts], [p[2] for p in pts], "o", color=c,
                      label=f"spheroidFoam, Re {re:g}")
    for a, yl, title in ((ax[0, 1], "C_D", "Prolate spheroid AR 2.5: drag"),
                         (ax[1, 0], "|C_L|", "Prolate spheroid AR 2.5: lift")):
        a.set_xlabel("incidence phi [deg] (stream to symmetry axis)")
        a.set_ylabel(yl + " (D_eq normalisation)")
        a.set_title(title)
        a.legend(fontsize=8)
        a.grid(True, alpha=0.3)

    a = ax[1, 1]
    results = os.path.dirname(path)
    for r in rows:
        f = os.path.join(results, f"{r['name']}.dat")
        if r["cpd"] == HEADLINE_CPD and os.path.exists(f):
            d = np.loadtxt(f)
            a.semilogy(d[1:, 0], np.abs(d[1:, 1] / d[-1, 1] - 1) + 1e-12, lw=1,
                       label=r["name"])
    a.set_xlabel("t U / D_eq")
    a.set_ylabel("|C_D(t)/C_D(t_end) - 1|")
    a.set_title("Approach to the steady drag")
    a.set_ylim(1e-7, 1)
    a.legend(fontsize=6, ncol=2)
    a.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
