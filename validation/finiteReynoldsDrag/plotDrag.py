#!/usr/bin/python3
"""Tables, metrics and the figure of validation/finiteReynoldsDrag from
results/runs.csv and results/<name>.dat (called by `finiteReynoldsDrag.py plot`)."""
import os

import numpy as np

import bodyFittedTable
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


def torque_table(rows, metrics, results, body_fitted=None):
    """The pitching torque of the prolate spheroid at 45 degrees: the immersed runs that
    recorded it (runs.csv column C_T), the body-fitted reference (bodyFittedTable.torque:
    {Re: dict(meshes, used, order, value, finest)}) and Zastawny's torque correlation."""
    body_fitted = body_fitted or {}
    runs = sorted((r for r in rows if r["shape"] == "prolate" and r["incidence"] == 45
                   and r.get("C_T") not in (None, "")), key=lambda r: (r["Re"], r["cpd"]))
    if not runs:
        return []
    md = ["", "## Pitching torque of the prolate spheroid at 45 degrees", "",
          "C_T = T_z/(rho U^2/2 pi D_eq^2/4 D_eq/2), T the hydrodynamic torque about the "
          "body's centre, the normalisation of Zastawny et al.'s torque correlation "
          "(references.zastawny_torque, c1..c10 = "
          + ", ".join(f"{c:g}" for c in ref.ZASTAWNY_TORQUE_AR25) + "); the magnitude is "
          "compared, the column \"turns the axis\" gives the sign. Immersed: bodies.h5 "
          "hydroTorque at t = 40 D_eq/U, \"change\" C_T(40) - C_T(30) relative. Body-fitted: "
          "the moment of the forces function object about CofR (0 0 0), the body's centre, "
          "twice the half space's; order and extrapolation from the three finest meshes whose "
          f"torque changed by at most {bodyFittedTable.STEADY_PCT:g} % over their last 50 "
          "iterations (\"finest\" where the order is outside 1-3).", "",
          "| Re | cells/D | immersed C_T | turns the axis | change | body-fitted C_T on the "
          "meshes (n) | order | body-fitted | Zastawny | immersed - Zastawny | "
          "immersed - body-fitted | Zastawny - body-fitted |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        re, ct = r["Re"], float(r["C_T"])
        z = ref.zastawny_torque(re, 45)
        change = "-"
        dat = os.path.join(results, f"{r['name']}.dat")
        if os.path.exists(dat):
            d = np.loadtxt(dat)
            if d.ndim == 2 and d.shape[1] >= 4:
                before = np.interp(d[-1, 0] - 10.0, d[:, 0], d[:, 3])
                change = f"{100 * (d[-1, 3] - before) / d[-1, 3]:+.4f} %"
        bf = body_fitted.get(re)
        d_z = pct(abs(ct), z)
        cells = [f"{re:g}", str(r["cpd"]), f"{abs(ct):.4f}",
                 "towards broadside" if ct > 0 else "towards the stream", change]
        if bf:
            meshes = " / ".join(f"{c:.4f} ({n})" for n, c, _ in bf["meshes"])
            left_out = [m for m in bf["meshes"] if m not in bf["used"]]
            if left_out:
                meshes += "; left out: " + ", ".join(
                    f"n {n}, changing by {abs(c):.2g} % over its last 50 iterations"
                    for n, _, c in left_out)
            d_bf, z_bf = pct(abs(ct), bf["value"]), pct(z, bf["value"])
            cells += [meshes, f"{bf['order']:.2f}",
                      f"{bf['value']:.4f}" + (" (finest)" if bf["finest"] else "")]
        else:
            cells += ["-", "-", "-"]
        cells += [f"{z:.4f}", f"{d_z:+.2f} %"]
        cells += [f"{d_bf:+.2f} %", f"{z_bf:+.2f} %"] if bf else ["-", "-"]
        md.append("| " + " | ".join(cells) + " |")
        if r["cpd"] == HEADLINE_CPD:
            key = f"Re{re:g}_{HEADLINE_CPD}"
            metrics[f"spheroid_torque45_{key}"] = round(abs(ct), 4)
            metrics[f"spheroid_torque45_towards_broadside_{key}"] = bool(ct > 0)
            metrics[f"spheroid_torque45_vs_zastawny_pct_{key}"] = round(d_z, 3)
            if bf:
                metrics[f"spheroid_torque45_vs_body_fitted_pct_{key}"] = round(d_bf, 3)
    turns = {re: all(c > 0 for _, c, _ in bf["meshes"]) for re, bf in body_fitted.items()}
    broadside = [f"{re:g}" for re, t in sorted(turns.items()) if t]
    stream = [f"{re:g}" for re, t in sorted(turns.items()) if not t]
    if broadside:
        md += ["", "The body-fitted torque turns the axis towards broadside on every mesh at Re "
               + " and ".join(broadside) + "."]
    if stream:
        md += ["", "The body-fitted torque turns the axis towards the stream on some mesh at Re "
               + " and ".join(stream) + "."]
    for re, bf in sorted(body_fitted.items()):
        key = f"prolate_Re{re:g}_i45"
        metrics[f"body_fitted_{key}_C_T_towards_broadside"] = turns[re]
        metrics[f"body_fitted_{key}_C_T"] = round(bf["value"], 5)
        metrics[f"body_fitted_{key}_C_T_order"] = round(bf["order"], 2)
        metrics[f"zastawny_torque_vs_body_fitted_pct_{key}"] = round(
            pct(ref.zastawny_torque(re, 45), bf["value"]), 3)
    return md


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
