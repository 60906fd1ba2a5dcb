#!/usr/bin/python3
"""Force ripple of a sphere moved at constant velocity through the cells
(validation/forceRipple, see README.md).

    forceRipple.py run [--force] [--only NAME ...]
    forceRipple.py runRe [--force] [--only NAME ...]
    forceRipple.py split
    forceRipple.py plot

A sphere (D = 1, nu = 1, rho_f = 1) in a triply periodic box L = 4 D moves
with the prescribed velocity U_b = (0.04, 0, 0) along x; the fluid's mean
velocity is held at (0.02, 0, 0) by meanVelocityForce, so the body moves at
0.02 relative to the mean flow: in its own frame the flow is a steady Stokes
flow at Re 0.02, and every change of the drag as it crosses the cells is the
grid's. The body starts at (0, 0.31 h, 0.17 h) (off the mesh lines), the
run is fixed in simulated time: 3 tau_box (tau_box = L^2/(4 pi^2 nu)) to set
the flow up, then the body crosses two cells; the ripple is the standard
deviation of the drag F_x over those two cells, divided by its mean.
run: the cases of the campaign (forcing surfaceCorrected and cutCellFraction,
     8 and 16 cells/D, lambda = nu dt/h^2 = 1) in run/<name>/ (git-ignored),
     each appended to results/runs.csv and skipped next time unless --force.
runRe: the same sphere at Re 10 relative to the mean flow (nu = 0.1, U_b =
     (1.5, 0, 0), the mean velocity held at (0.5, 0, 0)), in a box of uniform
     cells (the body crosses the periodic faces), paired with its fixed twin:
     the same sphere held still in the mean flow (-1, 0, 0), the same flow in
     the body's frame. Both run to t = 10 (2.5 box viscous times) from the same
     start with the same steps, so their drags share the start-up transient;
     the difference of their means over the last 4 time units is the forcing's
     departure from Galilean invariance (a moving body's drag against a fixed
     one's), the moving drag's standard deviation over its last 4 cells (linear
     trend removed) its ripple. Pairs for the time schemes Euler and backward,
     Courant number U_b dt/h 0.25 and 0.125, 8, 12 and 16 cells/D; and at
     Re 1.5 (nu = 1/1.5, to t = 5, the means over the last 2.5), the Reynolds
     number of ten Cate's E1, with Euler at co 0.25 and 0.075 (E1's); rows in
     results/runsRe.csv.
split: the moving sphere of runRe at 8 cells/D (Euler, co 0.25) for 3 time units
     with the module's debug output, which splits the penalty force into the
     penalised cells and the surface correction's links: the ripple of each
     part, of the internal-fluid term and of their sum over the last 4 cells,
     and the numbers of terms; results/split.md.
plot: results/table.md, results/metrics.json (ripple_pct_8, ripple_pct_16:
     the default forcing's; ripple_pct_8_cutCell, ripple_pct_16_cutCell; from
     runRe: ripple_pct_<cpd>_Re<Re>_<ddt>, galilean_difference_pct_<cpd>_Re<Re>_<ddt>,
     with _co<co> for a step other than co 0.25), results/forceRipple.png and
     results/forceRippleRe10.png.
"""
import argparse
import math
import os
import subprocess
import sys
import json
from pathlib import Path

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "stokesDrag"))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import caseWriter  # noqa: E402
from runner import read_force  # noqa: E402
from validationTools import (mesh_cells, provenance, read_csv, refined_box_mesh,  # noqa: E402
                             run_logged, write_csv, cpu_seconds)

RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
BOX = 4.0
U_BODY = 0.04
U_MEAN = 0.02
LAMBDA = 1.0
CELLS_CROSSED = 2
FORCINGS = ("surfaceCorrected", "cutCellFraction")
# the finite-Re campaign (runRe)
RE_NU = 0.1
RE_U_BODY = 1.5
RE_U_MEAN = 0.5
RE_T_END = 10.0
RE_WINDOW = 4.0
RE_RIPPLE_CELLS = 4
# Reynolds number -> (nu, end time, averaging window at its end): Re 10 runs 2.5 viscous times
# of the box, Re 1.5 (that of ten Cate's E1, validation/tenCate) about 8
RE_RUNS = {10.0: (RE_NU, RE_T_END, RE_WINDOW), 1.5: (1 / 1.5, 5.0, 2.5)}
RUNS_RE_CSV = os.path.join(RESULTS, "runsRe.csv")
RE_FIELDS = ["name", "re", "cpd", "motion", "ddt", "co", "dt", "cells", "steps", "mean_Fx",
             "ripple_pct", "cpu_s", "host", "date", "commit"]
FIELDS = ["name", "forcing", "cpd", "lambda", "dt", "cells", "steps", "t_start", "t_end",
          "mean_Fx", "std_Fx", "ripple_pct", "max_minus_min_pct", "cpu_s", "host", "date",
          "commit"]


def campaign():
    return [(f"sphere-c{cpd}-{forcing}", dict(cpd=cpd, forcing=forcing))
            for forcing in FORCINGS for cpd in (8, 16)]


def run_one(name, cpd, forcing):
    case = os.path.join(HERE, "run", name)
    if os.path.exists(case):
        subprocess.run(["rm", "-rf", case], check=True)
    h = 1.0 / cpd
    dt = LAMBDA * h * h
    tau = BOX ** 2 / (4 * math.pi ** 2)
    u_rel = U_BODY - U_MEAN
    t_start = 3 * tau
    n_start = int(math.ceil(t_start / dt))
    n_cross = int(round(CELLS_CROSSED * h / U_BODY / dt))
    t_end = (n_start + n_cross) * dt
    travel = U_BODY * t_end
    caseWriter.write_case(case, 1.0, "x", BOX, cpd, dt, t_end, u=u_rel,
                          margin=0.25 + travel + 2 * h, forcing=forcing,
                          write_interval=n_start + n_cross, ubar=(U_MEAN, 0.0, 0.0),
                          body_velocity=(U_BODY, 0.0, 0.0),
                          centre=(0.0, 0.31 * h, 0.17 * h))
    with open(os.path.join(case, "log.blockMesh"), "w") as out:
        subprocess.run(["blockMesh"], cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)
    print(f"{name}: {mesh_cells(case)} cells, dt {dt:.4g}, {n_start} + {n_cross} steps",
          flush=True)
    rc = run_logged(["nice", "-n", "10", "pimpleFoam"], case, "log.solver")
    if rc != 0:
        raise RuntimeError(f"pimpleFoam failed in {case} (see log.solver)")
    times, F = read_force(case)
    window = times > n_start * dt - 0.5 * dt
    fx = F[window, 0]
    mean, std = float(np.mean(fx)), float(np.std(fx))
    np.savetxt(os.path.join(RESULTS, f"{name}.dat"),
               np.column_stack([times[window] - n_start * dt, fx / mean]),
               header="t - t_start, F_x/mean", fmt="%.8g")
    return dict(name=name, forcing=forcing, cpd=cpd, **{"lambda": LAMBDA}, dt=f"{dt:.6g}",
                cells=mesh_cells(case), steps=n_start + n_cross, t_start=f"{n_start * dt:.6g}",
                t_end=f"{t_end:.6g}", mean_Fx=f"{mean:.8g}", std_Fx=f"{std:.6g}",
                ripple_pct=f"{100 * std / abs(mean):.5f}",
                max_minus_min_pct=f"{100 * (fx.max() - fx.min()) / abs(mean):.5f}",
                cpu_s=f"{cpu_seconds(case):.0f}", **provenance())


def campaign_re():
    """(name, settings) of the finite-Re pairs: each (Re, cpd, ddt, co) moving and fixed; at
    Re 1.5 with Euler at the Courant number of ten Cate's E1 runs (U dt/h about 0.075)."""
    sets = [(10.0, 8, "Euler", 0.25), (10.0, 8, "Euler", 0.125), (10.0, 8, "backward", 0.25),
            (10.0, 8, "backward", 0.125), (10.0, 12, "Euler", 0.25), (10.0, 12, "backward", 0.25),
            (10.0, 16, "backward", 0.25), (1.5, 8, "Euler", 0.25), (1.5, 8, "Euler", 0.075),
            (1.5, 12, "Euler", 0.075)]
    return [(re_name(cpd, motion, ddt, co, re), dict(cpd=cpd, motion=motion, ddt=ddt, co=co, re=re))
            for re, cpd, ddt, co in sets for motion in ("moving", "fixed")]


def re_name(cpd, motion, ddt, co, re=10.0):
    return f"re{re:g}-c{cpd}-{motion}-{ddt}" + ("" if co == 0.25 else f"-co{co:g}")


def write_re_case(case, cpd, motion, ddt, co, t_end, debug=False, nu=RE_NU):
    """Write and mesh a run of the finite-Re campaign in case (see runRe); debug: with the
    module's debug output; nu: the viscosity (Re = (U_b - U_mean)/nu). Returns its step and
    number of steps."""
    h = 1.0 / cpd
    dt = co * h / RE_U_BODY
    steps = int(round(t_end / dt))
    # the body starts off the mesh lines; the fixed twin sits at the same point
    centre = (0.0, 0.31 * h, 0.17 * h)
    if motion == "moving":
        flow = dict(ubar=(RE_U_MEAN, 0.0, 0.0), body_velocity=(RE_U_BODY, 0.0, 0.0))
    else:
        flow = dict(ubar=(RE_U_MEAN - RE_U_BODY, 0.0, 0.0))
    caseWriter.write_case(case, 1.0, "x", BOX, cpd, dt, steps * dt, nu=nu, ddt=ddt,
                          write_interval=steps, centre=centre, **flow)
    # uniform cells over the whole box: the moving body crosses the periodic faces
    half = 0.5 * BOX
    refined_box_mesh(case, ["--box", *map(str, (-half, half) * 3),
                            "--fine", *map(str, (-half, half) * 3), "--h", f"{h:.12g}",
                            "--periodic", "x", "--periodic", "y", "--periodic", "z"])
    if debug:
        with open(os.path.join(case, "system", "controlDict"), "a") as f:
            f.write("\nDebugSwitches\n{\n    immersedBodies  1;\n}\n")
    with open(os.path.join(case, "log.blockMesh"), "w") as out:
        subprocess.run(["blockMesh"], cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)
    return dt, steps


def run_one_re(name, cpd, motion, ddt, co, re=10.0):
    """One run of the finite-Re campaign; the drag history goes to results/<name>.dat."""
    nu, t_end, averaged = RE_RUNS[re]
    case = os.path.join(HERE, "run", name)
    if os.path.exists(case):
        subprocess.run(["rm", "-rf", case], check=True)
    dt, steps = write_re_case(case, cpd, motion, ddt, co, t_end, nu=nu)
    print(f"{name}: {mesh_cells(case)} cells, dt {dt:.4g}, {steps} steps", flush=True)
    rc = run_logged(["nice", "-n", "10", "pimpleFoam"], case, "log.solver")
    if rc != 0:
        raise RuntimeError(f"pimpleFoam failed in {case} (see log.solver)")
    times, F = read_force(case)
    if len(times) < steps:
        raise RuntimeError(f"{case}: {len(times)} force samples, {steps} steps expected")
    np.savetxt(os.path.join(RESULTS, f"{name}.dat"), np.column_stack([times, F[:, 0]]),
               header="t, F_x", fmt="%.10g")
    window = times > t_end - averaged
    return dict(name=name, re=f"{re:g}", cpd=cpd, motion=motion, ddt=ddt, co=f"{co:g}", dt=f"{dt:.6g}",
                cells=mesh_cells(case), steps=steps,
                mean_Fx=f"{float(np.mean(F[window, 0])):.8g}",
                ripple_pct=f"{re_ripple_pct(times, F[:, 0], cpd):.5f}",
                cpu_s=f"{cpu_seconds(case):.0f}", **provenance())


def re_ripple_pct(times, fx, cpd):
    """Standard deviation of the drag over the last RE_RIPPLE_CELLS cells the
    body crossed, its linear trend (the start-up's end) removed, over its mean."""
    span = RE_RIPPLE_CELLS / cpd / RE_U_BODY
    w = times > times[-1] - span + 1e-9
    t, f = times[w], fx[w]
    fit = np.polyval(np.polyfit(t - t.mean(), f, 1), t - t.mean())
    return 100 * float(np.std(f - fit)) / abs(float(np.mean(f)))


def run_campaign(args, runs_csv, fields, runs, run_one_case, report):
    """Run the campaign's cases not yet in runs_csv (all with --force, only those of --only),
    each recorded in runs_csv as it finishes; report(row) is the line printed for it."""
    os.makedirs(RESULTS, exist_ok=True)
    done = {r["name"] for r in read_csv(runs_csv)} if not args.force else set()
    for name, kw in runs:
        if (args.only and name not in args.only) or name in done:
            continue
        row = run_one_case(name, **kw)
        print("  -> " + report(row), flush=True)
        write_csv(runs_csv, [r for r in read_csv(runs_csv) if r["name"] != name] + [row], fields)


def do_run_re(args):
    run_campaign(args, RUNS_RE_CSV, RE_FIELDS, campaign_re(), run_one_re,
                 lambda row: f"mean F_x {row['mean_Fx']}, ripple {row['ripple_pct']} %")


def do_split():
    """The parts of the moving sphere's drag (see the module docstring)."""
    import re
    cpd, co, t_end = 8, 0.25, 3.0
    case = os.path.join(HERE, "run", "re10-split")
    subprocess.run(["rm", "-rf", case], check=True)
    dt, steps = write_re_case(case, cpd, "moving", "Euler", co, t_end, debug=True)
    h = 1.0 / cpd
    if run_logged(["pimpleFoam"], case, "log.solver") != 0:
        raise RuntimeError(f"pimpleFoam failed in {case} (see log.solver)")
    vec = r"\(([^)]*)\)"
    pat = re.compile(r"penalty force " + vec + r" \(links " + vec + r" from (\d+) terms of "
                     r"(\d+)\), internal-fluid momentum " + vec + r", hydrodynamic force " + vec)
    rows = []
    with open(os.path.join(case, "log.solver")) as f:
        for line in f:
            m = pat.search(line)
            if m:
                rows.append([float(m.group(1).split()[0]), float(m.group(2).split()[0]),
                             int(m.group(3)), int(m.group(4)), float(m.group(5).split()[0]),
                             float(m.group(6).split()[0])])
    d = np.array(rows)
    if len(d) < steps:
        raise RuntimeError(f"{case}: {len(d)} debug lines, {steps} steps expected")
    n = int(round(RE_RIPPLE_CELLS * h / (RE_U_BODY * dt)))
    last = d[-n:]
    drag = abs(float(np.mean(last[:, 5])))

    def ripple(x):
        k = np.arange(len(x))
        return 100 * float(np.std(x - np.polyval(np.polyfit(k, x, 1), k))) / drag

    internal = np.diff(d[-n - 1:, 4]) / dt
    parts = [("penalised cells", last[:, 0] - last[:, 1]), ("links", last[:, 1]),
             ("penalty force (both)", last[:, 0]), ("internal-fluid term", internal),
             ("hydrodynamic force", last[:, 5])]
    md = ["# The parts of a moving sphere's drag", "",
          "Produced by `/usr/bin/python3 validation/forceRipple/forceRipple.py split`: the moving "
          f"sphere of the Re 10 campaign, {cpd} cells/D, Euler, co {co:g}, to t = {t_end:g} with "
          "`DebugSwitches { immersedBodies 1; }`; the last "
          f"{RE_RIPPLE_CELLS} cells ({n} steps), linear trend removed, in % of the mean drag "
          f"{drag:.4f}.", "", "| part | mean F_x | ripple [%] |", "|---|---|---|"]
    for name, x in parts:
        md.append(f"| {name} | {np.mean(x):.4f} | {ripple(x):.3f} |")
    md += ["", f"Terms per step: {int(last[:, 3].min())}-{int(last[:, 3].max())}, of which links "
           f"{int(last[:, 2].min())}-{int(last[:, 2].max())} and penalised cells "
           f"{int((last[:, 3] - last[:, 2]).min())}-{int((last[:, 3] - last[:, 2]).max())}."]
    with open(os.path.join(RESULTS, "split.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


def do_run(args):
    run_campaign(args, RUNS_CSV, FIELDS, campaign(), run_one,
                 lambda row: f"ripple {row['ripple_pct']} % (max - min {row['max_minus_min_pct']} %)")


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_csv(RUNS_CSV, missing_ok=False)
    md = ["# Force ripple of a sphere moved through the cells", "",
          "Produced by `validation/forceRipple/Allrun -plot` from results/runs.csv. Sphere, "
          f"L/D = {BOX:g}, lambda = {LAMBDA:g}, body crossing {CELLS_CROSSED} cells along x at "
          f"{U_BODY:g} (relative to the mean flow {U_BODY - U_MEAN:g}, Re "
          f"{U_BODY - U_MEAN:g}); ripple = std(F_x)/mean(F_x) over the crossing.", "",
          "| forcing | cells/D | cells | steps | mean F_x | ripple, second cell [%] | "
          "(max - min)/mean, second cell [%] | ripple, both cells [%] | CPU [s] |",
          "|---|---|---|---|---|---|---|---|---|"]
    metrics = {}
    for r in sorted(rows, key=lambda r: (r["forcing"] != "surfaceCorrected", int(r["cpd"]))):
        d = np.loadtxt(os.path.join(RESULTS, f"{r['name']}.dat"))
        h = 1.0 / int(r["cpd"])
        second = d[d[:, 0] * U_BODY >= h * (CELLS_CROSSED - 1) - 1e-12, 1]
        ripple = 100 * np.std(second) / abs(np.mean(second))
        spread = 100 * (second.max() - second.min()) / abs(np.mean(second))
        md.append(f"| {r['forcing']} | {r['cpd']} | {r['cells']} | {r['steps']} | "
                  f"{float(r['mean_Fx']):.5g} | {ripple:.4f} | {spread:.4f} | "
                  f"{float(r['ripple_pct']):.3f} | {r['cpu_s']} |")
        suffix = "" if r["forcing"] == "surfaceCorrected" else "_cutCell"
        metrics[f"ripple_pct_{r['cpd']}{suffix}"] = round(float(ripple), 5)
    md += plot_re(plt, metrics)
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("\n".join(md))
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for r in rows:
        path = os.path.join(RESULTS, f"{r['name']}.dat")
        if not os.path.exists(path):
            continue
        d = np.loadtxt(path)
        h = 1.0 / int(r["cpd"])
        ax.plot(d[:, 0] * U_BODY / h, (d[:, 1] - 1) * 100,
                "-" if r["forcing"] == "surfaceCorrected" else "--",
                label=f"{r['forcing']}, {r['cpd']} cells/D")
    finish_figure(fig, ax, "distance travelled [cells]",
                  "Drag of a sphere moving through the cells (Stokes flow)", "forceRipple.png", 8)


def finish_figure(fig, ax, xlabel, title, name, legend_size):
    """Labels, grid and legend of a drag figure, saved as results/name."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel("F_x / mean - 1  [%]")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, name), dpi=120)


def plot_re(plt, metrics):
    """The finite-Re campaign: its tables (markdown lines), metrics and the Re 10 figure."""
    rows = {r["name"]: r for r in read_csv(RUNS_RE_CSV)}
    if not rows:
        return []
    md = []
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for re in sorted(RE_RUNS, reverse=True):
        nu, t_end, averaged = RE_RUNS[re]
        md += ["", f"## Re {re:g}: a moving sphere against its fixed twin", "",
               "Produced by `validation/forceRipple/Allrun -plot` from results/runsRe.csv "
               f"(`forceRipple.py runRe`). Sphere, L/D = {BOX:g}, uniform cells, nu = {nu:.6g}, "
               f"body velocity {RE_U_BODY:g} through the mean flow {RE_U_MEAN:g} (Re "
               f"{(RE_U_BODY - RE_U_MEAN) / nu:g}), its fixed twin in the mean flow "
               f"{RE_U_MEAN - RE_U_BODY:g}; Courant number co = U_b dt/h. Mean drags over t = "
               f"{t_end - averaged:g}-{t_end:g}; difference = moving/fixed - 1; ripple = "
               f"std/mean of the moving drag over its last {RE_RIPPLE_CELLS} cells (trend "
               "removed).",
               "", "| cells/D | time scheme | co | cells | steps | F_x fixed | F_x moving | "
               "difference [%] | ripple [%] | CPU moving + fixed [s] |",
               "|---|---|---|---|---|---|---|---|---|---|"]
        for name, kw in campaign_re():
            if kw["motion"] != "moving" or kw["re"] != re:
                continue
            fixed = rows.get(re_name(kw["cpd"], "fixed", kw["ddt"], kw["co"], re))
            moving = rows.get(name)
            if fixed is None or moving is None:
                continue
            diff = 100 * (float(moving["mean_Fx"]) / float(fixed["mean_Fx"]) - 1)
            ripple = float(moving["ripple_pct"])
            md.append(f"| {kw['cpd']} | {kw['ddt']} | {kw['co']:g} | {moving['cells']} | "
                      f"{moving['steps']} | {float(fixed['mean_Fx']):.5f} | "
                      f"{float(moving['mean_Fx']):.5f} | {diff:+.3f} | {ripple:.3f} | "
                      f"{moving['cpu_s']} + {fixed['cpu_s']} |")
            suffix = (f"{kw['cpd']}_Re{re:g}_{kw['ddt']}"
                      + ("" if kw["co"] == 0.25 else f"_co{kw['co']:g}"))
            metrics[f"galilean_difference_pct_{suffix}"] = round(diff, 4)
            metrics[f"ripple_pct_{suffix}"] = round(ripple, 4)
            if re != 10.0:
                continue
            d = np.loadtxt(os.path.join(RESULTS, f"{name}.dat"))
            h = 1.0 / kw["cpd"]
            last = d[:, 0] > d[-1, 0] - 2 * h / RE_U_BODY + 1e-9
            t = d[last, 0]
            ax.plot((t - t[0]) * RE_U_BODY / h, (d[last, 1] / np.mean(d[last, 1]) - 1) * 100,
                    ".-" if kw["ddt"] == "backward" else ".--",
                    label=f"{kw['cpd']} cells/D, {kw['ddt']}, co {kw['co']:g}")
    finish_figure(fig, ax, "distance travelled [cells] (the last two)",
                  "Drag of a sphere moving through the cells at Re 10", "forceRippleRe10.png", 7)
    return md


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    for cmd in ("run", "runRe"):
        r = sub.add_parser(cmd)
        r.add_argument("--force", action="store_true")
        r.add_argument("--only", action="append", default=[])
    sub.add_parser("split")
    sub.add_parser("plot")
    args = ap.parse_args()
    {"run": do_run, "runRe": do_run_re, "split": lambda _: do_split(),
     "plot": lambda _: do_plot()}[args.cmd](args)


if __name__ == "__main__":
    main()
