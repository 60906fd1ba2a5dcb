#!/usr/bin/python3
"""The results' sensitivity to the coupling's and the contact's stabilisers, each set a factor 2
below and above its default, one at a time (validation/stabiliserSensitivity).

The stabilisers (docs/collisions.md, steps 6-7; docs/immersedBodies.md, wall cells):
- filmDampingScale (top level, default 1): the factor on the film correction's estimate of the
  resolved film's damping, D = 6 pi mu R*^2/max(h, filmGap/4);
- sustainedLoadOverlap (collision, default 0.5): the static overlap a sustained load may give a
  contact, over the overlap cap (the spring is stiffened to k >= W/(f cap)); 0.25 and 1;
- softCellSteps (top level, default 1): the soft wall and contact cells' penalty time scale
  over the fluid's own, dt/c;
- contactSteps (collision, default 10) and maxOverlap (collision, default 0.1): the stretched
  contact, whose time is contactSteps fluid steps, shortened so that the overlap stays below
  maxOverlap of the smallest semi-axis (a real contact lasts microseconds and overlaps by far
  less); 5 and 20, 0.05 and 0.2.

The cases, each the set-up of an existing test or validation, run in run/<case>-<variant>:
- restingOnWall (tests/foam/restingOnWallCase): a light spheroid of the fluidised bed (Ar 2,
  density ratio 2, oil of 0.07 Pa s) released lying flat 0.02 D above the floor at Courant 0.5:
  the largest speed, the speed over the last 0.1 s and the overlap it rests at;
- restingStack: the same with a second body released 0.02 D above the first, resting on it:
  the same for the upper body, its rest gap to the lower one;
- wetRebound St 27 and St 152 (validation/wetRebound at 8 cells/d): e/e_dry (at separation),
  e(0.1 a)/e_dry (the speeds at the same gap of 0.1 a in and out, wetRebound's
  same_gap_restitution), the overlap and the gap of the e/e_dry sample;
- wallCellPenalty (tests/foam/wallCellPenaltyCase, soft): a sphere driven 0.09 a into a wall
  and out; the largest hydrodynamic force after the start over rho_f V U 2 pi f;
- fluidisedBed (tutorials/fluidisedBed, Allrun-parallel on 2 ranks, about 20 min a run; run
  only when named with --case): the bed's voidage in its three stages of inflow and the
  largest overlap, from the tutorial's results.md.

    stabiliserSensitivity.py run [--case C ...] [--variant V ...] [--force]
    stabiliserSensitivity.py collect   re-analyse the runs in run/ into results/runs.csv
    stabiliserSensitivity.py plot      results/table.md, metrics.json, sensitivity.png

Each run appends a row to results/runs.csv (its figures, CPU time, host, commit).
"""
import argparse
import math
import os
import shutil
import sys
from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = str(Path(HERE).parents[1])
sys.path.insert(0, os.path.join(TOP, "validation", "tools"))
sys.path.insert(0, os.path.join(TOP, "validation", "wetRebound"))
from validationTools import (cpu_seconds, locked, provenance, read_csv,  # noqa: E402
                             run_logged, substitute, substitute_re, write_csv)
import wetRebound  # noqa: E402

RESULTS = os.path.join(HERE, "results")
RUNS = os.path.join(HERE, "run")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")

# name: (keyword, value, where: "top" or "collision"); "default" sets nothing
VARIANTS = {
    "default": None,
    "filmDampingScale0.5": ("filmDampingScale", 0.5, "top"),
    "filmDampingScale2": ("filmDampingScale", 2, "top"),
    "sustainedLoadOverlap0.25": ("sustainedLoadOverlap", 0.25, "collision"),
    "sustainedLoadOverlap1": ("sustainedLoadOverlap", 1, "collision"),
    "softCellSteps0.5": ("softCellSteps", 0.5, "top"),
    "softCellSteps2": ("softCellSteps", 2, "top"),
    "contactSteps5": ("contactSteps", 5, "collision"),
    "contactSteps20": ("contactSteps", 20, "collision"),
    "maxOverlap0.05": ("maxOverlap", 0.05, "collision"),
    "maxOverlap0.2": ("maxOverlap", 0.2, "collision"),
}
KNOBS = {"filmDampingScale": 1, "sustainedLoadOverlap": 0.5, "softCellSteps": 1,
         "contactSteps": 10, "maxOverlap": 0.1}
CASES = ("restingOnWall", "restingStack", "wetReboundSt27", "wetReboundSt152", "wallCellPenalty",
         "fluidisedBed")
# the cases a run without --case leaves out (their runs take half an hour each)
LONG_CASES = ("fluidisedBed",)
# per case: its figures (the first is its headline, whose change the metrics report) and units
FIGURES = {
    "restingOnWall": ("rest_overlap_b", "max_speed", "late_speed"),
    "restingStack": ("upper_rest_gap_b", "max_speed", "late_speed"),
    "wetReboundSt27": ("e_over_edry", "e_same_gap_0.1a", "max_overlap_a", "out_gap_a"),
    "wetReboundSt152": ("e_over_edry", "e_same_gap_0.1a", "max_overlap_a", "out_gap_a"),
    "wallCellPenalty": ("peak_force",),
    "fluidisedBed": ("eps_0.14", "eps_0.25", "eps_0.42", "max_overlap_amin"),
}
# figures beside the headline whose change is reported too: the rebound at separation is one
# sample in the step where the film's force changes fastest, so its change mixes the knob's
# effect with where the steps fall; the same-gap ratio is interpolated on the trajectory
CHANGED = {"wetReboundSt27": ("e_same_gap_0.1a",), "wetReboundSt152": ("e_same_gap_0.1a",)}
UNITS = {"rest_overlap_b": "overlap at rest / b", "upper_rest_gap_b": "upper body's gap at rest / b",
         "max_speed": "largest speed [m/s]", "late_speed": "speed over the last 0.1 s [m/s]",
         "e_over_edry": "e/e_dry", "e_same_gap_0.1a": "e(0.1 a)/e_dry",
         "max_overlap_a": "largest overlap / a",
         "out_gap_a": "gap of the e/e_dry sample / a",
         "peak_force": "largest F_z magnitude / (rho_f V U 2 pi f)",
         "eps_0.14": "voidage at U/u_t 0.14", "eps_0.25": "voidage at U/u_t 0.25",
         "eps_0.42": "voidage at U/u_t 0.42", "max_overlap_amin": "largest overlap / a_min"}
FIELDS = ["name", "case", "variant", "figures", "cpu_s", "host", "date", "commit"]
B = 0.0015874          # the resting bodies' smaller semi-axis (restingOnWallCase)


def set_variant(props, variant):
    """Put the variant's keyword into immersedBodiesProperties."""
    if VARIANTS[variant] is None:
        return
    key, value, where = VARIANTS[variant]
    if where == "top":
        substitute(props, "\nbodies\n", f"\n{key:<16} {value:g};\n\nbodies\n")
    else:
        substitute_re(props, r"^(    type\s+lubricationContact;.*)$",
                      lambda m: f"{m.group(1)}\n    {key:<16} {value:g};")


def prepare(case, name, variant):
    """The case folder, ready for ./Allrun; returns the properties file."""
    shutil.rmtree(case, ignore_errors=True)
    if name == "fluidisedBed":
        shutil.copytree(os.path.join(TOP, "tutorials", "fluidisedBed"), case,
                        ignore=shutil.ignore_patterns("reference"))
    elif name.startswith("wetRebound"):
        wetRebound.write_case(case, name[len("wetRebound"):], 8)
    else:
        source = "restingOnWallCase" if name.startswith("resting") else "wallCellPenaltyCase"
        shutil.copytree(os.path.join(TOP, "tests", "foam", source), case)
    props = os.path.join(case, "constant", "immersedBodiesProperties")
    if name == "restingStack":
        upper = 0.0016674 + 2 * B + 0.02 * 2 * B
        substitute(props, "\nbodies\n{\n", "\nbodies\n{\n" + f"""\
    upper                                       // released 0.02 D above the lower body
    {{
        semiAxes        (0.0031748 0.0015874 0.0015874);
        density         2000;
        centre          (0.008 0.008 {upper:.7g});
        axis            (1 0 0);
        motion          {{ type free; }}
    }}
""")
    set_variant(props, variant)
    return props


def bed_figures(case):
    """The stages' voidages and the largest overlap from the tutorial's results.md."""
    import re
    with open(os.path.join(case, "results.md")) as f:
        text = f.read()
    out = {}
    for stage, eps in re.findall(r"^\| stage U/u_t = (\S+): voidage \(mean \+- sd\), bed height "
                                 r"\| (\S+) ", text, flags=re.M):
        out[f"eps_{stage}"] = float(eps)
    overlap = re.search(r"largest overlap / a_min \| \S+, \S+; (\S+) \|", text)
    if len(out) != 3 or overlap is None:
        raise RuntimeError(f"{case}/results.md: no voidage of three stages or no overlap")
    out["max_overlap_amin"] = float(overlap.group(1))
    return out


def analyse(case, name):
    import h5py
    import numpy as np
    if name == "fluidisedBed":
        return bed_figures(case)
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if name.startswith("wetRebound"):
        r = wetRebound.analyse(h5, name[len("wetRebound"):])
        same = wetRebound.same_gap_restitution(h5, name[len("wetRebound"):], gaps=(0.1,))[0]
        return {"e_over_edry": r["e"] / wetRebound.E_DRY, "e_same_gap_0.1a": same,
                "max_overlap_a": r["max_overlap_a"], "out_gap_a": r["out_gap_a"]}
    with h5py.File(h5, "r", locking=False) as f:
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["bodyNames"][()]]
        t = f["time"][()]
        c = f["centre"][()]
        v = f["velocity"][()]
        fz = f["hydroForce"][:, 0, 2]
    for x in (c, v):
        if not np.all(np.isfinite(x)):
            raise RuntimeError(f"{case}: non-finite body state")
    if name == "wallCellPenalty":
        scale = 1000 * 4 / 3 * math.pi * 0.002 ** 3 * 0.5 * 2 * math.pi * 416.6666666666667
        return {"peak_force": float(np.abs(fz[3:]).max() / scale)}
    speed = np.linalg.norm(v, axis=2).max(axis=1)
    late = t >= t[-1] - 0.1
    out = {"max_speed": float(speed.max()), "late_speed": float(speed[late].max())}
    lower = names.index("body")
    if name == "restingOnWall":
        out["rest_overlap_b"] = float((B - c[-1, lower, 2]) / B)
    else:
        up = names.index("upper")
        out["upper_rest_gap_b"] = float((c[-1, up, 2] - c[-1, lower, 2] - 2 * B) / B)
    return out


def run(name, variant, force):
    tag = f"{name}-{variant}"
    rows = read_csv(RUNS_CSV)
    if not force and any(r["name"] == tag for r in rows):
        print(f"{tag}: in results/runs.csv, skipped")
        return
    case = os.path.join(RUNS, tag)
    prepare(case, name, variant)
    script = "./Allrun-parallel" if name == "fluidisedBed" else "./Allrun"
    if run_logged([script], case, "log.Allrun") != 0:
        sys.exit(f"stabiliserSensitivity: {tag} failed (see {case}/log.*)")
    figures = analyse(case, name)
    print(f"{tag}: " + ", ".join(f"{k} {v:.4g}" for k, v in figures.items()), flush=True)
    row = {"name": tag, "case": name, "variant": variant,
           "figures": ";".join(f"{k}={v:.6g}" for k, v in figures.items()),
           "cpu_s": f"{cpu_seconds(case, 'log.immersedSpheroidFoam'):.0f}", **provenance()}
    os.makedirs(RESULTS, exist_ok=True)
    order = {(c, v): i for i, (c, v) in enumerate((c, v) for c in CASES for v in VARIANTS)}
    with locked(RUNS_CSV):
        rows = [r for r in read_csv(RUNS_CSV) if r["name"] != tag] + [row]
        write_csv(RUNS_CSV, sorted(rows, key=lambda r: order[(r["case"], r["variant"])]),
                  FIELDS)


def collect():
    """Re-analyse the runs kept in run/ (after a change of the analysis); rows whose run folder
    is gone keep their figures."""
    # under the file's lock: a run beside this one may add its row meanwhile
    with locked(RUNS_CSV):
        rows = read_csv(RUNS_CSV, missing_ok=False)
        for row in rows:
            case = os.path.join(RUNS, row["name"])
            if os.path.exists(os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")):
                figures = analyse(case, row["case"])
                row["figures"] = ";".join(f"{k}={v:.6g}" for k, v in figures.items())
            else:
                print(f"{row['name']}: no run folder, figures kept")
        write_csv(RUNS_CSV, rows, FIELDS)


def figures_of(rows):
    """{(case, variant): {figure: value}} from results/runs.csv."""
    out = {}
    for r in rows:
        out[(r["case"], r["variant"])] = {k: float(v) for k, v in
                                         (kv.split("=") for kv in r["figures"].split(";"))}
    return out


def change_pct(value, reference):
    return 100 * (value / reference - 1) if reference != 0 else float("nan")


def plot():
    rows = read_csv(RUNS_CSV, missing_ok=False)
    data = figures_of(rows)
    metrics, lines = {}, []
    for case in CASES:
        if (case, "default") not in data:
            continue
        base = data[(case, "default")]
        changed = (FIGURES[case][0],) + CHANGED.get(case, ())
        lines += [f"**{case}**", "", "| variant | " + " | ".join(UNITS[f] for f in FIGURES[case])
                  + "".join(f" | change of {UNITS[f]}" for f in changed) + " |",
                  "|---|" + "---|" * (len(FIGURES[case]) + len(changed))]
        for variant in VARIANTS:
            if (case, variant) not in data:
                continue
            fig = data[(case, variant)]
            changes = {f: change_pct(fig[f], base[f]) for f in changed if f in fig and f in base}
            lines.append(f"| {variant} | " + " | ".join(f"{fig[f]:.4g}" if f in fig else "-"
                                                          for f in FIGURES[case])
                         + "".join(" | -" if variant == "default" or f not in changes
                                   else f" | {changes[f]:+.1f} %" for f in changed) + " |")
            for f in FIGURES[case]:
                if f in fig:
                    metrics[f"{case}_{f}_{variant}"] = float(f"{fig[f]:.6g}")
            if variant != "default":
                for f, change in changes.items():
                    key = f"{case}_{f}_max_abs_change_pct_{VARIANTS[variant][0]}"
                    metrics[key] = round(max(abs(change), metrics.get(key, 0.0)), 3)
        lines.append("")
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines))
    import json
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    figure(data)
    print("\n".join(lines))


def figure(data):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    cases = [c for c in CASES if (c, "default") in data]
    fig, axs = plt.subplots(1, len(cases), figsize=(3.2 * len(cases), 3.8), squeeze=False)
    for ax, case in zip(axs[0], cases):
        head = FIGURES[case][0]
        base = data[(case, "default")][head]
        names = [v for v in VARIANTS if v != "default" and (case, v) in data]
        changes = [change_pct(data[(case, v)][head], base) for v in names]
        ax.barh(np.arange(len(names)), changes, color=[f"C{list(KNOBS).index(VARIANTS[v][0])}"
                                                       for v in names])
        ax.set_yticks(np.arange(len(names)))
        ax.set_yticklabels(names, fontsize=7)
        ax.axvline(0, color="k", lw=0.8)
        ax.set_title(f"{case}\n{UNITS[head]}: {base:.3g}", fontsize=8)
        ax.set_xlabel("change against the default [%]", fontsize=8)
        ax.grid(True, axis="x", alpha=0.3)
    fig.suptitle("Each stabiliser a factor 2 below and above its default")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "sensitivity.png"), dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--case", action="append", choices=CASES, default=[])
    r.add_argument("--variant", action="append", choices=list(VARIANTS), default=[])
    r.add_argument("--force", action="store_true")
    sub.add_parser("plot")
    sub.add_parser("collect")
    a = ap.parse_args()
    if a.cmd == "plot":
        plot()
        return
    if a.cmd == "collect":
        collect()
        return
    for case in a.case or [c for c in CASES if c not in LONG_CASES]:
        for variant in a.variant or VARIANTS:
            if case == "wallCellPenalty" and variant != "default" and \
                    VARIANTS[variant][0] != "softCellSteps":
                continue        # a prescribed body: no film correction, no load
            run(case, variant, a.force)


if __name__ == "__main__":
    main()
