"""ten Cate et al. (2002) settling sphere: simulated gap and velocity against the digitised
experimental curves, and the u_max error of every finished run.

    /usr/bin/python3 validation/tenCate/plot.py validation/tenCate      (Allrun -plot does this)

Reads results/<CASE>-<CPD>.h5 (+ .csv: cells, ranks, wall time, steps) and the reference curves
in ../shared/validation-data/tenCate2002 (or $TENCATE_DATA). Writes results/summary.md,
results/summary.csv, tenCate_E1.png, tenCate_E4.png.
"""
import glob
import json
import os
import sys
from pathlib import Path

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import read_csv, write_csv  # noqa: E402
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "finiteReynoldsDrag"))
import references  # noqa: E402  (the drag correlations)

here = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(__file__))
data_dir = os.environ.get("TENCATE_DATA",
                          os.path.join(here, "..", "..", "..", "shared", "validation-data", "tenCate2002"))
D = 0.015
Z0 = 0.1275          # initial centre height: bottom 120 mm above the floor
REFERENCE = {        # u_max (m/s), physics-references.md section 1; data files
    "E1": (0.035986, "Re1_5"),
    "E4": (0.12224, "Re32_2"),
}
FLUID_DENSITY = {"E1": 970.0, "E4": 960.0}
FLUID_VISCOSITY = {"E1": 0.373, "E4": 0.058}   # Pa s
PARTICLE_DENSITY = 1120.0
GRAVITY = 9.81
# ten Cate's u_inf (m/s, Table 1 as printed, physics-references.md section 1); the
# reference u_max is their u_max/u_inf times it
TABLE_U_INF = {"E1": 0.038, "E4": 0.128}
DEFAULT_FORCING = "surfaceCorrected"
COST_TARGET_PCT = 2.0   # the u_max error whose cost is compared between the forcings


def unrounded_reference(name):
    """ten Cate's u_inf is Abraham's terminal speed for the case's parameters (it reproduces
    the printed u_inf and Re of E1 and E4 to their digits); their ratio u_max/u_inf taken
    with the unrounded u_inf instead of the printed one gives this u_max (m/s). Returns it
    with Abraham's u_inf and the standard curve's unbounded terminal speed."""
    def speed(cd):
        return references.terminal_speed(cd, PARTICLE_DENSITY, FLUID_DENSITY[name],
                                         FLUID_VISCOSITY[name], D, GRAVITY)[0]
    u_abraham = speed(references.abraham)
    ratio = REFERENCE[name][0] / TABLE_U_INF[name]
    return ratio * u_abraham, u_abraham, speed(references.clift)


def load_reference(name):
    tag = REFERENCE[name][1]
    gap = np.loadtxt(os.path.join(data_dir, f"tencate_gap_{tag}.csv"), delimiter=",")
    u = np.loadtxt(os.path.join(data_dir, f"tencate_u_{tag}.csv"), delimiter=",")
    return gap, u


def load_run(path):
    with h5py.File(path, "r", locking=False) as f:
        t = np.asarray(f["time"][:], dtype=float)
        z = np.asarray(f["centre"][:, 0, 2], dtype=float)
        w = np.asarray(f["velocity"][:, 0, 2], dtype=float)
        fh = np.asarray(f["hydroForce"][:, 0, 2], dtype=float)
        fc = np.asarray(f["collisionForce"][:, 0, 2], dtype=float)
    rows = read_csv(path[:-3] + ".csv")    # cells, ranks, wall time, steps; optional
    return t, z, w, fh, fc, rows[0] if rows else {}


def landing(t, z, w, fh, rho_f):
    """The landing, from the first touch (gap <= 0) on: the largest downward hydrodynamic
    force over the buoyant weight, the largest overlap (in d), the largest upward speed
    (over u_max) and the largest gap (in d). An upward speed with the gap never opening
    beyond the lubrication's saturation gap is the contact spring giving back its overlap,
    not a rebound off the floor."""
    touch = np.flatnonzero(z - D / 2 <= 0)
    if not len(touch):
        return None
    after = slice(touch[0], None)
    weight = (1120.0 - rho_f) * 9.81 * np.pi * D ** 3 / 6
    return dict(push=float(-fh[after].min() / weight), overlap=float(-(z[after] - D / 2).min() / D),
                rebound=float(max(w[after].max(), 0.0) / -w.min()),
                maxGapAfter=float((z[after] - D / 2).max() / D), touchTime=float(t[touch[0]]))


def gap_from_velocity(gap_ref, u_ref, gap0):
    """The gap implied by the data's own velocity curve: gap0 at t = 0 (the sphere released
    from rest) minus the integral of |u| / d. The digitised gap and velocity curves are two
    records of one trajectory; where this curve and the gap curve differ, no trajectory can
    match both, and that difference bounds how well a gap error can be judged."""
    t = np.concatenate([[0.0], u_ref[:, 0]])
    u = np.concatenate([[0.0], u_ref[:, 1]])
    order = np.argsort(t)
    t, u = t[order], u[order]
    fine = np.linspace(0.0, t[-1], 4000)
    uf = np.interp(fine, t, u)
    travelled = np.concatenate([[0.0], np.cumsum(0.5 * (uf[1:] + uf[:-1]) * np.diff(fine))]) / D
    return fine, gap0 + travelled


def main():
    runs = sorted(glob.glob(os.path.join(here, "results", "E*-*.h5")))
    if not runs:
        sys.exit(f"plot.py: no results in {here}/results (run Allrun E4 8 first)")
    rows = []
    figs = {}
    for path in runs:
        tag = os.path.basename(path)[:-3]
        name, cpd, *rest = tag.split("-")       # <case>-<cpd>[-<forcing>][-column<W>][-dt<S>]
        column = next((v[len("column"):] for v in rest if v.startswith("column")), "")
        dt_scale = next((v[len("dt"):] for v in rest if v.startswith("dt")), "")
        forcing = next((v for v in rest if not v.startswith(("column", "dt"))), DEFAULT_FORCING)
        variant = "-".join(rest)
        t, z, w, fh, fc, info = load_run(path)
        land = landing(t, z, w, fh, FLUID_DENSITY[name])
        gap_ref, u_ref = load_reference(name)
        # the floor is a collision wall (lubricationContact): the comparison runs
        # to the end of the data; "contact" marks runs in which the sphere touched
        t_end = max(gap_ref[-1, 0], u_ref[-1, 0])
        gap = (z - D / 2) / D
        closed = np.flatnonzero(gap <= 0)
        keep = t <= t_end
        t, z, w = t[keep], z[keep], w[keep]
        umax = -w.min()
        uref = REFERENCE[name][0]
        # the digitised velocity curve's own largest speed, beside the table value uref
        ucurve = float(-u_ref[:, 1].min())
        unrounded = unrounded_reference(name)[0]
        # velocity error over the data's time range (interpolated to the data's times)
        inside = u_ref[:, 0] <= t[-1]
        u_sim = np.interp(u_ref[inside, 0], t, w)
        rms_u = np.sqrt(np.mean((u_sim - u_ref[inside, 1]) ** 2)) / uref
        # the same with the sphere held at rest from its first touch: what the contact's
        # motion after the touch adds to the whole-curve error
        w_rest = np.where(t >= land["touchTime"], 0.0, w) if land else w
        u_rest = np.interp(u_ref[inside, 0], t, w_rest)
        rms_u_rest = np.sqrt(np.mean((u_rest - u_ref[inside, 1]) ** 2)) / uref
        gap_sim = np.interp(gap_ref[:, 0], t, (z - D / 2) / D)
        inside_g = gap_ref[:, 0] <= t[-1]
        max_gap = np.max(np.abs(gap_sim[inside_g] - gap_ref[inside_g, 1]))
        # what the error is made of: the approach (the data's gap above 1 d, before the
        # film and the contact act) and the start (the data's gap at t = 0 against the
        # case's 8 d, an offset present from the first step)
        gap_ref_u = np.interp(u_ref[inside, 0], gap_ref[:, 0], gap_ref[:, 1])
        far_u = gap_ref_u > 1.0
        rms_u_far = np.sqrt(np.mean((u_sim[far_u] - u_ref[inside, 1][far_u]) ** 2)) / uref
        far_g = inside_g & (gap_ref[:, 1] > 1.0)
        max_gap_far = np.max(np.abs(gap_sim[far_g] - gap_ref[far_g, 1]))
        start_offset = np.interp(0.0, gap_ref[:, 0], gap_ref[:, 1]) - gap[0]
        max_gap_far_shifted = np.max(np.abs(gap_sim[far_g] + start_offset - gap_ref[far_g, 1]))
        # the data against themselves: the gap curve against the integral of the velocity
        # curve (both from the data's start gap), and the run against that integral over the
        # approach (the case's start gap, 8 d)
        gap0_ref = np.interp(0.0, gap_ref[:, 0], gap_ref[:, 1])
        t_int, gap_int = gap_from_velocity(gap_ref, u_ref, gap0_ref)
        within = gap_ref[:, 0] <= t_int[-1]
        data_inconsistency = np.max(np.abs(gap_ref[within, 1] - np.interp(gap_ref[within, 0], t_int, gap_int)))
        approach = (t_int <= t[-1]) & (gap_int - gap0_ref + gap[0] > 1.0)
        gap_sim_int = np.interp(t_int[approach], t, (z - D / 2) / D)
        max_gap_vs_u = np.max(np.abs(gap_sim_int - (gap_int[approach] - gap0_ref + gap[0])))
        rows.append(dict(case=name, cpd=int(cpd), forcing=forcing, variant=variant,
                         column=column or "2.5", dtScale=dt_scale or "1", cells=info.get("cells", ""),
                         ranks=info.get("ranks", ""),
                         steps=info.get("steps", ""), wallSeconds=info.get("wallSeconds", ""),
                         umax=umax, umaxRef=uref, umaxError=(umax - uref) / uref,
                         umaxCurve=ucurve, umaxErrorVsCurve=(umax - ucurve) / ucurve,
                         umaxUnrounded=unrounded,
                         umaxErrorVsUnrounded=(umax - unrounded) / unrounded,
                         rmsUError=rms_u, maxGapError=max_gap, endTime=t[-1],
                         rmsUErrorApproach=rms_u_far, maxGapErrorApproach=max_gap_far,
                         startOffset=start_offset, maxGapErrorApproachShifted=max_gap_far_shifted,
                         dataInconsistency=data_inconsistency, maxGapErrorVsVelocityData=max_gap_vs_u,
                         landingPushOverWeight=land["push"] if land else "",
                         landingMaxOverlap=land["overlap"] if land else "",
                         landingReboundOverUmax=land["rebound"] if land else "",
                         landingMaxGapAfterTouch=land["maxGapAfter"] if land else "",
                         landingTouchTime=land["touchTime"] if land else "",
                         rmsUErrorAtRestAfterTouch=rms_u_rest if land else "",
                         contact=bool(len(closed))))
        if name not in figs:
            fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
            ax[0].plot(gap_ref[:, 0], gap_ref[:, 1], "ko", ms=3, label="ten Cate et al. 2002")
            ax[0].plot(t_int, gap_int, "k--", lw=1, label="the data's velocity curve, integrated")
            ax[1].plot(u_ref[:, 0], u_ref[:, 1], "ko", ms=3, label="ten Cate et al. 2002")
            figs[name] = (fig, ax)
        fig, ax = figs[name]
        style = "-" if not variant else ":"
        label = (f"{cpd} cells/D" + ("" if forcing == DEFAULT_FORCING else f", {forcing}")
                 + (f", fine column {column} d" if column else "")
                 + (f", time step x{dt_scale}" if dt_scale else ""))
        ax[0].plot(t, (z - D / 2) / D, style, label=label)
        ax[1].plot(t, w, style, label=label)
    for name, (fig, ax) in figs.items():
        ax[0].set_xlabel("t (s)"); ax[0].set_ylabel("gap / d")
        ax[0].set_ylim(bottom=-0.3)
        ax[1].set_xlabel("t (s)"); ax[1].set_ylabel("u_z (m/s)")
        ax[0].legend(); ax[1].legend()
        fig.suptitle(f"ten Cate settling sphere, case {name}")
        fig.tight_layout()
        fig.savefig(os.path.join(here, f"tenCate_{name}.png"), dpi=110)
    rows.sort(key=lambda r: (r["case"], r["variant"] != "", r["variant"], r["cpd"]))
    write_csv(os.path.join(here, "results", "summary.csv"), rows)
    with open(os.path.join(here, "results", "summary.md"), "w") as f:
        f.write("| case | forcing | fine column (d) | time step (x default) | cells/D | cells | ranks | steps | wall (s) | u_max (m/s) | ref. | u_max error "
                "| rms u error / u_max | max gap error / d | compared up to t (s) "
                "| rms u error, gap > 1 d | max gap error, gap > 1 d | the same, start offset removed "
                "| max gap error against the data's integrated velocity, gap > 1 d "
                "| the data's gap curve against their integrated velocity |"
                "\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write(f"| {r['case']} | {r['forcing']} | {r['column']} | {r['dtScale']} | {r['cpd']} | {r['cells']} | {r['ranks']} | {r['steps']} | {r['wallSeconds']} "
                    f"| {r['umax']:.5f} | {r['umaxRef']:.5f} | {100 * r['umaxError']:+.1f} % "
                    f"| {100 * r['rmsUError']:.1f} % | {r['maxGapError']:.3f} | {r['endTime']:.3f}"
                    f"{' (contact)' if r['contact'] else ''} "
                    f"| {100 * r['rmsUErrorApproach']:.1f} % | {r['maxGapErrorApproach']:.3f} "
                    f"| {r['maxGapErrorApproachShifted']:.3f} ({r['startOffset']:+.3f}) "
                    f"| {r['maxGapErrorVsVelocityData']:.3f} | {r['dataInconsistency']:.3f} |\n")
        f.write("\nThe landing (runs that touched the floor): the first touch, the largest downward "
                "hydrodynamic force over the buoyant weight after it, the largest overlap, the largest "
                "upward speed, the largest gap after the touch, and the whole-curve velocity error with "
                "the sphere held at rest from its touch\n\n"
                "| case | variant | cells/D | first touch t (s) | push / weight | max overlap / d "
                "| max upward speed / u_max | max gap after touch / d | rms u error / u_max "
                "| the same, at rest from the touch |\n|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            if r["landingTouchTime"] == "":
                continue
            f.write(f"| {r['case']} | {r['variant'] or 'default'} | {r['cpd']} | {r['landingTouchTime']:.4f} "
                    f"| {r['landingPushOverWeight']:.1f} | {r['landingMaxOverlap']:.4f} "
                    f"| {r['landingReboundOverUmax']:.3f} | {r['landingMaxGapAfterTouch']:+.5f} "
                    f"| {100 * r['rmsUError']:.1f} % | {100 * r['rmsUErrorAtRestAfterTouch']:.1f} % |\n")
    metrics = {}
    for r in rows:
        key = f"{r['case']}_{r['cpd']}" + ("" if not r["variant"] else f"_{r['variant'].replace('-', '_')}")
        metrics[f"{key}_umax_error_pct"] = round(100 * r["umaxError"], 4)
        metrics[f"{key}_umax_error_vs_data_curve_max_pct"] = round(100 * r["umaxErrorVsCurve"], 4)
        metrics[f"{r['case']}_data_curve_umax_m_s"] = round(r["umaxCurve"], 6)
        metrics[f"{key}_umax_error_vs_unrounded_reference_pct"] = round(
            100 * r["umaxErrorVsUnrounded"], 4)
        ref_unrounded, u_abraham, u_clift = unrounded_reference(r["case"])
        metrics[f"{r['case']}_reference_umax_unrounded_m_s"] = round(ref_unrounded, 6)
        metrics[f"{r['case']}_abraham_u_inf_m_s"] = round(u_abraham, 6)
        metrics[f"{r['case']}_unbounded_terminal_speed_clift_m_s"] = round(u_clift, 6)
        metrics[f"{key}_rms_u_error_pct"] = round(100 * r["rmsUError"], 4)
        metrics[f"{key}_max_gap_error_d"] = round(float(r["maxGapError"]), 5)
        metrics[f"{key}_rms_u_error_pct_approach"] = round(100 * r["rmsUErrorApproach"], 4)
        metrics[f"{key}_max_gap_error_d_approach"] = round(float(r["maxGapErrorApproach"]), 5)
        metrics[f"{key}_max_gap_error_d_vs_integrated_velocity"] = round(float(r["maxGapErrorVsVelocityData"]), 5)
        metrics[f"{r['case']}_data_gap_vs_integrated_velocity_d"] = round(float(r["dataInconsistency"]), 5)
        if r["landingPushOverWeight"] != "":
            metrics[f"{key}_landing_push_over_weight"] = round(r["landingPushOverWeight"], 3)
            metrics[f"{key}_landing_max_overlap_d"] = round(r["landingMaxOverlap"], 5)
            metrics[f"{key}_landing_rebound_over_umax"] = round(r["landingReboundOverUmax"], 4)
            metrics[f"{key}_landing_max_gap_after_touch_d"] = round(r["landingMaxGapAfterTouch"], 5)
            metrics[f"{key}_landing_touch_time_s"] = round(r["landingTouchTime"], 4)
            metrics[f"{key}_rms_u_error_pct_at_rest_after_touch"] = round(100 * r["rmsUErrorAtRestAfterTouch"], 4)
    metrics.update(cost_of_target(rows, os.path.join(here, "results", "cost.md")))
    with open(os.path.join(here, "results", "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print(open(os.path.join(here, "results", "summary.md")).read())


def cost_of_target(rows, path):
    """The cost of u_max within COST_TARGET_PCT of the data with each forcing: the coarsest
    run from which every finer run of the same case and forcing is within it. Cost: cells,
    steps and core-seconds (wall time x ranks; the runs shared the machine, so upper bounds).
    Writes the table to path; returns its metrics."""
    metrics = {}
    # the case's own mesh and time step only
    rows = [r for r in rows if r["column"] == "2.5" and r["dtScale"] == "1"]
    lines = [f"| case | forcing | cells/D run | u_max error at them | coarsest within {COST_TARGET_PCT:g} % "
             "| cells | steps | core-seconds |", "|---|---|---|---|---|---|---|---|"]
    for case in sorted({r["case"] for r in rows}):
        for forcing in sorted({r["forcing"] for r in rows if r["case"] == case}):
            runs = sorted((r for r in rows if r["case"] == case and r["forcing"] == forcing),
                          key=lambda r: r["cpd"])
            within = [abs(100 * r["umaxError"]) <= COST_TARGET_PCT for r in runs]
            first = next((k for k in range(len(runs)) if all(within[k:])), None)
            errors = ", ".join(f"{100 * r['umaxError']:+.1f} %" for r in runs)
            cpds = "/".join(str(r["cpd"]) for r in runs)
            key = f"{case}_{forcing}_umax_{COST_TARGET_PCT:g}pct"
            if first is None:
                lines.append(f"| {case} | {forcing} | {cpds} | {errors} | not reached | | | |")
                metrics[f"{key}_cpd"] = None
                continue
            r = runs[first]
            core_s = float(r["wallSeconds"]) * float(r["ranks"]) if r["wallSeconds"] != "" else None
            core_text = f"{core_s:.0f}" if core_s is not None else ""
            lines.append(f"| {case} | {forcing} | {cpds} | {errors} | {r['cpd']} | {r['cells']} | {r['steps']} "
                         f"| {core_text} |")
            metrics[f"{key}_cpd"] = r["cpd"]
            metrics[f"{key}_cells"] = int(r["cells"]) if r["cells"] != "" else None
            metrics[f"{key}_core_seconds"] = core_s
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return metrics


if __name__ == "__main__":
    main()
