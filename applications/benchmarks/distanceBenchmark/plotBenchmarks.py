#!/usr/bin/python3
"""Plots, tables and the HDF5 copy of a distanceBenchmark run.

    plotBenchmarks.py DIR

Reads DIR/{grid,boxSize,peer,warmStart,smallArray,epsTheta}.csv and DIR/machine.txt
(whatever exists), writes DIR/*.png, DIR/results.h5 (one group per CSV) and
DIR/tables.md (the tables quoted in docs/benchmarks.md). Debian's
/usr/bin/python3 with python3-matplotlib, python3-numpy, python3-h5py.
"""
import collections
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

AR_ORDER = ["1/6", "1/3", "2/3", "3/2", "3", "6"]
AR_VALUE = {"1/6": 1 / 6, "1/3": 1 / 3, "2/3": 2 / 3, "3/2": 1.5, "3": 3.0, "6": 6.0}


def load(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k in ("ar", "method", "start", "parameter", "rule"):
                continue
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def to_hdf5(d, tables):
    import h5py

    with h5py.File(os.path.join(d, "results.h5"), "w") as h:
        machine = os.path.join(d, "machine.txt")
        if os.path.exists(machine):
            h.attrs["machine"] = open(machine).read()
        for name, rows in tables.items():
            if not rows:
                continue
            g = h.create_group(name)
            for k in rows[0]:
                vals = [r[k] for r in rows]
                if all(isinstance(v, float) for v in vals):
                    g.create_dataset(k, data=np.array(vals))
                else:
                    g.create_dataset(k, data=np.array([str(v) for v in vals], dtype=h5py.string_dtype()))


def by(rows, **kw):
    return [r for r in rows if all(r.get(k) == v for k, v in kw.items())]


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return out


def main():
    d = sys.argv[1]
    grid = load(os.path.join(d, "grid.csv"))
    box = load(os.path.join(d, "boxSize.csv"))
    peer = load(os.path.join(d, "peer.csv"))
    warm = load(os.path.join(d, "warmStart.csv"))
    small = load(os.path.join(d, "smallArray.csv"))
    epsTheta = load(os.path.join(d, "epsTheta.csv"))
    to_hdf5(d, {"grid": grid, "boxSize": box, "peer": peer, "warmStart": warm, "smallArray": small,
                "epsTheta": epsTheta})
    lines = []
    machine = os.path.join(d, "machine.txt")
    if os.path.exists(machine):
        lines += ["Machine: " + open(machine).read().replace("\n", "; ").strip("; "), ""]

    if grid:
        alphas = sorted({r["alpha"] for r in grid})
        epss = sorted({r["epsRel"] for r in grid}, reverse=True)
        ars = [a for a in AR_ORDER if by(grid, ar=a)]
        amax = max(alphas)

        # Fig. 24 analogue: MB / GJK mean time ratio against Ar, one curve per eps
        fig, ax = plt.subplots(figsize=(6, 4))
        for e in epss:
            x, y = [], []
            for a in ars:
                mb = by(grid, ar=a, alpha=amax, epsRel=e, method="movingBalls")
                gj = by(grid, ar=a, alpha=amax, epsRel=e, method="gjk")
                if mb and gj:
                    x.append(AR_VALUE[a])
                    y.append(mb[0]["meanUs"] / gj[0]["meanUs"])
            ax.semilogx(x, y, "o-", label="eps_d/R_eq = %g" % e, mfc="none")
        ax.axhline(1, color="k", lw=0.8)
        ax.set_xlabel("Ar")
        ax.set_ylabel("t(Moving Balls) / t(GJK)")
        ax.set_title("Moving Balls / GJK mean time, alpha_p = %g (paper Fig. 24)" % amax, fontsize=9)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(d, "ratioMbGjkVsAr.png"), dpi=110)
        plt.close(fig)

        # Fig. 23 analogue: the ratio against alpha, per Ar at eps 1e-5
        fig, ax = plt.subplots(figsize=(6, 4))
        e5 = min(epss, key=lambda e: abs(np.log10(e) + 5))
        for a in ars:
            x, y = [], []
            for al in alphas:
                mb = by(grid, ar=a, alpha=al, epsRel=e5, method="movingBalls")
                gj = by(grid, ar=a, alpha=al, epsRel=e5, method="gjk")
                if mb and gj:
                    x.append(al)
                    y.append(mb[0]["meanUs"] / gj[0]["meanUs"])
            ax.semilogy(x, y, "o-", label="Ar " + a, mfc="none")
        ax.set_xlabel("alpha_p")
        ax.set_ylabel("t(Moving Balls) / t(GJK)")
        ax.set_title("Moving Balls / GJK mean time against alpha_p, eps_d = %g R_eq (paper Fig. 23)" % e5, fontsize=9)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(d, "ratioMbGjkVsAlpha.png"), dpi=110)
        plt.close(fig)

        # Fig. F.26 analogue: Moving Balls (paper stopping rule) max error against eps
        fig, ax = plt.subplots(figsize=(5, 4))
        x, y = [], []
        nq = 0
        for e in epss:
            rs = by(grid, method="movingBalls", epsRel=e)
            if rs:
                x.append(e)
                y.append(max(r["maxErrorRel"] for r in rs))
                nq = sum(r["queries"] for r in rs)
        ax.loglog(x, y, "o", label="max |d_MB - d_ref| / R_eq", mfc="none")
        ax.loglog(x, x, "k--", label="y = eps_d")
        ax.set_xlabel("eps_d / R_eq")
        ax.set_ylabel("max error / R_eq")
        ax.set_title("Moving Balls, paper stop, %d queries per eps (Fig. F.26)" % nq, fontsize=9)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(d, "movingBallsErrorVsEps.png"), dpi=110)
        plt.close(fig)

        # speed-accuracy frontier: median time against achieved max error, all methods (+ FCL)
        fig, axs = plt.subplots(2, 3, figsize=(13, 7), sharey=True)
        methods = sorted({r["method"] for r in grid})
        markers = dict(zip(methods, "osD^vp"))
        for ax, a in zip(axs.flat, ars):
            for m in methods:
                rs = sorted(by(grid, ar=a, alpha=amax, method=m), key=lambda r: r["epsRel"])
                ax.loglog([max(r["maxErrorRel"], 1e-17) for r in rs], [r["medianUs"] for r in rs],
                          markers[m] + "-", label=m, mfc="none")
            for r in by(peer, ar=a):
                if r["method"].startswith("fcl"):
                    ax.loglog([max(r["maxErrorRel"], 1e-17)], [r["medianUs"]], "x", ms=8,
                              label=r["method"])
            ax.set_title("Ar " + a + ", alpha_p %g" % amax, fontsize=9)
            ax.set_xlabel("max error / R_eq")
            ax.grid(True, which="major", lw=0.3)
        for ax in axs[:, 0]:
            ax.set_ylabel("median time per query (us)")
        axs.flat[0].legend(fontsize=6)
        fig.suptitle("Speed-accuracy frontier (each point: one eps_d; x: FCL)")
        fig.tight_layout()
        fig.savefig(os.path.join(d, "speedAccuracy.png"), dpi=110)
        plt.close(fig)

        # tables: per method at every eps, worst over Ar and alpha
        lines += ["## Per method and accuracy (all Ar and alpha_p)", ""]
        rows = []
        for m in methods:
            for e in epss:
                rs = by(grid, method=m, epsRel=e)
                if not rs:
                    continue
                rows.append([m, "%g" % e, "%.3f" % max(r["medianUs"] for r in rs),
                             "%.3f" % max(r["meanUs"] for r in rs),
                             "%.2f" % max(r["meanIterations"] for r in rs), "%d" % max(r["maxIterations"] for r in rs),
                             "%.2e" % max(r["maxBracketRel"] for r in rs), "%.2e" % max(r["maxErrorRel"] for r in rs),
                             "%d" % sum(r["failures"] for r in rs), "%d" % sum(r["outOfTolerance"] for r in rs),
                             "%d" % sum(r["bracketMisses"] for r in rs), "%d" % sum(r["queries"] for r in rs)])
        lines += md_table(["method", "eps_d/R_eq", "worst median (us)", "worst mean (us)", "worst mean it.",
                           "max it.", "max bracket/R_eq", "max error/R_eq", "not converged",
                           "error > eps_d", "bracket misses", "queries"], rows)

        # median time per query by Ar at eps 1e-5 and 1e-8 (the targets)
        for e in (1e-5, 1e-8):
            if e not in epss:
                continue
            lines += ["", "## Median time per query (us) at eps_d = %g R_eq, alpha_p %g" % (e, amax), ""]
            rows = []
            for m in methods:
                rows.append([m] + ["%.3f" % by(grid, method=m, ar=a, epsRel=e, alpha=amax)[0]["medianUs"]
                                   if by(grid, method=m, ar=a, epsRel=e, alpha=amax) else "" for a in ars])
            lines += md_table(["method"] + ["Ar " + a for a in ars], rows)

        # the measured auto table: fastest (median) method per (Ar, eps) with zero failures
        # and every answer within eps_d, over all alpha
        lines += ["", "## Fastest certified method per Ar and eps_d (median time, every alpha_p)", ""]
        rows = []
        candidates = [m for m in methods if m not in ("auto", "movingBalls")]
        for a in ars:
            row = ["Ar " + a]
            for e in epss:
                best, bt = None, 1e300
                for m in candidates:
                    rs = by(grid, method=m, ar=a, epsRel=e)
                    if not rs or any(r["failures"] or r["outOfTolerance"] for r in rs):
                        continue
                    t = max(r["medianUs"] for r in rs)
                    if t < bt:
                        best, bt = m, t
                row.append("%s (%.2f)" % (best, bt) if best else "-")
            rows.append(row)
        lines += md_table(["Ar \\ eps_d/R_eq"] + ["%g" % e for e in epss], rows)

    if box:
        fig, axs = plt.subplots(2, 3, figsize=(13, 7))
        for ax, a in zip(axs.flat, AR_ORDER):
            for m in ("movingBalls", "gjk", "dual"):
                for al in sorted({r["alpha"] for r in box}):
                    rs = sorted(by(box, ar=a, method=m, alpha=al), key=lambda r: r["l"])
                    if rs:
                        ax.plot([r["l"] for r in rs], [r["meanIterations"] for r in rs], "o-", mfc="none",
                                label="%s alpha %g" % (m, al))
            ax.set_title("Ar " + a, fontsize=9)
            ax.set_xlabel("l = L/D_eq")
            ax.set_ylabel("mean iterations")
            ax.set_yscale("log")
        axs.flat[0].legend(fontsize=6)
        fig.suptitle("Mean iterations per query against box size, eps_d 1e-5 R_eq (paper Figs. 21-22)")
        fig.tight_layout()
        fig.savefig(os.path.join(d, "boxSizeConvergence.png"), dpi=110)
        plt.close(fig)
        lines += ["", "## Box size: largest relative change of the mean iteration count from l to the largest l", ""]
        rows = []
        ls = sorted({r["l"] for r in box})
        for m in ("movingBalls", "gjk", "dual"):
            row = [m]
            for l in ls:
                worst = 0.0
                for a in AR_ORDER:
                    for al in sorted({r["alpha"] for r in box}):
                        ref = by(box, ar=a, method=m, alpha=al, l=max(ls))
                        cur = by(box, ar=a, method=m, alpha=al, l=l)
                        if ref and cur and ref[0]["meanIterations"] > 0:
                            worst = max(worst, abs(cur[0]["meanIterations"] / ref[0]["meanIterations"] - 1))
                row.append("%.1f %%" % (100 * worst))
            rows.append(row)
        lines += md_table(["method"] + ["l = %g" % l for l in ls], rows)

    if peer:
        lines += ["", "## FCL side by side (same queries, alpha_p 0.25)", ""]
        rows = []
        for a in AR_ORDER:
            ours = by(peer, ar=a, method="dual")
            for r in by(peer, ar=a):
                o5 = [x for x in ours if x["epsRel"] == 1e-5]
                ratio = r["medianUs"] / o5[0]["medianUs"] if o5 else float("nan")
                rows.append(["Ar " + a, r["method"], "%g" % r["epsRel"] if r["epsRel"] else "-",
                             "%.3f" % r["medianUs"], "%.3f" % r["meanUs"], "%.2e" % r["maxErrorRel"],
                             "%d" % r["missesEps5"], "%d" % r["missesEps8"], "%d" % r["notOk"],
                             "%d" % r["queries"], "%.1f" % ratio])
        lines += md_table(["Ar", "method", "eps_d/R_eq", "median (us)", "mean (us)", "max error/R_eq",
                           "error > 1e-5 R_eq", "error > 1e-8 R_eq", "no answer", "queries",
                           "median / dual's at 1e-5"], rows)

    if warm:
        lines += ["", "## Warm start (slightly moved packings, alpha_p 0.25)", ""]
        rows = []
        for r in warm:
            rows.append(["Ar " + r["ar"], r["method"], "%g" % r["epsRel"], r["start"], "%.2f" % r["meanIterations"],
                         "%.3f" % r["medianUs"], "%.3f" % r["meanUs"], "%d" % r["failures"]])
        lines += md_table(["Ar", "method", "eps_d/R_eq", "start", "mean it.", "median (us)", "mean (us)",
                           "failures"], rows)

    if small:
        lines += ["", "## Small array l = 5, Ar = 1/6, alpha_p = 0.25, eps_d = 1e-5 R_eq (paper Tables 1 and 5)", ""]
        rows = [[r["method"], r["parameter"], "%d" % r["queries"], "%d" % r["failures"],
                 "%.1f" % r["failurePercent"], "%.1f" % r["timeRatioToGjk"], "%.2e" % r["maxErrorRel"]]
                for r in small]
        lines += md_table(["method", "parameters", "queries", "not converged", "% not converged",
                           "time / GJK's (converged queries)", "max error/R_eq"], rows)

    if epsTheta:
        # Fig. F.26: Moving Balls' max error against eps_d, eq. F.6 (the paper's check) and eq. 2.9
        epss = sorted({r["epsRel"] for r in epsTheta})
        fig, ax = plt.subplots(figsize=(5, 4))
        nq = sum(r["queries"] for r in by(epsTheta, epsRel=epss[0], rule="F.6"))
        for rule, marker in (("F.6", "o"), ("2.9", "s")):
            y = [max(r["maxErrorRel"] for r in by(epsTheta, epsRel=e, rule=rule)) for e in epss]
            ax.loglog(epss, y, marker, mfc="none", label="eps_theta of eq. %s" % rule)
        ax.loglog(epss, epss, "k--", label="y = eps_d")
        ax.set_xlabel("eps_d / R_eq")
        ax.set_ylabel("max |d_MB - d_ref| / R_eq")
        ax.set_title("Moving Balls, paper stop, %d queries per eps_d (Fig. F.26)" % nq, fontsize=9)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(d, "movingBallsAdaptiveErrorVsEps.png"), dpi=110)
        plt.close(fig)
        lines += ["", "## Fig. F.26 check: Moving Balls with the paper's angle stop, l = %g, alpha_p %g, every Ar"
                  % (epsTheta[0]["l"], epsTheta[0]["alpha"]), ""]
        rows = []
        for rule in ("F.6", "2.9"):
            for e in epss:
                rs = by(epsTheta, epsRel=e, rule=rule)
                worst = max(r["maxErrorRel"] for r in rs)
                rows.append(["eq. " + rule, "%g" % e, "%.2e" % worst, "%.2f" % (worst / e),
                             "%d" % sum(r["outOfTolerance"] for r in rs), "%d" % sum(r["failures"] for r in rs),
                             "%.1f" % max(r["meanIterations"] for r in rs), "%d" % max(r["maxIterations"] for r in rs),
                             "%d" % sum(r["queries"] for r in rs)])
        lines += md_table(["eps_theta", "eps_d/R_eq", "max error/R_eq", "max error/eps_d", "error > eps_d",
                           "not converged", "worst mean it.", "max it.", "queries"], rows)

    with open(os.path.join(d, "tables.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
