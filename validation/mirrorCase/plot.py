#!/usr/bin/python3
"""Plots and tables of the analytic validation study (paper section 3).

    plot.py results.csv [outdir]

Reads the CSV of mirrorValidation and writes, in outdir (default: the CSV's
folder), the analogues of the paper's Figs. 6-18 (distance error and point
error against d*/D for one varied parameter), Tables 3-4 for Jain et al., and
summary.md (per method: statuses, worst |d - d*|/eps_d, bracket check, scale
invariance). Debian's /usr/bin/python3 with python3-matplotlib.
"""
import collections
import json
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import read_csv  # noqa: E402

AR_LABEL = {1 / 6: "1/6", 1 / 3: "1/3", 2 / 3: "2/3", 1.5: "3/2", 3.0: "3", 6.0: "6"}


def ar_name(ar):
    for k, v in AR_LABEL.items():
        if abs(ar - k) < 1e-6:
            return v
    return "%g" % ar


def load(path):
    rows = read_csv(path, missing_ok=False)
    for r in rows:
        for k in ("lambda", "ar", "dStarRel", "distErrRel", "pointErrRel", "lowerRel", "upperRel", "timeUs"):
            r[k] = float(r[k])
        r["epsRel"] = float(r["epsRel"]) if r["epsRel"] else None
        r["iterations"] = int(r["iterations"])
        r["bracketContains"] = r["bracketContains"] == "1"
    return rows


def select(rows, **kw):
    out = []
    for r in rows:
        ok = True
        for k, v in kw.items():
            x = r[k]
            if isinstance(v, float) and x is not None:
                ok &= abs(x - v) <= 1e-9 * max(abs(v), 1e-300)
            else:
                ok &= x == v
        if ok:
            out.append(r)
    return out


def figure(rows, vary, title, path, fmt=str):
    """Two panels: |d - d*|/D and |x1 - x1*|/D against d*/D, one curve per value of vary."""
    groups = collections.OrderedDict()
    for r in sorted(rows, key=lambda r: (r[vary] if r[vary] is not None else 0, r["dStarRel"])):
        groups.setdefault(r[vary], []).append(r)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    markers = "sDo^v<>p*h"
    floor = 1e-17
    for i, (value, g) in enumerate(groups.items()):
        g = sorted(g, key=lambda r: r["dStarRel"])
        conv = [r for r in g if r["status"] == "converged"]
        fail = [r for r in g if r["status"] != "converged"]
        label = fmt(value)
        m = markers[i % len(markers)]
        ax[0].loglog([r["dStarRel"] for r in conv], [max(r["distErrRel"], floor) for r in conv], m + "-",
                     label=label, mfc="none")
        ax[1].loglog([r["dStarRel"] for r in conv], [max(r["pointErrRel"], floor) for r in conv], m + "-",
                     label=label, mfc="none")
        if fail:
            ax[0].loglog([r["dStarRel"] for r in fail], [max(r["distErrRel"], floor) for r in fail], "x",
                         color="red")
    eps = {r["epsRel"] for r in rows if r["epsRel"]}
    if vary != "epsRel" and len(eps) == 1:
        ax[0].axhline(list(eps)[0], color="k", ls="--", lw=0.8, label="eps_d")
    elif vary == "epsRel":
        for e in eps:
            ax[0].axhline(e, color="k", ls=":", lw=0.6)
    ax[0].set_xlabel("d*/D_eq")
    ax[0].set_ylabel("|d - d*| / D_eq")
    ax[1].set_xlabel("d*/D_eq")
    ax[1].set_ylabel("|x1 - x1*| / D_eq")
    ax[0].legend(title=vary, fontsize=8)
    fig.suptitle(title + "   (red x: not converged)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    path = sys.argv[1]
    outdir = sys.argv[2] if len(sys.argv) > 2 else os.path.dirname(os.path.abspath(path))
    rows = load(path)
    g = lambda x: "%g" % x  # noqa: E731

    studies = [("movingBalls", "", "Moving Balls"), ("gjk", "", "GJK from eq. 3.3"),
               ("newtonCoulomb", "Cmax=0.01 tau=1 lambda=0.5", "Newton-Coulomb (Cmax 0.01, tau 1, lambda 0.5)"),
               ("dual", "", "dual Newton (ours)"), ("dual", "start=eq3.3", "dual Newton from eq. 3.3"),
               ("auto", "", "auto")]
    made = []
    for method, param, title in studies:
        base = select(rows, method=method, parameter=param)
        if not base:
            continue
        stem = method + ("Eq33" if param == "start=eq3.3" else "")
        figure(select(base, ar=3.0, epsRel=1e-5), "lambda", title + ": scale, Ar 3, eps_d 1e-5 D",
               os.path.join(outdir, stem + "_scale.png"), g)
        figure(select(base, **{"lambda": 1.0, "epsRel": 1e-6}), "ar", title + ": aspect ratio, eps_d 1e-6 D",
               os.path.join(outdir, stem + "_aspectRatio.png"), ar_name)
        figure([r for r in select(base, **{"lambda": 1.0, "ar": 3.0}) if r["epsRel"] in (1e-4, 1e-6, 1e-8)],
               "epsRel", title + ": tolerance, Ar 3", os.path.join(outdir, stem + "_tolerance.png"), g)
        made += [stem + s for s in ("_scale.png", "_aspectRatio.png", "_tolerance.png")]

    # exterior penalty: Figs. 15-18
    ep = select(rows, method="exteriorPenalty")
    if ep:
        for r in ep:
            r["epsG"] = float(r["parameter"].split()[0].split("=")[1])
            r["penalty"] = float(r["parameter"].split()[1].split("=")[1])
        figure([r for r in ep if r["ar"] == 3.0 and r["epsG"] == 1e-4 and r["penalty"] == 1e3], "lambda",
               "exterior penalty: scale, Ar 3, eps_G 1e-4 D, lambda 1e3 D^2",
               os.path.join(outdir, "exteriorPenalty_scale.png"), g)
        figure([r for r in ep if r["lambda"] == 1 and r["epsG"] == 1e-4 and r["penalty"] == 1e4], "ar",
               "exterior penalty: aspect ratio, eps_G 1e-4 D, lambda 1e4 D^2",
               os.path.join(outdir, "exteriorPenalty_aspectRatio.png"), ar_name)
        figure([r for r in ep if r["lambda"] == 1 and r["ar"] == 3.0 and r["penalty"] == 1e3], "epsG",
               "exterior penalty: eps_G, Ar 3, lambda 1e3 D^2", os.path.join(outdir, "exteriorPenalty_epsG.png"), g)
        figure([r for r in ep if r["lambda"] == 1 and r["ar"] == 3.0 and r["epsG"] == 1e-4], "penalty",
               "exterior penalty: lambda, Ar 3, eps_G 1e-4 D", os.path.join(outdir, "exteriorPenalty_penalty.png"), g)
        made += ["exteriorPenalty_" + s + ".png" for s in ("scale", "aspectRatio", "epsG", "penalty")]

    lines = ["# Analytic validation study (paper section 3): results", "",
             "Produced by `validation/mirrorCase/Allrun` (mirrorValidation, then plot.py). "
             "Errors are relative to D_eq; eps_d = epsRel x D_eq. The grid: Lambda in {1e-6, 1e-3, 1, 1e3, 1e6}, "
             "d*/D in {1, ..., 1e-6}, Ar in {1/6, 1/3, 2/3, 3/2, 3, 6}, eps_d/D in {1e-4, 1e-5, 1e-6, 1e-8}.", "",
             "## Summary per method", "",
             "| method | parameter | runs | converged | other statuses | worst \\|d-d*\\|/eps_d (converged) "
             "| bracket misses d* | scale spread (max over configs of \\|err(Lambda)-err(1)\\|/eps_d) |",
             "|---|---|---|---|---|---|---|---|"]
    metrics = {"bracket_misses_all_methods": sum(not r["bracketContains"] for r in rows)}
    keys = []
    for r in rows:
        k = (r["method"], r["parameter"])
        if k not in keys:
            keys.append(k)
    for k in keys:
        rs = select(rows, method=k[0], parameter=k[1])
        st = collections.Counter(r["status"] for r in rs)
        conv = [r for r in rs if r["status"] == "converged" and r["epsRel"]]
        worst = max((r["distErrRel"] / r["epsRel"] for r in conv), default=float("nan"))
        misses = sum(not r["bracketContains"] for r in rs)
        byconf = collections.defaultdict(dict)
        for r in rs:
            if r["status"] == "converged" and r["epsRel"]:
                byconf[(r["ar"], r["dStarRel"], r["epsRel"])][r["lambda"]] = r["distErrRel"]
        spread = 0.0
        for conf, errs in byconf.items():
            if 1.0 in errs:
                spread = max(spread, max(abs(e - errs[1.0]) for e in errs.values()) / conf[2])
        if k[1] in ("", "start=eq3.3"):
            tag = k[0] + ("Eq33" if k[1] else "")
            metrics[tag + "_runs"] = len(rs)
            metrics[tag + "_converged"] = st["converged"]
            metrics[tag + "_bracket_misses"] = misses
            if conv:
                metrics[tag + "_worst_error_over_eps"] = float("%.4g" % worst)
                metrics[tag + "_scale_spread_over_eps"] = float("%.3g" % spread)
        other = ", ".join("%s %d" % (s, n) for s, n in sorted(st.items()) if s != "converged") or "-"
        worst_s = "%.3g" % worst if conv else "n/a (ignores eps_d)"
        spread_s = "%.2g" % spread if conv else "-"
        lines.append("| %s | %s | %d | %d | %s | %s | %d | %s |" % (k[0], k[1] or "-", len(rs), st["converged"], other,
                                                                   worst_s, misses, spread_s))

    # Jain et al.: Tables 3-4 (smallest d*/D down to which every larger d* converged)
    jain = select(rows, method="jain")
    if jain:
        def min_conv(rs):
            ok = None
            for r in sorted(rs, key=lambda r: -r["dStarRel"]):
                if r["status"] != "converged":
                    break
                ok = r["dStarRel"]
            return "none" if ok is None else "%g" % ok
        factors = sorted({r["parameter"] for r in jain}, key=lambda p: -float(p.split("=")[1]))
        lines += ["", "## Jain et al.: smallest d*/D_eq down to which every larger d* converged (Table 3 analogue, "
                  "eps_d 1e-6 D, Lambda 1)", "",
                  "| Ar \\ C/C_Jain | " + " | ".join(p.split("=")[1] for p in factors) + " |",
                  "|---" * (len(factors) + 1) + "|"]
        for ar in sorted({r["ar"] for r in jain}):
            cells = [min_conv(select(jain, parameter=p, ar=ar, epsRel=1e-6, **{"lambda": 1.0})) for p in factors]
            lines.append("| %s | %s |" % (ar_name(ar), " | ".join(cells)))
        lines += ["", "## Jain et al.: the same against eps_d (Table 4 analogue, Ar 3, Lambda 1)", "",
                  "| eps_d/D \\ C/C_Jain | " + " | ".join(p.split("=")[1] for p in factors) + " |",
                  "|---" * (len(factors) + 1) + "|"]
        for e in (1e-4, 1e-6, 1e-8):
            cells = [min_conv(select(jain, parameter=p, ar=3.0, epsRel=e, **{"lambda": 1.0})) for p in factors]
            lines.append("| %g | %s |" % (e, " | ".join(cells)))
    lines += ["", "## Figures", ""] + ["![%s](%s)" % (m, m) for m in made]
    with open(os.path.join(outdir, "summary.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    # the headline figures, one flat JSON object (the methods run without a parameter, and the
    # dual method from eq. 3.3)
    os.makedirs(os.path.join(outdir, "results"), exist_ok=True)
    with open(os.path.join(outdir, "results", "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("\n".join(lines[:40]))


if __name__ == "__main__":
    main()
