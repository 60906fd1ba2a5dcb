#!/usr/bin/python3
"""The scaling benchmark's tables and cost model (runScaling's runs).

    scaling.py table RUNDIR OUTDIR [--skip K]
    scaling.py memory RUNDIR OUTDIR     (after table: the memory per body, OUTDIR/memory.md)

Reads every run RUNDIR/L<L>-p<P> that finished (log.done): per time step after the first K
(default 2: the set-up and the first penalty), the master rank's CPU time of the step
(OpenFOAM's ExecutionTime), the module's (the immersedBodies line: CPU update by part, and the
penalty terms), the collision sub-steps and distances (summed over the ranks, and the busiest
rank's), the bodies the busiest rank evaluated in the sub-steps, the bodies in the busiest
rank's cells, and each rank's peak resident memory
(log.rss). Writes OUTDIR/runs.csv, OUTDIR/table.md (the runs), OUTDIR/costModel.md (the
per-item costs fitted on the 1-rank runs, their check on the 2-rank runs, and the model's
prediction for 10^4 bodies on 10^8 cells and 1000 ranks), OUTDIR/metrics.json and
OUTDIR/shares.png (each rank's share of the collision and body work against 1/P).
"""
import argparse
import csv
import glob
import json
import os
import re
import sys

import numpy as np

PARTS = ("loads", "motion", "substeps", "checks", "cells", "output")
STEP = re.compile(r"^ExecutionTime = ([0-9.e+-]+) s")
COLLECTIVES = re.compile(r" \(collectives ([0-9.e+-]+)\)")
MODULE = re.compile(
    r"^immersedBodies: (\d+) bodies, (\d+) covered cells, \d+ penalty terms, CPU update ([0-9.e+-]+) s "
    r"\(loads ([0-9.e+-]+), motion ([0-9.e+-]+) of which sub-steps ([0-9.e+-]+), checks ([0-9.e+-]+), "
    r"cells ([0-9.e+-]+), output ([0-9.e+-]+)\), penalty \(last step\) ([0-9.e+-]+) s"
    r"(?:, bodies in a rank's cells \(max\) (\d+))?")
COLLISIONS = re.compile(
    r"^collisions: (\d+) sub-step\(s\)(?: \(the most of (\d+) island\(s\) of (\d+) bodies\))?, per evaluation "
    r"([0-9.e+-]+) candidate pairs, .* "
    r"([0-9.e+-]+) distances \([0-9.e+-]+ iterations each(?:; most on one rank ([0-9.e+-]+))?\)"
    r"(?:, bodies evaluated on one rank \(max\) (\d+))?")


def parse(case):
    done = open(os.path.join(case, "log.done")).read().split()
    info = dict(zip(done[3::2], done[4::2]))
    L, P = float(info["L"]), int(info["P"])
    n = int(info["n"])
    steps, cpu, last = [], [], None
    current = {}
    with open(os.path.join(case, "log.immersedSpheroidFoam")) as f:
        for line in f:
            m = COLLISIONS.match(line)
            if m:
                current["subSteps"] = int(m.group(1))
                current["islandBodies"] = int(m.group(3)) if m.group(3) else -1
                current["candidates"] = float(m.group(4))
                current["distances"] = float(m.group(5))
                current["busiestDistances"] = float(m.group(6)) if m.group(6) else float(m.group(5))
                current["evaluatedBodies"] = int(m.group(7)) if m.group(7) else -1
                continue
            c = COLLECTIVES.search(line)
            if c and line.startswith("immersedBodies:"):
                current["collectives"] = float(c.group(1))
                line = COLLECTIVES.sub("", line)
            m = MODULE.match(line)
            if m:
                current.setdefault("collectives", 0.0)
                current["bodies"] = int(m.group(1))
                current["covered"] = int(m.group(2))
                current["update"] = float(m.group(3))
                for k, name in enumerate(PARTS):
                    current[name] = float(m.group(4 + k))
                current["penalty"] = float(m.group(10))
                current["busiestBodies"] = int(m.group(11)) if m.group(11) else int(m.group(1))
                continue
            m = STEP.match(line)
            if m:
                t = float(m.group(1))
                if last is not None and "update" in current:
                    current["step"] = t - last
                    steps.append(current)
                last = t
                current = {}
    rss = [float(x) for x in re.findall(r"rss (\d+) kB", open(os.path.join(case, "log.rss")).read())]
    return {"L": L, "n": n, "P": P, "cells": n ** 3, "steps": steps, "rss": rss, "date": " ".join(done[:2]),
            "host": done[2] if len(done) > 2 else ""}


def summarise(run, skip):
    s = run["steps"][skip:]
    if not s:
        sys.exit(f"scaling.py: L {run['L']} P {run['P']}: no steps after the first {skip}")
    mean = lambda k: float(np.mean([x[k] for x in s]))
    row = {"L": run["L"], "cells": run["cells"], "P": run["P"], "bodies": s[0]["bodies"], "steps": len(s),
           "step_cpu_s": mean("step"), "module_cpu_s": mean("update") + mean("penalty"),
           "covered_cells": mean("covered"), "sub_steps": mean("subSteps"), "distances": mean("distances"),
           "island_bodies": mean("islandBodies"),
           "busiest_distances": mean("busiestDistances"), "busiest_bodies": mean("busiestBodies"),
           "rss_max_MB": max(run["rss"]) / 1024, "rss_sum_MB": sum(run["rss"]) / 1024}
    for name in PARTS + ("penalty", "collectives"):
        row[name + "_cpu_s"] = mean(name)
    row["module_share_pct"] = 100 * row["module_cpu_s"] / row["step_cpu_s"]
    # the body and collision work of a rank: the module but its output and the time in the
    # sub-steps' collectives (the exchange and the wait for the other ranks' earlier work)
    row["body_work_cpu_s"] = row["module_cpu_s"] - row["output_cpu_s"] - row["collectives_cpu_s"]
    row["substep_work_cpu_s"] = row["substeps_cpu_s"] - row["collectives_cpu_s"]
    row["distance_share"] = row["busiest_distances"] / max(row["distances"], 1e-30)
    row["body_share"] = row["busiest_bodies"] / row["bodies"]
    # the bodies whose trial states the busiest rank built in the sub-steps (all on one rank)
    evaluated = [x["evaluatedBodies"] for x in s]
    row["evaluated_share"] = 1.0 if min(evaluated) < 0 else float(np.mean(evaluated)) / row["bodies"]
    return row


def fit_costs(rows, floor_csv):
    """Per-item costs: what each part of the module costs per item, from the 1- and 2-rank runs
    (the oversubscribed runs' CPU times include waiting for the other ranks: counts only)."""
    one = [r for r in rows if r["P"] == 1]
    timed = [r for r in rows if r["P"] <= 2]
    if len(one) < 2:
        sys.exit("scaling.py: the cost model needs 1-rank runs of two sizes")
    c = {}
    # cells, loads and penalty terms: per covered cell of the rank
    c["per_covered_cell"] = np.mean([(r["cells_cpu_s"] + r["loads_cpu_s"] + r["penalty_cpu_s"]) /
                                     r["covered_cells"] for r in one])
    # the collision sub-steps: a part every rank does for every body (the islands and their
    # check, the damping solve, the states' exchange, the loops over the bodies), below what
    # these runs resolve: taken from collisionScaling (the sub-steps alone, threads as ranks),
    # the busiest rank's CPU per body and step on the most ranks it ran (an upper bound: it
    # includes that rank's own bodies); and a part per body and evaluation for the bodies a
    # rank evaluates (their trial states, its pairs' distances and laws: the busiest rank's
    # share e of the bodies, measured), fitted on the runs of the most bodies on every P (the
    # work without the collectives; on the oversubscribed ranks too, where e is smallest)
    floor = [row for row in csv.DictReader(open(floor_csv))]
    most_ranks = max(int(row["ranks"]) for row in floor)
    c["per_body_step_every_rank"] = max(float(row["cpu_per_step_s"]) / int(row["bodies"])
                                        for row in floor if int(row["ranks"]) == most_ranks)
    fitted = [r for r in rows if r["bodies"] == max(x["bodies"] for x in rows)]
    A = np.array([2 * r["sub_steps"] * r["bodies"] * r["evaluated_share"] for r in fitted])
    b = np.array([r["substep_work_cpu_s"] - c["per_body_step_every_rank"] * r["bodies"] for r in fitted])
    c["per_evaluated_body_evaluation"] = max(float(A @ b / (A @ A)), 0.0)
    # the bodies a rank evaluates: a body is evaluated on a rank if the rank owns it or one of
    # the bodies linked to it as first bodies; with m such bodies (itself included) owned at
    # random, e = 1 - (1 - 1/P)^m, m from the run on the most ranks (counts)
    most = max(rows, key=lambda r: (r["P"], r["bodies"]))
    if most["P"] > 1 and 0 < most["evaluated_share"] < 1:
        c["bodies_evaluating_a_body"] = float(np.log(1 - most["evaluated_share"]) / np.log(1 - 1 / most["P"]))
    else:
        c["bodies_evaluating_a_body"] = 1.0
    # the checks: a cell search for 7 points a body, each on the rank whose cells hold it
    c["per_body_checks"] = np.mean([r["checks_cpu_s"] / r["bodies"] for r in one])
    c["per_body_output"] = np.mean([r["output_cpu_s"] / r["bodies"] for r in one])
    c["per_body_motion_rest"] = np.mean([max(r["motion_cpu_s"] - r["substeps_cpu_s"], 0) / r["bodies"]
                                         for r in one])
    # the flow solver's CPU per cell of a rank: it grows with the mesh (the pressure solver's
    # iterations); the prediction takes the largest mesh's, the smallest's gives the other end
    per_cell = lambda rs: np.mean([(r["step_cpu_s"] - r["module_cpu_s"]) * r["P"] / r["cells"] for r in rs])
    largest = max(r["cells"] for r in timed)
    smallest = min(r["cells"] for r in timed)
    c["fluid_per_cell"] = per_cell([r for r in timed if r["cells"] == largest])
    c["fluid_per_cell_smallest_mesh"] = per_cell([r for r in timed if r["cells"] == smallest])
    c["covered_per_body"] = np.mean([r["covered_cells"] / r["bodies"] for r in one])
    c["sub_steps"] = np.mean([r["sub_steps"] for r in one])
    # memory per rank: a base and a part per cell of the rank (a part per body, every rank
    # holding every body, is below what these runs resolve)
    M = np.array([[1, r["cells"] / r["P"]] for r in rows])
    m = np.array([r["rss_max_MB"] for r in rows])
    (c["rss_base_MB"], c["rss_per_cell_MB"]), *_ = np.linalg.lstsq(M, m, rcond=None)
    return {k: float(v) for k, v in c.items()}


def model(c, bodies, cells, P, busiest_body_share=None):
    """The module's and the fluid's CPU time per step on the busiest rank, and its memory."""
    covered = c["covered_per_body"] * bodies
    share = busiest_body_share if busiest_body_share is not None else 1.0 / P
    parts = {
        "cells, loads, penalty (the rank's covered cells)": c["per_covered_cell"] * covered * share,
        "collision sub-steps: the rank's evaluated bodies and pairs": 2 * c["sub_steps"] *
        c["per_evaluated_body_evaluation"] * bodies * (1 - (1 - 1 / P) ** c["bodies_evaluating_a_body"]),
        "collision sub-steps: every body (every rank)": c["per_body_step_every_rank"] * bodies,
        "checks (shared)": c["per_body_checks"] * bodies / P,
        "body updates (every rank)": c["per_body_motion_rest"] * bodies,
        "output (master)": c["per_body_output"] * bodies,
        # not measurable on one machine: a stated network (latency 5 us a message, 10 GB/s),
        # four gathers a sub-step of 14 numbers a body through the master and back (Pstream's
        # gatherList and scatterList: 2 log2 P messages on the longest path)
        "collision collectives (assumed network)": 2 * c["sub_steps"] * 2 * (
            2 * np.log2(max(P, 2)) * 5e-6 + 2 * 14 * 8 * bodies / 10e9),
    }
    module = sum(parts.values())
    fluid = c["fluid_per_cell"] * cells / P
    memory = c["rss_base_MB"] + c["rss_per_cell_MB"] * cells / P
    return parts, module, fluid, memory


def table(args):
    runs = [parse(os.path.dirname(p)) for p in sorted(glob.glob(os.path.join(args.rundir, "L*-p*", "log.done")))]
    if not runs:
        sys.exit(f"scaling.py: no finished runs in {args.rundir}")
    rows = sorted((summarise(r, args.skip) for r in runs), key=lambda r: (r["cells"], r["P"]))
    os.makedirs(args.outdir, exist_ok=True)
    with open(os.path.join(args.outdir, "runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    host = runs[0]["host"]
    lines = [f"Runs of `runScaling` ({runs[0]['date']} UTC, {host}: 2 cores; P > 2 oversubscribed: "
             "work counts, not times). Means over the steps after the first "
             f"{args.skip}; CPU s per step of the master rank.", "",
             "| L (D) | cells | bodies | P | step CPU s | module CPU s | module % | cells+loads+penalty | "
             "sub-steps (of which collectives) | checks | output | distances/eval | busiest rank's distances | "
             "busiest rank's bodies | busiest rank's evaluated bodies | peak memory/rank MB |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['L']:g} | {r['cells']} | {r['bodies']} | {r['P']} | {r['step_cpu_s']:.3g} | "
            f"{r['module_cpu_s']:.3g} | {r['module_share_pct']:.1f} | "
            f"{r['cells_cpu_s'] + r['loads_cpu_s'] + r['penalty_cpu_s']:.3g} | {r['substeps_cpu_s']:.3g} "
            f"({r['collectives_cpu_s']:.3g}) | "
            f"{r['checks_cpu_s']:.3g} | {r['output_cpu_s']:.3g} | {r['distances']:.0f} | "
            f"{r['distance_share']:.2f} | {r['body_share']:.2f} | {r['evaluated_share']:.2f} | "
            f"{r['rss_max_MB']:.0f} |")
    open(os.path.join(args.outdir, "table.md"), "w").write("\n".join(lines) + "\n")

    c = fit_costs(rows, os.path.join(args.outdir, "collisionScaling.csv"))
    out = ["Per-item costs fitted on the 1-rank runs (CPU s on the machine of table.md):", "",
           "| item | cost |", "|---|---|"]
    for k, v in c.items():
        out.append(f"| {k} | {v:.4g} |")
    out += ["", "Check on the timed runs (the model at each run's size and ranks, the busiest rank's body "
            "share as measured; the flow solver's cost per cell of a rank as measured on that mesh):", "",
            "| L | P | module CPU s measured | model | fluid CPU s per cell of the rank |",
            "|---|---|---|---|---|"]
    for r in rows:
        if r["P"] > 2:
            continue
        _, mod, _, _ = model(c, r["bodies"], r["cells"], r["P"], r["body_share"])
        fluid = (r["step_cpu_s"] - r["module_cpu_s"]) * r["P"] / r["cells"]
        out.append(f"| {r['L']:g} | {r['P']} | {r['module_cpu_s']:.3g} | {mod:.3g} | {fluid:.3g} |")
    parts, mod, fl, mem = model(c, 1e4, 1e8, 1000)
    out += ["", "Prediction: 10^4 bodies on 10^8 cells and 1000 ranks (10^5 cells a rank; covered cells and "
            "distances per body as measured at 8 cells/D and solid fraction 0.1; bodies' cells spread "
            "evenly):", "", "| part | CPU s per step |", "|---|---|"]
    for k, v in parts.items():
        out.append(f"| {k} | {v:.3g} |")
    fl_small = c["fluid_per_cell_smallest_mesh"] * 1e8 / 1000
    out += [f"| **module** | **{mod:.3g}** |", f"| fluid (the largest mesh's cost per cell) | {fl:.3g} |",
            f"| module share of the step | {100 * mod / (mod + fl):.1f} % |",
            f"| module share with the smallest mesh's fluid cost per cell ({fl_small:.3g} s) | "
            f"{100 * mod / (mod + fl_small):.1f} % |",
            f"| memory per rank | {mem:.0f} MB |"]
    open(os.path.join(args.outdir, "costModel.md"), "w").write("\n".join(out) + "\n")

    metrics = {"predicted_module_share_pct_1e4_bodies_1000_ranks": round(100 * mod / (mod + fl), 2),
               "predicted_module_cpu_s_1e4_bodies_1e8_cells_1000_ranks": round(mod, 4),
               "predicted_memory_per_rank_MB_1e4_bodies_1e8_cells_1000_ranks": round(mem, 1)}
    # the keys: the module's share at about 1000 bodies on 2 ranks, and the body and
    # collision work per rank (the module but its output) on 2 and 8 ranks over 1 rank
    largest = max(r["bodies"] for r in rows)
    work = {r["P"]: r["body_work_cpu_s"] for r in rows if r["bodies"] == largest}
    byP = {r["P"]: r for r in rows if r["bodies"] == largest}
    if 2 in byP:
        metrics["module_share_pct_1000_bodies_2_ranks"] = round(byP[2]["module_share_pct"], 2)
    for P in (2, 8):
        if 1 in work and P in work:
            metrics[f"body_work_ratio_{P}_over_1_rank"] = round(work[P] / work[1], 3)
            metrics[f"substep_work_ratio_{P}_over_1_rank"] = round(
                byP[P]["substep_work_cpu_s"] / byP[1]["substep_work_cpu_s"], 3)
    for r in rows:
        key = f"N{r['bodies']}_P{r['P']}"
        metrics[f"busiest_evaluated_share_{key}"] = round(r["evaluated_share"], 3)
        metrics[f"module_share_pct_{key}"] = round(r["module_share_pct"], 2)
        metrics[f"busiest_distance_share_{key}"] = round(r["distance_share"], 3)
        metrics[f"busiest_body_share_{key}"] = round(r["body_share"], 3)
    with open(os.path.join(args.outdir, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for bodies in sorted({r["bodies"] for r in rows}):
        rs = [r for r in rows if r["bodies"] == bodies]
        ax.plot([r["P"] for r in rs], [r["distance_share"] for r in rs], "o-", label=f"{bodies} bodies: distances")
        ax.plot([r["P"] for r in rs], [r["body_share"] for r in rs], "s--", label=f"{bodies} bodies: bodies in cells")
        ax.plot([r["P"] for r in rs], [r["evaluated_share"] for r in rs], "^-.",
                label=f"{bodies} bodies: bodies evaluated in the sub-steps")
    P = np.array(sorted({r["P"] for r in rows}))
    ax.plot(P, 1 / P, "k:", label="1/P")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log", base=2)
    ax.set_xlabel("ranks P")
    ax.set_ylabel("busiest rank's share")
    ax.legend(fontsize=7)
    ax.set_title("scaling: each rank's share of the work")
    fig.tight_layout()
    fig.savefig(os.path.join(args.outdir, "shares.png"), dpi=120)
    print("\n".join(lines))
    print("\n".join(out))


def memory(args):
    """Bytes per body on a rank: serial runs of one mesh with two or more solid fractions; the
    peak resident memory against the bodies by least squares (the collision core's share, which
    every rank holds for every body, from collisionScaling's heap count)."""
    runs = [parse(os.path.dirname(p))
            for p in sorted(glob.glob(os.path.join(args.rundir, "**", "L*-p1", "log.done"), recursive=True))]
    runs = [r for r in runs if r["steps"]]
    if len({r["cells"] for r in runs}) != 1 or len(runs) < 2:
        sys.exit(f"scaling.py memory: {args.rundir} needs serial runs of one mesh with two or more fractions")
    N = np.array([r["steps"][0]["bodies"] for r in runs], dtype=float)
    rss = np.array([max(r["rss"]) * 1024 for r in runs])
    path = os.path.join(args.outdir, "metrics.json")
    metrics = json.load(open(path)) if os.path.exists(path) else {}
    (base, per_body), *_ = np.linalg.lstsq(np.vstack([np.ones_like(N), N]).T, rss, rcond=None)
    lines = [f"Serial runs of `runScaling -fraction` on one mesh ({runs[0]['cells']} cells, "
             f"{runs[0]['date']} UTC): peak resident memory against the bodies.", "",
             "| bodies | peak memory MB |", "|---|---|"]
    lines += [f"| {int(n)} | {m / 2**20:.1f} |" for n, m in zip(N, rss)]
    lines += ["", f"Memory per body (least squares): {per_body / 1024:.1f} kB "
              f"(the body's cells on the rank that holds them, and what every rank holds of every body)."]
    # what every rank holds of every body in the collision sub-steps: collisionScaling's heap count
    core = re.findall(r"^\| (\d+) \| (\d+) \|$", open(os.path.join(args.outdir, "collisionScaling.md")).read(), re.M)
    if core:
        n, per = max((int(a), int(b)) for a, b in core)
        lines += [f"Of it, every rank holds for every body {per} bytes of the collision sub-steps' data "
                  f"(collisionScaling, {n} bodies): 10^4 bodies add {per * 1e4 / 2**20:.0f} MB to every rank; "
                  f"the rest follows the body's cells, on the ranks that hold them "
                  f"(10^4 bodies on 1000 ranks: {per_body * 10 / 2**20:.1f} MB a rank)."]
        metrics["replicated_bytes_per_body_collision"] = per
    open(os.path.join(args.outdir, "memory.md"), "w").write("\n".join(lines) + "\n")
    metrics["memory_per_body_kB_serial"] = round(per_body / 1024, 2)
    with open(path, "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    t = sub.add_parser("table")
    t.add_argument("rundir")
    t.add_argument("outdir")
    t.add_argument("--skip", type=int, default=2)
    m = sub.add_parser("memory")
    m.add_argument("rundir")
    m.add_argument("outdir")
    args = ap.parse_args()
    table(args) if args.command == "table" else memory(args)


if __name__ == "__main__":
    main()
