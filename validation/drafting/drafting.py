#!/usr/bin/python3
"""Drafting, kissing and tumbling (DKT) of two bodies settling one above the other in a closed
box: the 3D two-sphere set-up of Glowinski, Pan, Hesla, Joseph & Periaux (2001, JCP 169), and
the same with two prolate spheroids (aspect ratio 2, the spheres' volume).

    drafting.py run [--shape sphere|spheroid] [--cpd N] [--tilt DEG] [--offset F] [--end T]
                    [--np N] [--force] [--quick]
    drafting.py plot
    drafting.py collect

run:  one case in run/<tag>/ (git-ignored), nice; the body time series is copied to
      results/<tag>.h5 and a line written to results/runs.csv (a finished tag is skipped
      unless --force). --quick: the sphere at 4 cells/d for 0.1 s (the pipeline only; its
      line goes to run/quick.csv, its time series stays in run/; both git-ignored).
plot: results/table.md, results/metrics.json, results/trajectories.png, velocities.png,
      gap.png from the runs of results/runs.csv.
collect: recompute the measured columns of results/runs.csv from results/<tag>.h5.

Set-up: box 10 x 10 x 40 mm, no-slip walls, water (rho_f 1000 kg/m^3, nu 1e-6 m^2/s);
bodies rho_p 1140 kg/m^3 released from rest, centres (5, 5, 31.6) mm (leading) and
(5 + F d, 5, 35) mm (trailing, F = --offset, 0.01 by default), d = 1/6 cm (the spheroids' equal-volume diameter);
lubricationContact between the bodies and with every wall (e_dry 0.97, the rest defaults);
backward, PISO with 2 correctors, limitedLinearV 1, adaptive dt with Courant 0.4.

Measures (all from the body time series, one row per fluid step), d the equal-volume diameter:
- the surface gap: centre distance - d for spheres (negative in contact); for spheroids the
  signed distance between the two surfaces (minus the penetration depth in contact), the
  geometry core's certified dual method through ellipsoidDistance (surface_gaps);
- kissing: the first time the gap falls below KISS_GAP d (interpolated between rows), and the
  first time the collision model acts on the pair (its lubrication onset, a few cells wide);
- the collision speed: the largest downward speed of the trailing body up to the kissing time,
  and its time;
- tumbling: the first time after the kissing that the trailing body's centre is below the
  leading one's (their z order swaps);
- the leading body's speed at the pair force onset (the speed it reached on its own, the
  trailing body still a few cells away) with its acceleration there over g (how far from
  terminal it is), the Reynolds numbers of that speed and of the collision speed;
- the window: up to the first time either body comes within FLOOR_GAP d of the floor (its
  lowest point), so that nothing after the floor contact is measured.
"""
import argparse
import json
import math
import os
import shutil
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import (cpu_seconds, locked, merge_row, mesh_cells, provenance,  # noqa: E402
                             read_csv, run_logged, substitute, write_csv)

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")

D = 1.0 / 600.0                  # m, sphere diameter (1/6 cm), the spheroids' equal-volume one
R = D / 2
RHO_P, RHO_F, NU, G = 1140.0, 1000.0, 1e-6, 9.81
LX, LZ = 0.010, 0.040            # m, box width (x, y) and height (z)
LEADING = (0.005, 0.005, 0.0316)
TRAILING = (0.005, 0.005, 0.035)  # plus the offset along x
OFFSET = 0.01                    # the trailing body's x offset over d (breaks the symmetry)
ASPECT = 2.0                     # spheroid a/b, a along the symmetry axis
KISS_GAP = 0.05                  # kissing: surface gap below this fraction of d
FLOOR_GAP = 0.5                  # analysis window: lowest point at least this many d above the floor
END_TIME = 0.65                  # s, default simulated time: the leading sphere reaches the floor at about 0.6 s

# Published values for this set-up: two scalars quoted in a third-party validation script and
# attributed there to Lai et al. (2023); not checked against the paper.
LAI_KISSING_TIME = 0.34          # s
LAI_COLLISION_SPEED = 0.0714     # m/s

FIELDS = ["tag", "shape", "cpd", "tilt_deg", "offset_d", "np", "cells", "end_time", "steps", "t_last",
          "kiss_time", "pair_onset_time", "collision_speed", "collision_speed_time",
          "tumbling_time", "min_gap_d", "lead_speed", "lead_speed_time", "lead_acc_g", "Re_lead",
          "Re_collision", "window_end", "separation_end_d", "max_overlap_window", "max_overlap_run", "wall_s", "cpu_s", "host", "date", "commit"]


def semi_axes(shape):
    """(a, b, c) of the shape, a along the body x axis (the spheroid's symmetry axis)."""
    if shape == "sphere":
        return (R, R, R)
    a = R * ASPECT ** (2 / 3)
    b = R * ASPECT ** (-1 / 3)
    return (a, b, b)


def tag_of(shape, cpd, tilt, offset):
    return (f"{shape}-c{cpd}" + (f"-tilt{tilt:g}" if tilt else "")
            + (f"-off{offset:g}" if offset != OFFSET else ""))


def schiller_naumann_speed():
    """The terminal speed of the sphere in unbounded fluid from the Schiller-Naumann drag
    correlation, C_D = 24/Re (1 + 0.15 Re^0.687) (Re < 800): C_D Re^2 = 4/3 (rho_p/rho_f - 1)
    g d^3/nu^2, solved for Re by bisection. An estimate for the order of the speeds, not a
    reference of this set-up (the box walls, 3 d from the centres, slow the spheres)."""
    target = 4 / 3 * (RHO_P / RHO_F - 1) * G * D ** 3 / NU ** 2
    lo, hi = 1e-3, 800.0
    for _ in range(100):
        re_ = 0.5 * (lo + hi)
        if 24 * re_ * (1 + 0.15 * re_ ** 0.687) < target:
            lo = re_
        else:
            hi = re_
    return re_ * NU / D


# ---------------------------------------------------------------------------
# the case

def write_case(case, shape, cpd, tilt, end, np_, offset):
    """Copy caseTemplate/ to case and fill its placeholders (a placeholder not found stops the
    run, naming the file)."""
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(HERE, "caseTemplate"), case)
    nx, nz = round(LX / D * cpd), round(LZ / D * cpd)
    # the step follows the Courant limit; the cap only bounds the first steps from rest
    max_dt = 1e-3 * 8 / cpd
    substitute(f"{case}/system/blockMeshDict", "@CPD@", f"{cpd}")
    substitute(f"{case}/system/blockMeshDict", "@NX@ @NX@ @NZ@", f"{nx} {nx} {nz}")
    cd = f"{case}/system/controlDict"
    substitute(cd, "@END_TIME@", f"{end:g}")
    substitute(cd, "@MAX_DT@", f"{max_dt:g}")
    substitute(cd, "@WRITE_INTERVAL@", f"{end / 4:g}")
    substitute(f"{case}/system/decomposeParDict", "@NP@", f"{np_}", count=2)
    p = f"{case}/constant/immersedBodiesProperties"
    a, b, c = semi_axes(shape)
    substitute(p, "@SEMI_AXES@", f"({a:.12g} {b:.12g} {c:.12g})", count=2)
    substitute(p, "@CENTRE_LEADING@", "(%.9g %.9g %.9g)" % LEADING)
    substitute(p, "@CENTRE_TRAILING@", "(%.9g %.9g %.9g)" % (TRAILING[0] + offset * D, *TRAILING[1:]))
    # symmetry axis vertical, or tilted by tilt degrees in the x-z plane
    t = math.radians(tilt)
    substitute(p, "@AXIS@", f"({math.sin(t):.9g} 0 {math.cos(t):.9g})", count=2)
    return dict(cells=nx * nx * nz, max_dt=max_dt)


# ---------------------------------------------------------------------------
# geometry

def rotation(q):
    """Rotation matrices (..., 3, 3) of unit quaternions q (..., 4) = (w, x, y, z)."""
    w, x, y, z = np.moveaxis(np.asarray(q, float), -1, 0)
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


def vertical_extent(axes, rot):
    """Half the height of an ellipsoid (semi-axes axes, rotation rot (..., 3, 3)): the distance
    from its centre to its lowest point, sqrt(sum_i (a_i R_zi)^2)."""
    return np.sqrt(np.sum((np.asarray(axes) * rot[..., 2, :]) ** 2, axis=-1))


def distance_application():
    """The geometry core's ellipsoidDistance application (built by ./Allwmake)."""
    exe = os.path.join(os.environ.get("FOAM_USER_APPBIN", ""), "ellipsoidDistance")
    if not os.access(exe, os.X_OK):
        raise RuntimeError(f"drafting: {exe} not found; build the module (./Allwmake) and source "
                           f"etc/bashrc (FOAM_USER_APPBIN)")
    return exe


def surface_gaps(axes, c1, q1, c2, q2):
    """The signed distance between the surfaces of two ellipsoids of semi-axes axes at each
    row: centres c1, c2 (N, 3), unit quaternions q1, q2 (N, 4) = (w, x, y, z); minus the
    penetration depth where they overlap. The geometry core's certified dual method, through
    ellipsoidDistance (one call for all rows); a row it does not certify stops the analysis."""
    import csv
    import io
    import subprocess
    a = np.broadcast_to(np.asarray(axes, float), (len(c1), 3))
    rows = np.hstack([a, c1, q1, a, c2, q2])
    text = "a1,b1,c1,x1,y1,z1,qw1,qx1,qy1,qz1,a2,b2,c2,x2,y2,z2,qw2,qx2,qy2,qz2\n" + \
        "".join(",".join(repr(float(x)) for x in row) + "\n" for row in rows)
    done = subprocess.run([distance_application(), "-method", "dual", "-epsRel", "1e-9", "-"],
                          input=text, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"drafting: ellipsoidDistance failed: {done.stderr.strip()}")
    out = list(csv.DictReader(io.StringIO(done.stdout)))
    if len(out) != len(rows):
        raise RuntimeError(f"drafting: ellipsoidDistance gave {len(out)} rows for {len(rows)}")
    bad = [r for r in out if r["status"] not in ("converged", "overlapping")]
    if bad:
        raise RuntimeError(f"drafting: ellipsoidDistance did not certify row {bad[0]['row']} "
                           f"({bad[0]['status']})")
    return np.array([float(r["distance"]) for r in out])


# ---------------------------------------------------------------------------
# the time series

def load(h5):
    """The time series of both bodies: t, centre (N, 2, 3), velocity, collisionForce,
    orientation (N, 2, 4), semi-axes; the bodies ordered (leading, trailing) by name."""
    import h5py
    with h5py.File(h5, "r", locking=False) as f:
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["bodyNames"][()]]
        n = min(len(f[k]) for k in ("time", "centre", "velocity", "collisionForce", "orientation"))
        idx = [names.index("leading"), names.index("trailing")]
        out = dict(t=f["time"][:n])
        for k in ("centre", "velocity", "collisionForce", "orientation"):
            out[k] = f[k][:n][:, idx, :]
        out["axes"] = f["semiAxes"][()][idx[0]]
    return out


def first_crossing(t, y, level, start=0):
    """The first time from row start at which y falls below level, interpolated linearly
    between the rows; None if it does not."""
    below = np.flatnonzero(y[start:] < level)
    if len(below) == 0:
        return None, None
    k = start + below[0]
    if k == 0:
        return float(t[0]), 0
    f = (y[k - 1] - level) / (y[k - 1] - y[k])
    return float(t[k - 1] + f * (t[k] - t[k - 1])), int(k)


def analyse(h5):
    """The measures of one run (module docstring) and the series the figures use."""
    s = load(h5)
    t, c, u, fc = s["t"], s["centre"], s["velocity"], s["collisionForce"]
    if not (np.all(np.isfinite(c)) and np.all(np.isfinite(u))):
        raise RuntimeError(f"{h5}: non-finite body state")
    axes = s["axes"]
    sphere = np.ptp(axes) < 1e-12 * axes[0]
    rot = rotation(s["orientation"])
    # the gap between the surfaces, over d
    dist = np.linalg.norm(c[:, 1] - c[:, 0], axis=1)
    if sphere:
        gap = (dist - 2 * axes[0]) / D
    else:
        q = s["orientation"]
        gap = surface_gaps(axes, c[:, 0], q[:, 0], c[:, 1], q[:, 1]) / D
    # the window: both lowest points at least FLOOR_GAP d above the floor
    floor = c[:, :, 2] - vertical_extent(axes, rot)
    low = np.flatnonzero(np.min(floor, axis=1) < FLOOR_GAP * D)
    n = low[0] if len(low) else len(t)
    window_end = float(t[n - 1])
    tw, gw = t[:n], gap[:n]
    kiss, k_kiss = first_crossing(tw, gw, KISS_GAP)
    # the pair's collision force: the first row with a collision force on the trailing body
    # while the pair is within 1 d (its wall gaps are several d here)
    pair = np.flatnonzero((np.linalg.norm(fc[:n, 1], axis=1) > 0) & (gw < 1.0))
    onset = float(tw[pair[0]]) if len(pair) else None
    # collision speed: the trailing body's largest downward speed up to the kissing
    upto = k_kiss + 1 if k_kiss is not None else n
    w_trail = -u[:upto, 1, 2]
    j = int(np.argmax(w_trail))
    collision_speed, collision_time = float(w_trail[j]), float(tw[j])
    # tumbling: the trailing centre below the leading one, after the kissing
    tumble = None
    if k_kiss is not None:
        dz = c[:n, 1, 2] - c[:n, 0, 2]
        tumble, _ = first_crossing(tw, dz, 0.0, k_kiss)
    # the leading body's speed and acceleration at the pair force onset (at the kissing if the
    # pair never gets a force, at the window's end if neither): the speed it reached on its own,
    # the trailing body still at the onset gap; its acceleration over g says how far from
    # terminal it is
    ref = pair[0] if len(pair) else (k_kiss if k_kiss is not None else n - 1)
    w_lead = -u[:n, 0, 2]
    acc = np.gradient(w_lead, tw) if n > 2 else np.zeros(n)
    lead_speed, lead_time, lead_acc = float(w_lead[ref]), float(tw[ref]), float(acc[ref] / G)
    # the angle between each body's symmetry axis (body x) and the vertical, 0 to 90 degrees
    # (the axis has no direction); zero for spheres
    tilt = np.degrees(np.arccos(np.clip(np.abs(rot[:, :, 2, 0]), 0, 1))) if not sphere \
        else np.zeros((len(t), 2))
    sep = np.hypot(c[:, 1, 0] - c[:, 0, 0], c[:, 1, 1] - c[:, 0, 1]) / D
    return dict(t=t, centre=c, velocity=u, gap=gap, tilt=tilt, sphere=sphere, n=n,
                separation_end_d=float(sep[n - 1]),
                window_end=window_end,
                kiss_time=kiss, pair_onset_time=onset, collision_speed=collision_speed,
                collision_speed_time=collision_time, tumbling_time=tumble,
                min_gap_d=float(np.min(gw)), lead_speed=lead_speed, lead_speed_time=lead_time,
                lead_acc_g=lead_acc, Re_lead=lead_speed * D / NU,
                Re_collision=collision_speed * D / NU, t_last=float(t[-1]),
                steps=len(t) - 1)


def log_max_overlap(log, t_end):
    """The largest overlap over the smallest semi-axis the collision model reported in the
    solver log ('max overlap X a_min', one line per step): (up to the time t_end, over the
    whole run); None for a missing log."""
    import re
    if not os.path.exists(log):
        return None, None
    t, upto, every = 0.0, 0.0, 0.0
    with open(log) as f:
        for line in f:
            if line.startswith("Time = "):
                t = float(line.split()[2])
                continue
            m = re.search(r"max overlap (\S+) a_min", line)
            if m and line.startswith("collisions:"):
                x = float(m.group(1))
                every = max(every, x)
                if t <= t_end:
                    upto = max(upto, x)
    return upto, every


def fmt(x, digits=5):
    return "" if x is None else f"{x:.{digits}g}"


def measured(r):
    """The measured columns of runs.csv from analyse()."""
    return {k: fmt(r[k]) for k in ("kiss_time", "pair_onset_time", "collision_speed",
                                   "collision_speed_time", "tumbling_time", "min_gap_d",
                                   "lead_speed", "lead_speed_time", "lead_acc_g", "Re_lead",
                                   "Re_collision",
                                   "window_end", "t_last", "separation_end_d")} | dict(steps=r["steps"])


# ---------------------------------------------------------------------------
# run

def run_one(shape, cpd, tilt, end, np_, force, quick, offset=OFFSET):
    out_csv = os.path.join(HERE, "run", "quick.csv") if quick else RUNS_CSV
    tag = tag_of(shape, cpd, tilt, offset)
    if not force and not quick and any(r["tag"] == tag for r in read_csv(out_csv)):
        print(f"{tag}: in {os.path.relpath(out_csv, HERE)}, skipped")
        return
    case = os.path.join(HERE, "run", tag + ("-quick" if quick else ""))
    info = write_case(case, shape, cpd, tilt, end, np_, offset)
    print(f"{tag}: {info['cells']} cells, end {end:g} s, {np_} rank(s), in {case}", flush=True)
    start = time.time()
    rc = run_logged(["nice", "-n", "5", "./Allrun", str(np_)], case, "log.Allrun")
    wall = time.time() - start
    solver_log = os.path.join(case, "log.immersedSpheroidFoam")
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if rc != 0 or not os.path.exists(h5):
        sys.exit(f"drafting: {tag} failed (see {case}/log.*)")
    cpu = cpu_seconds(case, os.path.basename(solver_log))
    r = analyse(h5)
    ov_window, ov_run = log_max_overlap(solver_log, r["window_end"])
    row = dict(tag=tag, shape=shape, cpd=cpd, tilt_deg=f"{tilt:g}", offset_d=f"{offset:g}", np=np_,
               max_overlap_window=fmt(ov_window, 3), max_overlap_run=fmt(ov_run, 3),
               cells=mesh_cells(case), end_time=f"{end:g}", wall_s=round(wall),
               cpu_s=round(cpu) if math.isfinite(cpu) else "", **provenance(), **measured(r))
    print(f"  kissing {fmt(r['kiss_time'], 4)} s, pair force from {fmt(r['pair_onset_time'], 4)} s, "
          f"collision speed {fmt(r['collision_speed'], 4)} m/s at {fmt(r['collision_speed_time'], 4)} s, "
          f"tumbling {fmt(r['tumbling_time'], 4)} s, {r['steps']} steps, wall {wall:.0f} s",
          flush=True)
    if not quick:
        shutil.copy(h5, os.path.join(RESULTS, f"{tag}.h5"))
    merge_row(out_csv, row, "tag", FIELDS, ignore_extra=True)


# ---------------------------------------------------------------------------
# plot

def offset_of(r):
    return r.get("offset_d") or f"{OFFSET:g}"


def label(r):
    what = r["shape"] + (f", axes tilted {r['tilt_deg']} deg" if r["tilt_deg"] != "0" else "")
    what += f", offset {offset_of(r)} d" if offset_of(r) != f"{OFFSET:g}" else ""
    return f"{what}, {r['cpd']} cells/d"


def metric_key(r):
    return (r["shape"] + (f"_tilt{r['tilt_deg']}" if r["tilt_deg"] != "0" else "")
            + (f"_offset{offset_of(r)}" if offset_of(r) != f"{OFFSET:g}" else "") + f"_{r['cpd']}")


def num(x):
    return float(x) if x not in ("", None) else None


def diff(x, ref, decimals):
    """x (with its difference from ref, absolute and relative) as a table cell, with that many
    decimals."""
    if x is None:
        return "-"
    return f"{x:.{decimals}f} ({x - ref:+.{decimals}f}, {100 * (x / ref - 1):+.1f} %)"


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_csv(RUNS_CSV)
    if not rows:
        sys.exit("drafting: no runs in results/runs.csv")
    rows.sort(key=lambda r: (r["shape"] != "sphere", float(r["tilt_deg"]), float(offset_of(r)),
                             int(r["cpd"])))

    lines = ["| run | cells | kissing: gap < 0.05 d [s] | pair force from [s] | collision speed [m/s] "
             "(at t [s]) | tumbling [s] | smallest gap/d | leading body's speed at the pair force onset [m/s] (t [s]) "
             "| its acceleration/g | Re (leading) | Re (collision) | analysed up to [s] | horizontal separation/d then "
             "| largest overlap/a_min then (whole run) | run to [s] | steps | wall | CPU |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    u_sn = schiller_naumann_speed()
    metrics = dict(lai2023_kissing_time_s=LAI_KISSING_TIME,
                   lai2023_collision_speed_m_s=LAI_COLLISION_SPEED,
                   schiller_naumann_terminal_speed_m_s=round(u_sn, 5),
                   schiller_naumann_reynolds=round(u_sn * D / NU, 2))
    for r in rows:
        def ts(col):
            """A time [s] cell, to the millisecond."""
            return "-" if num(r[col]) is None else f"{num(r[col]):.3f}"

        lines.append(
            f"| {label(r)} | {int(r['cells']):,} | {ts('kiss_time')} | {ts('pair_onset_time')} | "
            f"{num(r['collision_speed']):.4f} ({ts('collision_speed_time')}) | {ts('tumbling_time')} | "
            f"{num(r['min_gap_d']):.3f} | {num(r['lead_speed']):.4f} ({ts('lead_speed_time')}) | "
            f"{num(r['lead_acc_g']):+.4f} | {num(r['Re_lead']):.0f} | {num(r['Re_collision']):.0f} | "
            f"{ts('window_end')} | {num(r['separation_end_d']):.3f} | "
            f"{r.get('max_overlap_window') or '-'} ({r.get('max_overlap_run') or '-'}) | "
            f"{num(r['end_time']):g} | {r['steps']} | {r['wall_s']} s | {r['cpu_s']} s |")
        key = metric_key(r)
        for name, col in (("kissing_time_s", "kiss_time"), ("pair_force_onset_s", "pair_onset_time"),
                          ("collision_speed_m_s", "collision_speed"),
                          ("collision_speed_time_s", "collision_speed_time"),
                          ("tumbling_time_s", "tumbling_time"), ("min_gap_over_d", "min_gap_d"),
                          ("leading_speed_m_s", "lead_speed"), ("leading_accel_over_g", "lead_acc_g"),
                          ("reynolds_leading", "Re_lead"),
                          ("reynolds_collision", "Re_collision"), ("analysed_up_to_s", "window_end"),
                          ("separation_at_window_end_over_d", "separation_end_d"),
                          ("max_overlap_in_window_over_a", "max_overlap_window"),
                          ("max_overlap_whole_run_over_a", "max_overlap_run"),
                          ("wall_s", "wall_s"), ("cpu_s", "cpu_s")):
            # null where the event did not happen within the analysed window
            metrics[f"{key}_{name}"] = num(r[col])
        metrics[f"{key}_cells"] = int(r["cells"])
        if r["shape"] == "sphere":
            if num(r["kiss_time"]) is not None:
                metrics[f"{key}_kissing_time_minus_lai2023_s"] = round(
                    num(r["kiss_time"]) - LAI_KISSING_TIME, 5)
            metrics[f"{key}_collision_speed_minus_lai2023_m_s"] = round(
                num(r["collision_speed"]) - LAI_COLLISION_SPEED, 5)
    lines += ["", "Spheres against the two values attributed to Lai et al. (2023) in a third-party "
              "validation script (not checked against the paper); in brackets the difference, "
              "absolute and relative:", "",
              "| run | kissing time [s] (Lai et al.: 0.34) | collision speed [m/s] (Lai et al.: 0.0714) |",
              "|---|---|---|"]
    for r in rows:
        if r["shape"] != "sphere":
            continue
        lines.append(f"| {label(r)} | {diff(num(r['kiss_time']), LAI_KISSING_TIME, 3)} | "
                     f"{diff(num(r['collision_speed']), LAI_COLLISION_SPEED, 4)} |")
    lines += ["", f"Single sphere in unbounded fluid, Schiller-Naumann drag correlation "
              f"(`schiller_naumann_speed`, an estimate, not a reference of this set-up): terminal "
              f"speed {u_sn:.4f} m/s, Re {u_sn * D / NU:.0f}."]
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")

    series = []
    for r in rows:
        h5 = os.path.join(RESULTS, f"{r['tag']}.h5")
        if os.path.exists(h5):
            series.append((r, analyse(h5)))

    def mark(ax):
        ax.axvline(LAI_KISSING_TIME, color="0.5", ls=":", lw=1)
        ax.grid(True, alpha=0.3)

    # trajectories: z and x of both bodies, and the spheroids' axis angle from the vertical
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
    for k, (r, a) in enumerate(series):
        for b, ls in ((0, "-"), (1, "--")):
            who = "leading" if b == 0 else "trailing"
            axes[0].plot(a["t"], a["centre"][:, b, 2] * 1e3, ls, color=f"C{k}",
                         label=f"{label(r)}, {who}")
            axes[1].plot(a["t"], (a["centre"][:, b, 0] - LX / 2) / D, ls, color=f"C{k}")
            if not a["sphere"]:
                axes[2].plot(a["t"], a["tilt"][:, b], ls, color=f"C{k}")
    axes[0].set_ylabel("z [mm]")
    axes[1].set_ylabel("(x - 5 mm) / d")
    axes[2].set_ylabel("spheroids: symmetry axis from the vertical [deg]")
    axes[2].set_ylim(0, 90)
    for ax in axes:
        ax.set_xlabel("t [s]")
        mark(ax)
    axes[0].legend(fontsize=7)
    fig.suptitle("Drafting, kissing and tumbling: centres (solid leading, dashed trailing; "
                 "dotted: kissing time 0.34 s attributed to Lai et al. 2023)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "trajectories.png"), dpi=120)

    # velocities: vertical speeds, with the collision speed attributed to Lai et al.
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for k, (r, a) in enumerate(series):
        for b, ls in ((0, "-"), (1, "--")):
            who = "leading" if b == 0 else "trailing"
            axes[0].plot(a["t"], -a["velocity"][:, b, 2], ls, color=f"C{k}",
                         label=f"{label(r)}, {who}")
            axes[1].plot(a["t"], a["velocity"][:, b, 0], ls, color=f"C{k}")
        axes[0].plot(a["collision_speed_time"], a["collision_speed"], "o", color=f"C{k}", mfc="none")
    axes[0].axhline(LAI_COLLISION_SPEED, color="0.5", ls=":", lw=1)
    axes[0].set_ylabel("settling speed -w [m/s]")
    axes[1].set_ylabel("horizontal velocity u [m/s]")
    for ax in axes:
        ax.set_xlabel("t [s]")
        mark(ax)
    axes[0].legend(fontsize=7)
    fig.suptitle("Velocities (circles: collision speed; dotted: 0.0714 m/s and 0.34 s "
                 "attributed to Lai et al. 2023)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "velocities.png"), dpi=120)

    # gap and horizontal separation
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for k, (r, a) in enumerate(series):
        axes[0].plot(a["t"], a["gap"], color=f"C{k}", label=label(r))
        sep = np.hypot(a["centre"][:, 1, 0] - a["centre"][:, 0, 0],
                       a["centre"][:, 1, 1] - a["centre"][:, 0, 1]) / D
        axes[1].plot(a["t"], sep, color=f"C{k}")
        axes[0].axvline(a["window_end"], color=f"C{k}", lw=0.5, ls="-.")
    axes[0].axhline(KISS_GAP, color="k", lw=0.5)
    axes[0].set_ylabel("surface gap / d")
    axes[0].set_yscale("symlog", linthresh=0.01)
    axes[1].set_ylabel("horizontal centre separation / d")
    for ax in axes:
        ax.set_xlabel("t [s]")
        mark(ax)
    axes[0].legend(fontsize=7)
    fig.suptitle("Gap between the surfaces (line: 0.05 d, the kissing threshold; dash-dot: end of "
                 "the analysed window) and horizontal separation", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "gap.png"), dpi=120)
    print("drafting: results/table.md, metrics.json, trajectories.png, velocities.png, gap.png")


def do_collect():
    # under the file's lock: a run beside this one may add its row meanwhile
    with locked(RUNS_CSV):
        rows = read_csv(RUNS_CSV)
        for row in rows:
            r = analyse(os.path.join(RESULTS, f"{row['tag']}.h5"))
            row.update(measured(r))
            # the largest overlaps from the solver log, while the run's folder is there
            log = os.path.join(HERE, "run", row["tag"], "log.immersedSpheroidFoam")
            if os.path.exists(log):
                ov_window, ov_run = log_max_overlap(log, r["window_end"])
                row.update(max_overlap_window=fmt(ov_window, 3), max_overlap_run=fmt(ov_run, 3))
        write_csv(RUNS_CSV, rows, FIELDS, ignore_extra=True)
    print(f"drafting: {len(rows)} runs re-analysed")


def main():
    ap = argparse.ArgumentParser()
    sp = ap.add_subparsers(dest="cmd", required=True)
    r = sp.add_parser("run")
    r.add_argument("--shape", choices=("sphere", "spheroid"), default="sphere")
    r.add_argument("--cpd", type=int, default=8, help="cells per diameter (default 8)")
    r.add_argument("--tilt", type=float, default=0.0,
                   help="spheroids: symmetry axes tilted from the vertical by DEG (x-z plane)")
    r.add_argument("--offset", type=float, default=OFFSET,
                   help=f"the trailing body's x offset over d (default {OFFSET:g})")
    r.add_argument("--end", type=float, default=END_TIME, help=f"end time [s] (default {END_TIME})")
    r.add_argument("--np", type=int, default=1, help="ranks (default 1)")
    r.add_argument("--force", action="store_true")
    r.add_argument("--quick", action="store_true")
    sp.add_parser("plot")
    sp.add_parser("collect")
    args = ap.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    if args.cmd == "plot":
        do_plot()
        return
    if args.cmd == "collect":
        do_collect()
        return
    if not 4 <= args.cpd <= 24:
        sys.exit(f"drafting: --cpd {args.cpd}: allowed 4 to 24 cells per diameter")
    if args.tilt and args.shape == "sphere":
        sys.exit("drafting: --tilt applies to spheroids only")
    if not 0 <= args.tilt <= 90:
        sys.exit(f"drafting: --tilt {args.tilt}: allowed 0 to 90 degrees")
    if not 0 <= args.offset <= 2:
        sys.exit(f"drafting: --offset {args.offset}: allowed [0, 2] d")
    if not 0 < args.end <= 2:
        sys.exit(f"drafting: --end {args.end}: allowed (0, 2] s")
    if args.np not in (1, 2, 4):
        sys.exit(f"drafting: --np {args.np}: allowed 1, 2, 4")
    if args.quick:
        run_one("sphere", 4, 0.0, 0.1, args.np, True, True)
        return
    run_one(args.shape, args.cpd, args.tilt, args.end, args.np, args.force, False, args.offset)


if __name__ == "__main__":
    main()
