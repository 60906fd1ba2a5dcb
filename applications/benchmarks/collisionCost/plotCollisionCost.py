#!/usr/bin/python3
"""Figures and tables of docs/collisionCost.md from the CSV of `collisionCost --table`.

    /usr/bin/python3 applications/benchmarks/collisionCost/plotCollisionCost.py CSV OUTDIR

Writes OUTDIR/timePerCall.png (time per call: cold, warm, naive peer, pair search alone),
OUTDIR/breakdown.png (where the time of a call goes) and OUTDIR/tables.md (the tables of
docs/collisionCost.md). Needs numpy and matplotlib (Debian's python3-numpy, python3-matplotlib).
"""
import csv
import os
import sys

MODES = ["contact", "lubricationContact"]
NEED = ("machine nproc date compiler quick bodies volumeFraction boxLength aspectRatio mode viscosity "
        "rounds coldUs coldWallUs warmWallUs naiveWallUs clearHistoryUs loadAverage coldQ1Us coldQ3Us warmUs warmQ1Us warmQ3Us naiveUs naiveQ1Us naiveQ3Us "
        "setupUs searchUs prefilterUs distancesColdUs distancesWarmUs restColdUs restWarmUs "
        "naiveSpheresUs naiveDistancesUs naiveOverCold naiveOverWarm coldOverWarm "
        "naiveOverPipelineCold naiveOverPipelineWarm coldUsPerQuery warmUsPerQuery naiveUsPerQuery "
        "candidatePairs prefilterRejected boxRejected distanceQueries coldMeanIterations warmMeanIterations "
        "coldNotConverged warmNotConverged contacts lubricated naiveQueries naiveMeanIterations "
        "naiveNotConverged").split()


def fail(message):
    sys.stderr.write("plotCollisionCost.py: " + message + "\n")
    sys.exit(2)


def read(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail("cannot read %s: %s" % (path, e.strerror))
    if not rows or any(k not in rows[0] for k in NEED):
        missing = [k for k in NEED if not rows or k not in rows[0]]
        fail("%s is not a CSV written by this version of collisionCost --table (missing columns: %s)"
             % (path, ", ".join(missing)))
    for r in rows:
        for k, v in r.items():
            if k in ("machine", "date", "compiler", "aspectRatio", "mode"):
                continue
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                fail("%s: column %s has the non-number '%s'" % (path, k, v))
        p, _, q = r["aspectRatio"].partition("/")
        try:
            r["ar"] = float(p) / float(q) if q else float(p)
        except ValueError:
            fail("%s: bad aspect ratio '%s'" % (path, r["aspectRatio"]))
    return rows


def byMode(rows, mode):
    return sorted((r for r in rows if r["mode"] == mode), key=lambda r: r["ar"])


def ms(x):
    return "%.2f" % (x / 1000)


def tables(rows):
    r0 = rows[0]
    out = ["<!-- written by plotCollisionCost.py from the CSV; do not edit -->", "",
           "Machine: %s, %d CPUs (nproc), %s; run %s; 1-minute load average %.1f to %.1f "
           "during the run (other jobs); %d bodies, phi %.2f, box %.4f D_eq, "
           "%d timed rounds per row; times are the medians of the thread's CPU time per call%s."
           % (r0["machine"], r0["nproc"], r0["compiler"], r0["date"],
              min(r["loadAverage"] for r in rows), max(r["loadAverage"] for r in rows),
              r0["bodies"], r0["volumeFraction"], r0["boxLength"], r0["rounds"],
              ", QUICK MODE (not for the docs)" if r0["quick"] else ""), ""]
    for mode in MODES:
        rs = byMode(rows, mode)
        if not rs:
            continue
        out += ["### %s%s" % (mode, " (viscosity %g)" % rs[0]["viscosity"] if rs[0]["viscosity"] else ""), "",
                "Time per call (ms, median [Q1, Q3]) and the ratio naive/ours (whole call; and "
                "against our pipeline up to the distances, without the forces the peer does not compute):", "",
                "| Ar | cold | warm | naive peer | naive/cold | naive/warm | cold/warm | naive/pipeline cold | naive/pipeline warm |",
                "|---|---|---|---|---|---|---|---|---|"]
        for r in rs:
            out.append("| %s | %s [%s, %s] | %s [%s, %s] | %s [%s, %s] | %.2f | %.2f | %.2f | %.2f | %.2f |" % (
                r["aspectRatio"], ms(r["coldUs"]), ms(r["coldQ1Us"]), ms(r["coldQ3Us"]),
                ms(r["warmUs"]), ms(r["warmQ1Us"]), ms(r["warmQ3Us"]),
                ms(r["naiveUs"]), ms(r["naiveQ1Us"]), ms(r["naiveQ3Us"]),
                r["naiveOverCold"], r["naiveOverWarm"], r["coldOverWarm"],
                r["naiveOverPipelineCold"], r["naiveOverPipelineWarm"]))
        out += ["", "Breakdown (ms, medians of the stages timed on their own; rest = call - stages):", "",
                "| Ar | setup | pair search | prefilter | distances cold | distances warm | rest cold | rest warm | clearHistory (before cold, not in it) | peer: all-pairs spheres | peer: distances | wall: cold / warm / peer |",
                "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in rs:
            out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s / %s / %s |" % (
                r["aspectRatio"], ms(r["setupUs"]), ms(r["searchUs"]), ms(r["prefilterUs"]),
                ms(r["distancesColdUs"]), ms(r["distancesWarmUs"]), ms(r["restColdUs"]),
                ms(r["restWarmUs"]), ms(r["clearHistoryUs"]), ms(r["naiveSpheresUs"]),
                ms(r["naiveDistancesUs"]), ms(r["coldWallUs"]), ms(r["warmWallUs"]),
                ms(r["naiveWallUs"])))
        out += ["", "Statistics per call (means over the rounds) and time per distance query (us, median):", "",
                "| Ar | candidate pairs | prefilter rejected | of which by the boxes | distance queries | mean it. cold | mean it. warm | not conv. cold/warm | contacts | lubricated | us/query cold | us/query warm | peer queries | peer mean it. | peer us/query | peer not conv. |",
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in rs:
            out.append("| %s | %.0f | %.0f | %.0f | %.1f | %.2f | %.2f | %d/%d | %.1f | %.1f | %.3f | %.3f | %.0f | %.2f | %.3f | %d |" % (
                r["aspectRatio"], r["candidatePairs"], r["prefilterRejected"], r["boxRejected"], r["distanceQueries"],
                r["coldMeanIterations"], r["warmMeanIterations"], r["coldNotConverged"],
                r["warmNotConverged"], r["contacts"], r["lubricated"], r["coldUsPerQuery"],
                r["warmUsPerQuery"], r["naiveQueries"], r["naiveMeanIterations"],
                r["naiveUsPerQuery"], r["naiveNotConverged"]))
        if all("paperColdUs" in r for r in rs):
            out += ["", "The same calls with `distanceMethod paper` (Moving Balls for 1/3 < Ar < 3, GJK "
                    "otherwise, certified stop; overlapping pairs asked again of the dual method), "
                    "in the same rounds (ms, median [Q1, Q3]):", "",
                    "| Ar | dual cold | paper cold | paper/dual cold | dual warm | paper warm | paper/dual warm | paper queries | paper mean it. cold / warm | paper not conv. |",
                    "|---|---|---|---|---|---|---|---|---|---|"]
            for r in rs:
                out.append("| %s | %s | %s [%s, %s] | %.2f | %s | %s [%s, %s] | %.2f | %.1f | %.2f / %.2f | %d |" % (
                    r["aspectRatio"], ms(r["coldUs"]), ms(r["paperColdUs"]), ms(r["paperColdQ1Us"]),
                    ms(r["paperColdQ3Us"]), r["paperOverDualCold"], ms(r["warmUs"]), ms(r["paperWarmUs"]),
                    ms(r["paperWarmQ1Us"]), ms(r["paperWarmQ3Us"]), r["paperOverDualWarm"], r["paperQueries"],
                    r["paperColdMeanIterations"], r["paperWarmMeanIterations"], r["paperNotConverged"]))
        if any(r.get("dampedPairs", 0) > 0 for r in rs):
            out += ["", "The implicit damping solve (dampingForces, once per sub-step after the "
                    "Heun evaluations; its Gauss-Seidel sweeps over the damped pairs):", "",
                    "| Ar | damped pairs | sweeps | time (ms, median) | share of a warm call |",
                    "|---|---|---|---|---|"]
            for r in rs:
                out.append("| %s | %.1f | %.1f | %s | %.1f %% |" % (
                    r["aspectRatio"], r["dampedPairs"], r["dampingSweeps"], ms(r["dampingUs"]),
                    100 * r["dampingUs"] / r["warmUs"] if r["warmUs"] > 0 else 0))
        if all("fullFilmWarmUs" in r for r in rs) and any(r["lubricated"] > 0 for r in rs):
            out += ["", "The film's tangential terms (the tangential law and, for pairs that are not two "
                    "spheres, the cubic coupling): the warm call with them and without them, back to "
                    "back in alternating order (ms, median; per lubricated pair: the difference over "
                    "the pairs lubricated per call):", "",
                    "| Ar | lubricated pairs | warm, with | warm, without | with/without | us per lubricated pair |",
                    "|---|---|---|---|---|---|"]
            for r in rs:
                perPair = ("%.2f" % ((r["fullFilmWarmUs"] - r["normalFilmWarmUs"]) / r["lubricated"])
                           if r["lubricated"] > 0 else "-")
                out.append("| %s | %.1f | %s | %s | %.3f | %s |" % (
                    r["aspectRatio"], r["lubricated"], ms(r["fullFilmWarmUs"]),
                    ms(r["normalFilmWarmUs"]), r["fullFilmOverNormalFilm"], perPair))
        out.append("")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
        fail("usage: plotCollisionCost.py CSV OUTDIR")
    rows = read(sys.argv[1])
    outDir = sys.argv[2]
    if not os.path.isdir(outDir):
        fail("output folder %s does not exist" % outDir)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    title = "1000 spheroids, phi 0.25, %s (%d CPUs), %s" % (
        rows[0]["machine"], rows[0]["nproc"], rows[0]["date"][:10])
    if rows[0]["quick"]:
        title += " [quick]"

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, mode in zip(axes, MODES):
        rs = byMode(rows, mode)
        if not rs:
            continue
        ar = np.array([r["ar"] for r in rs])
        for key, label, style in [("naive", "naive peer (all pairs + cold distances)", "s--"),
                                  ("cold", "forces(), cold", "o-"), ("warm", "forces(), warm", "^-")]:
            med = np.array([r[key + "Us"] for r in rs]) / 1000
            lo = med - np.array([r[key + "Q1Us"] for r in rs]) / 1000
            hi = np.array([r[key + "Q3Us"] for r in rs]) / 1000 - med
            ax.errorbar(ar, med, yerr=[lo, hi], fmt=style, capsize=3, label=label)
        ax.plot(ar, [r["searchUs"] / 1000 for r in rs], "x:", label="PairSearch alone")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xticks(ar)
        ax.set_xticklabels([r["aspectRatio"] for r in rs])
        ax.set_xlabel("aspect ratio Ar")
        ax.set_title(mode)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("CPU time per call (ms), median, bars Q1-Q3")
    axes[0].legend(fontsize=8)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(outDir, "timePerCall.png"), dpi=120)
    plt.close(fig)

    stages = [("setupUs", "setup (spheres, grown bodies)"), ("searchUs", "PairSearch"),
              ("prefilterUs", "prefilter (boxes, then Jia)"), ("distances", "distances"),
              ("rest", "rest: forces, warm-start bookkeeping")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, mode in zip(axes, MODES):
        rs = byMode(rows, mode)
        if not rs:
            continue
        x = np.arange(len(rs))
        for k, (variant, shift) in enumerate([("Cold", -0.2), ("Warm", 0.2)]):
            bottom = np.zeros(len(rs))
            for s, (key, label) in enumerate(stages):
                if key == "distances":
                    v = np.array([r["distances%sUs" % variant] for r in rs])
                elif key == "rest":
                    v = np.maximum(0, np.array([r["rest%sUs" % variant] for r in rs]))
                else:
                    v = np.array([r[key] for r in rs])
                ax.bar(x + shift, v / 1000, 0.38, bottom=bottom, color="C%d" % s,
                       label=label if k == 0 else None, hatch="//" if variant == "Warm" else None,
                       edgecolor="white")
                bottom += v / 1000
        ax.plot(x, [r["naiveUs"] / 1000 for r in rs], "ks--", label="naive peer (total)")
        ax.set_xticks(x)
        ax.set_xticklabels(["Ar %s\ncold | warm" % r["aspectRatio"] for r in rs], fontsize=8)
        ax.set_ylabel("ms per call (medians of CPU time)")
        ax.set_title(mode)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(title + "; left bar cold, right bar (hatched) warm", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(outDir, "breakdown.png"), dpi=120)
    plt.close(fig)

    with open(os.path.join(outDir, "tables.md"), "w") as f:
        f.write(tables(rows))
    print("plotCollisionCost.py: wrote %s/{timePerCall.png, breakdown.png, tables.md}" % outDir)


if __name__ == "__main__":
    main()
