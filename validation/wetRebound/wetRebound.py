#!/usr/bin/python3
"""Wet rebound of a steel sphere on a wall against Gondret, Lance and Petit (2002):
the five cases of physics-references.md section 2, e/e_dry against St and the
master curve e/e_dry = exp(-35/St) (Legendre et al.).

    wetRebound.py run [--case NAME ...] [--cpd N] [--max-overlap X] [--release-speed F]
                      [--bounce] [--force] [--quick]
    wetRebound.py plot
    wetRebound.py collect

run:  each case in run/<name>/ (git-ignored), serial, nice; the body time series is
      copied to results/<name>.h5 and a line appended to results/runs.csv; finished
      runs are skipped unless --force. --quick: the St 152 case at 6 cells/d to the
      rebound (about a minute; results/quick.csv).
plot: results/table.md (with the quasi-steady Stokes film estimate of each run), metrics.json,
      results/restitution.png, results/sameGap.png, results/trajectories.png and, for the
      --bounce runs, results/bounce.png (with Gondret's measured trajectories where their
      digitised files are in ../shared/validation-data/gondret2002: St27_trajectory.csv,
      St152_trajectory.csv, time from the touch [s], gap [m]).
collect: recompute the measured columns of results/runs.csv from results/<name>.h5
      (after a change of the analysis; the run columns are kept).

Set-up: a box 4d x 4d x 5d (side walls no-slip, bottom the collision wall), the
sphere released at gap 2d with the velocity of the case (U = 9 St mu/(rho_p d))
and gravity; it slows as its boundary layer and wake form, so St is measured:
U_in is the approach speed just before the first collision force (the lubrication
onset, 4 resolved gaps of 0.62 cells from the wall at the defaults), U_out the largest rebound speed once the sphere has left
the wall (gap >= 0 after the contact), e = U_out/U_in, St = rho_p U_in d/(9 mu);
e_spring (the largest speed at any time after the touch, at the end of the
stretched spring phase, before the film resists the separation) is reported too,
with the impulses of the collision force, the hydrodynamic force and the net weight
over the steps with a collision force, over m U_in (J_coll, J_hydro, J_gravity), the part of
J_hydro while the sphere already moves up (J_hydro_out) and the strongest downward
hydrodynamic force then over the largest collision force (suction). Fixed step dt = 0.4 h/U.
Collision: lubricationContact (e_dry 0.97, T_c = 10 dt, 10 sub-steps per contact,
the resolved-gap lubrication at its defaults, saturation 1e-3 a), penaltyRatio 1e-3,
virtualMass 0.5.
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
from validationTools import (cpu_seconds, locked, merge_row, provenance, read_csv,  # noqa: E402
                             run_logged, substitute_re, write_csv)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lubricationResolution"))
from sphereWallStokes import brenner  # noqa: E402  (Brenner's exact series, gap over the radius)

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
RHO_P = 7800.0
E_DRY = 0.97
# the library's defaults the film estimate uses: the wall's resolved gap in cells
# (LubricationParameters::kWallResolvedGapCells) and the activation gap in resolved gaps
# (kActivationOverResolvedGap)
RESOLVED_GAP_CELLS = 0.62
# the release gap and the box width, in d, of the validation's runs
DEFAULT_RELEASE_GAP = 2.0
DEFAULT_BOX_WIDTH = 4.0
ACTIVATION_OVER_DELTA = 4.0

# name: (St, Re, rho_f, mu, d) of Gondret et al. 2002 (physics-references.md 2)
CASES = {
    "St27": (27, 30, 965.0, 0.100, 6e-3),
    "St100": (100, 110, 953.0, 0.020, 4e-3),
    "St152": (152, 164, 935.0, 0.010, 3e-3),
    "St192": (192, 212, 953.0, 0.020, 6e-3),
    "St742": (742, 788, 920.0, 0.005, 5e-3),
}

FIELDS = ["name", "St_case", "cpd", "maxOverlap", "saturation", "virtualMass", "startShift", "releaseGap", "boxWidth", "releaseSpeed", "bounce", "cells", "dt", "steps", "U_release", "U_in", "U_out", "e",
          "e_spring", "e_after_film", "top_gap_a",
          "St", "e_over_edry", "master", "max_overlap_a", "J_coll", "J_hydro", "J_gravity", "J_hydro_out", "suction", "wall_s", "cpu_s", "host", "date",
          "commit"]


def write_case(case, name, cpd, end_factor=1.0, max_overlap=None, saturation=None,
               virtual_mass=None, start_shift=None, release_gap=None, box_width=None,
               release_speed=None, bounce=False):
    """The case of run `name`; start_shift: the release gap raised by that many cells (the
    sphere's position against the cells when it reaches the wall); release_gap: the gap at
    the release in d (default 2; the box is 3 d higher than it); box_width: the box's width
    in d (default 4); release_speed: the release speed over the case's speed (default 1; the
    sphere loses about 15 % of it while its boundary layer forms, so a faster release meets
    the wall at the experiment's speed); bounce: the run lasts through the rebound's top and
    the fall back to the wall (1.3 U/g' after the touch, U the case's speed, g' gravity less
    buoyancy: the ballistic time to the top of a rebound at U, which drag shortens)."""
    st, re_, rho_f, mu, d = CASES[name]
    a = d / 2
    u_case = 9 * st * mu / (RHO_P * d)
    u = u_case * (release_speed or 1.0)
    h = d / cpd
    dt = 0.4 * h / u_case
    gap0 = DEFAULT_RELEASE_GAP if release_gap is None else release_gap
    width = DEFAULT_BOX_WIDTH if box_width is None else box_width
    lx, lz = width * d, (gap0 + 3) * d
    nx, nz = round(width * cpd), round((gap0 + 3) * cpd)
    # approach, contact, and the rebound to its largest speed (the viscous
    # cases decelerate within a fraction of d; 1.2 d at St 742); a longer fall
    # is timed for the sphere slowed by up to 15 % while its wake forms
    shift = (start_shift or 0.0) * h
    approach = (2.0 * d + shift) / u if release_gap is None else (gap0 * d + shift) / (0.85 * u)
    end = end_factor * (approach + 40 * dt + (0.6 + 0.6 * (st > 500)) * d / u)
    if bounce:
        end = approach + 1.3 * u_case / (9.81 * (1 - rho_f / RHO_P))
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(HERE, "caseTemplate"), case)
    mm = 1e3
    bm = f"{case}/system/blockMeshDict"
    substitute_re(bm, r"^// .*cells.*$",
                  f"// {width:g}d x {width:g}d x {gap0 + 3:g}d, d = {d * mm:g} mm, {cpd} cells per d")
    substitute_re(bm, r"\(9 0 0\) \(9 9 0\) \(0 9 0\)",
                  f"({lx * mm:g} 0 0) ({lx * mm:g} {lx * mm:g} 0) (0 {lx * mm:g} 0)")
    substitute_re(bm, r"\(0 0 12\) \(9 0 12\) \(9 9 12\) \(0 9 12\)",
                  f"(0 0 {lz * mm:g}) ({lx * mm:g} 0 {lz * mm:g}) "
                  f"({lx * mm:g} {lx * mm:g} {lz * mm:g}) (0 {lx * mm:g} {lz * mm:g})")
    substitute_re(bm, r"\(24 24 32\)", f"({nx} {nx} {nz})")
    cd = f"{case}/system/controlDict"
    substitute_re(cd, r"^endTime .*$", f"endTime         {end:.6g};")
    substitute_re(cd, r"^deltaT .*$", f"deltaT          {dt:.6g};")
    substitute_re(cd, r"^maxDeltaT .*$", f"maxDeltaT       {dt:.6g};")
    substitute_re(cd, r"^writeInterval .*$", "writeInterval   100000;")
    substitute_re(f"{case}/constant/transportProperties", r"^nu .*$",
                  f"nu              {mu / rho_f:.8g};   // mu/rho_f [m^2/s]")
    p = f"{case}/constant/immersedBodiesProperties"
    substitute_re(p, r"^fluidDensity .*$", f"fluidDensity    {rho_f:g};")
    substitute_re(p, r"semiAxes .*$", f"semiAxes        ({a:g} {a:g} {a:g});")
    substitute_re(p, r"centre .*$",
                  f"centre          ({lx / 2:g} {lx / 2:g} {a + gap0 * d + shift:.9g});")
    substitute_re(p, r"velocity .*$", f"velocity        (0 0 {-u:.6g});")
    if max_overlap is not None:
        substitute_re(p, r"^    restitution     0.97;$",
                      f"    restitution     0.97;\n    maxOverlap      {max_overlap:g};")
    if saturation is not None:
        substitute_re(p, r"^    restitution     0.97;$",
                      f"    restitution     0.97;\n    saturation      {saturation:g};")
    if virtual_mass is not None:
        substitute_re(p, r"^fluidDensity .*$",
                      f"fluidDensity    {rho_f:g};\nvirtualMass     {virtual_mass:g};")
    return dict(dt=dt, cells=nx * nx * nz, U_release=u, end=end)


def first_bounce_end(gap):
    """The row of the second touch of the wall (the gap negative again after it was
    non-negative following the first touch), or the series' length."""
    below = np.flatnonzero(gap < 0)
    if len(below):
        out = below[0] + np.flatnonzero(gap[below[0]:] >= 0)
        again = out[0] + np.flatnonzero(gap[out[0]:] < 0) if len(out) else []
        if len(again):
            return int(again[0])
    return len(gap)


def analyse(h5, name):
    import h5py
    st, re_, rho_f, mu, d = CASES[name]
    a = d / 2
    with h5py.File(h5, "r", locking=False) as f:
        t = f["time"][()]
        z = f["centre"][:, 0, 2]
        w = f["velocity"][:, 0, 2]
        fc = f["collisionForce"][:, 0, 2]
        fh = f["hydroForce"][:, 0, 2]
    if not (np.all(np.isfinite(z)) and np.all(np.isfinite(w))):
        raise RuntimeError(f"{name}: non-finite body state")
    touched = np.flatnonzero(fc != 0)
    if len(touched) == 0:
        raise RuntimeError(f"{name}: the sphere never reached the wall")
    i0 = touched[0]
    if i0 == 0:
        raise RuntimeError(f"{name}: a collision force in the first row, no approach to measure")
    u_in = -w[i0 - 1]
    gap = z - a
    # the first bounce only: the series ends before a second touch of the wall
    end = first_bounce_end(gap)
    t, z, w, fc, fh, gap = (x[:end] for x in (t, z, w, fc, fh, gap))
    touched = touched[touched < end]
    # the largest rebound speed once the sphere has left the wall (gap >= 0
    # again after the contact: the film's resistance to the separation
    # included); the largest speed at any time after the touch, reached at
    # the end of the stretched spring phase, is reported beside it
    inContact = np.flatnonzero(gap[i0:] < 0)
    u_spring = max(w[i0:].max(), 0.0)
    # out_gap: the gap of the sample u_out is taken at
    if len(inContact):
        left = i0 + inContact[-1] + 1
        u_out = max(w[left:].max(), 0.0) if left < len(w) else 0.0
        out_gap = gap[left + int(np.argmax(w[left:]))] if left < len(w) else 0.0
    else:
        u_out = u_spring
        out_gap = gap[i0 + int(np.argmax(w[i0:]))]
    # the largest upward speed once the collision model's forces (contact and film) have
    # vanished: beyond the lubrication onset on the way out, where the film's loss on the way
    # out is complete; zero if the sphere falls back before it leaves the film's range
    left = i0 + (inContact[-1] + 1 if len(inContact) else 0)
    free = left + np.flatnonzero(fc[left:] == 0)
    u_after_film = max(w[free[0]:].max(), 0.0) if len(free) else 0.0
    # the rebound's height: the largest gap once the sphere moves away from the wall
    # (after its deepest point), not the gap of the approach at the first collision force
    deepest = i0 + int(np.argmin(gap[i0:]))
    top_gap = gap[deepest:].max()
    # impulses over the steps with a collision force, over m U_in (the forces
    # of row k act over the step that ends at row k; fixed step)
    i1 = touched[-1]
    dt = t[1] - t[0]
    volume = 4 / 3 * math.pi * a ** 3
    momentum = RHO_P * volume * u_in
    j_coll = np.sum(fc[i0:i1 + 1]) * dt / momentum
    j_hydro = np.sum(fh[i0:i1 + 1]) * dt / momentum
    j_gravity = -(RHO_P - rho_f) * volume * 9.81 * (i1 + 1 - i0) * dt / momentum
    # the part of J_hydro while the sphere already moves up (leaves the wall),
    # and the strongest downward hydrodynamic force then, over the largest
    # collision force
    up = np.arange(i0, i1 + 1)[w[i0:i1 + 1] > 0]
    j_hydro_out = np.sum(fh[up]) * dt / momentum
    suction = max(-fh[up].min(), 0.0) / fc[i0:i1 + 1].max() if len(up) else 0.0
    return dict(t=t, gap=gap / d, w=w, U_in=u_in, U_out=u_out, e=u_out / u_in,
                e_spring=u_spring / u_in, e_after_film=u_after_film / u_in, top_gap_a=top_gap / a,
                out_gap_a=out_gap / a,
                St=RHO_P * u_in * d / (9 * mu), max_overlap_a=max(-gap.min(), 0) / a,
                J_coll=j_coll, J_hydro=j_hydro, J_gravity=j_gravity, J_hydro_out=j_hydro_out,
                suction=suction)


# gaps over the radius at which the rebound speed is also compared with the approach speed at
# the same gap (same_gap_restitution)
SAME_GAPS = (0.05, 0.1, 0.2, 0.3, 0.5)


def same_gap_restitution(h5, name, gaps=SAME_GAPS):
    """e(h)/e_dry = U_out(h)/(e_dry U_in(h)): the speed at which the sphere first passes the gap
    h on the way out over its speed at the same gap on the way in, both interpolated linearly
    between the samples (zero where the rebound does not reach h). The ratio of speeds at one
    position is what a velocity measured at a given distance from the wall compares; it
    includes the film's loss on both sides of the contact down to that gap."""
    import h5py
    a = CASES[name][4] / 2
    with h5py.File(h5, "r", locking=False) as f:
        gap = f["centre"][:, 0, 2] / a - 1.0
        w = f["velocity"][:, 0, 2]
    end = first_bounce_end(gap)
    gap, w = gap[:end], w[:end]
    deepest = int(np.argmin(gap))
    gap_in, w_in = gap[:deepest][::-1], w[:deepest][::-1]
    top = deepest + int(np.argmax(gap[deepest:]))
    gap_out, w_out = gap[deepest:top + 1], w[deepest:top + 1]
    values = []
    for h in gaps:
        u_in = -np.interp(h, gap_in, w_in)
        if gap_out[-1] < h:
            values.append(0.0)
            continue
        j = int(np.flatnonzero(gap_out >= h)[0])
        u_out = np.interp(h, gap_out[j - 1:j + 1], w_out[j - 1:j + 1])
        values.append(u_out / u_in / E_DRY)
    return values


def default_geometry(r):
    """True for a run in the validation's box, released from the default gap."""
    return ((r.get("releaseGap") or f"{DEFAULT_RELEASE_GAP:g}") == f"{DEFAULT_RELEASE_GAP:g}"
            and (r.get("boxWidth") or f"{DEFAULT_BOX_WIDTH:g}") == f"{DEFAULT_BOX_WIDTH:g}")


def standard_release(r):
    """True for a run released at the case's speed and stopped after the rebound's largest
    speed (not a trajectory run of --release-speed or --bounce)."""
    return (r.get("releaseSpeed") or "1") == "1" and (r.get("bounce") or "0") == "0"


def default_position(r):
    """True for a run released from the default position in the validation's box."""
    return r["startShift"] == "0" and default_geometry(r) and standard_release(r)


def same_gap_rows(rows, variants=False):
    """{cpd: [(row, [e(h)/e_dry for SAME_GAPS])]} for the default-setting runs, or with
    variants, for every run released from the default position (each setting its rows)."""
    out = {}
    for r in rows:
        if not default_position(r) or (not variants and (r["maxOverlap"], r["saturation"],
                                                         r["virtualMass"]) != ("0.1", "0.001", "0.5")):
            continue
        name = r["name"].split("-c")[0]
        h5 = os.path.join(RESULTS, f"{r['name']}.h5")
        out.setdefault(int(r["cpd"]), []).append((r, same_gap_restitution(h5, name)))
    return out


def same_gap_table(rows):
    """Markdown: e(h)/e_dry and its error against exp(-35/St) at the gaps SAME_GAPS, every
    run released from the default position (rows sorted as in the main table)."""
    lines = ["Rebound speed over approach speed at the same gap h (`same_gap_restitution`), "
             "e(h)/e_dry (its error against exp(-35/St)):", "",
             "| case | cells/d | maxOverlap | saturation | C_v | St | exp(-35/St) | "
             + " | ".join(f"h = {h:g} a" for h in SAME_GAPS) + " |",
             "|---|---|---|---|---|---|---|" + "---|" * len(SAME_GAPS)]
    for cpd, sel in sorted(same_gap_rows(rows, variants=True).items()):
        for r, values in sel:
            master = float(r["master"])
            lines.append(f"| St {r['St_case']} | {cpd} | {r['maxOverlap']} | {r['saturation']} | "
                         f"{r['virtualMass']} | {float(r['St']):.0f} | {master:.3f} | "
                         + " | ".join(f"{v:.3f} ({v - master:+.3f})" for v in values) + " |")
    return lines


def measured(r):
    """The measured columns of runs.csv from analyse()."""
    return dict(U_in=f"{r['U_in']:.5g}", U_out=f"{r['U_out']:.5g}", e=f"{r['e']:.4f}",
                e_spring=f"{r['e_spring']:.4f}", e_after_film=f"{r['e_after_film']:.4f}",
                top_gap_a=f"{r['top_gap_a']:.4f}", St=f"{r['St']:.1f}",
                e_over_edry=f"{r['e'] / E_DRY:.4f}", master=f"{math.exp(-35 / r['St']):.4f}",
                max_overlap_a=f"{r['max_overlap_a']:.4f}", J_coll=f"{r['J_coll']:.3f}",
                J_hydro=f"{r['J_hydro']:.3f}", J_gravity=f"{r['J_gravity']:.3f}",
                J_hydro_out=f"{r['J_hydro_out']:.3f}", suction=f"{r['suction']:.3f}")


def run_one(name, cpd, force, quick, max_overlap=None, saturation=None, virtual_mass=None,
            start_shift=None, release_gap=None, box_width=None, release_speed=None, bounce=False):
    out_csv = os.path.join(RESULTS, "quick.csv") if quick else RUNS_CSV
    tag = (f"{name}-c{cpd}" + (f"-ov{max_overlap:g}" if max_overlap is not None else "")
           + (f"-sat{saturation:g}" if saturation is not None else "")
           + (f"-cv{virtual_mass:g}" if virtual_mass is not None else "")
           + (f"-sh{start_shift:g}" if start_shift is not None else "")
           + (f"-rg{release_gap:g}" if release_gap is not None else "")
           + (f"-w{box_width:g}" if box_width is not None else "")
           + (f"-rs{release_speed:g}" if release_speed is not None else "")
           + ("-bounce" if bounce else ""))
    rows = read_csv(out_csv)
    if not force and not quick and any(r["name"] == tag for r in rows):
        print(f"{tag}: in {os.path.relpath(out_csv, HERE)}, skipped")
        return
    case = os.path.join(HERE, "run", tag)
    info = write_case(case, name, cpd, max_overlap=max_overlap, saturation=saturation,
                      virtual_mass=virtual_mass, start_shift=start_shift,
                      release_gap=release_gap, box_width=box_width,
                      release_speed=release_speed, bounce=bounce)
    print(f"{tag}: {info['cells']} cells, dt {info['dt']:.3g} s, end {info['end']:.3g} s", flush=True)
    start = time.time()
    rc = run_logged(["nice", "-n", "5", "./Allrun"], case, "log.Allrun")
    wall = time.time() - start
    solver_log = os.path.join(case, "log.immersedSpheroidFoam")
    if rc != 0 or not os.path.exists(solver_log):
        sys.exit(f"wetRebound: {tag} failed (see {case}/log.*)")
    cpu = cpu_seconds(case, "log.immersedSpheroidFoam")
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    r = analyse(h5, name)
    master = math.exp(-35 / r["St"])
    row = dict(name=tag, St_case=CASES[name][0], cpd=cpd,
               maxOverlap=f"{max_overlap if max_overlap is not None else 0.1:g}",
               saturation=f"{saturation if saturation is not None else 1e-3:g}",
               virtualMass=f"{virtual_mass if virtual_mass is not None else 0.5:g}",
               startShift=f"{start_shift or 0:g}",
               releaseGap=f"{release_gap if release_gap is not None else DEFAULT_RELEASE_GAP:g}",
               boxWidth=f"{box_width if box_width is not None else DEFAULT_BOX_WIDTH:g}",
               releaseSpeed=f"{release_speed or 1:g}", bounce="1" if bounce else "0",
               cells=info["cells"],
               dt=f"{info['dt']:.6g}", steps=len(r["t"]) - 1, U_release=f"{info['U_release']:.5g}",
               wall_s=round(wall), cpu_s=round(cpu) if math.isfinite(cpu) else "",
               **provenance(), **measured(r))
    print(f"  U_in {r['U_in']:.4f} m/s, St {r['St']:.1f}, e {r['e']:.3f}, e/e_dry "
          f"{r['e'] / E_DRY:.3f} (master curve {master:.3f}), max overlap "
          f"{r['max_overlap_a']:.3f} a, wall {wall:.0f} s", flush=True)
    if not quick:
        shutil.copy(h5, os.path.join(RESULTS, f"{tag}.h5"))
    merge_row(out_csv, row, "name", FIELDS, ignore_extra=True)


def after_film_text(r):
    """Table cells: e/e_dry after the film, its error against the master curve, the top gap."""
    if not r.get("e_after_film"):
        return "- | - | -"
    after = float(r["e_after_film"]) / E_DRY
    return f"{after:.3f} | {after - float(r['master']):+.3f} | {float(r['top_gap_a']):.2f}"


def write_metrics(rows):
    """results/metrics.json: max_abs_deviation_<cpd>, the largest |e/e_dry - exp(-35/St)| over
    the cases run with the default maxOverlap and saturation at that resolution, and
    cases_<cpd>, how many cases that is (five when the resolution is complete);
    max_abs_deviation_after_film_<cpd>, the same with the rebound speed taken once the
    sphere has left the film's range; virtual_mass_<C_v>_shift_min/_max, the range of the change
    of e/e_dry over the cases run with another virtualMass against the default 0.5;
    start_shift_spread_<cpd> and start_shift_spread_after_film_<cpd>, the largest range of
    e/e_dry (and of the same after the film) over the release positions a case was run
    from (start_table); release_gap_<G>_box_<W>_St<N>_<cpd>_shift (and _after_film), the
    change of e/e_dry of a run released from G d in a box W d wide against the same case in the
    validation's set-up; max_abs_deviation_roughness_<cpd>, max_abs_deviation_<cpd> with the
    saturation gap 1e-4 R (the roughness of Gondret's spheres) when every case ran with it.
    Rows with a start shift or another set-up count only there."""
    metrics = {}
    default = [r for r in rows if r["maxOverlap"] == "0.1" and r["saturation"] == "0.001"
               and r["virtualMass"] == "0.5" and default_position(r)]
    for cpd in sorted({int(r["cpd"]) for r in default}):
        sel = [r for r in default if int(r["cpd"]) == cpd]
        metrics[f"max_abs_deviation_{cpd}"] = round(
            max(abs(float(r["e_over_edry"]) - float(r["master"])) for r in sel), 4)
        metrics[f"cases_{cpd}"] = len(sel)
        if all(r.get("e_after_film") for r in sel):
            metrics[f"max_abs_deviation_after_film_{cpd}"] = round(
                max(abs(float(r["e_after_film"]) / E_DRY - float(r["master"])) for r in sel), 4)
    # the same with the saturation gap at the roughness of Gondret's spheres (about 1e-4 R,
    # physics-references.md section 2) instead of the library's default
    rough = [r for r in rows if r["maxOverlap"] == "0.1" and r["saturation"] == "0.0001"
             and r["virtualMass"] == "0.5" and default_position(r)]
    for cpd in sorted({int(r["cpd"]) for r in rough}):
        sel = [r for r in rough if int(r["cpd"]) == cpd]
        if len({r["St_case"] for r in sel}) == len(CASES):
            metrics[f"max_abs_deviation_roughness_{cpd}"] = round(
                max(abs(float(r["e_over_edry"]) - float(r["master"])) for r in sel), 4)
    # the stabiliser's sensitivity: the largest shift of e/e_dry over the cases run with another
    # virtualMass C_v against the default 0.5 (same resolution, maxOverlap and saturation)
    base = {(r["St_case"], int(r["cpd"])): float(r["e_over_edry"]) for r in default}
    for cv in sorted({r["virtualMass"] for r in rows} - {"0.5"}, key=float):
        shifts = [float(r["e_over_edry"]) - base[(r["St_case"], int(r["cpd"]))] for r in rows
                  if r["virtualMass"] == cv and r["maxOverlap"] == "0.1" and default_position(r)
                  and r["saturation"] == "0.001" and (r["St_case"], int(r["cpd"])) in base]
        if shifts:
            metrics[f"virtual_mass_{cv}_shift_min"] = round(min(shifts), 4)
            metrics[f"virtual_mass_{cv}_shift_max"] = round(max(shifts), 4)
    # the release gap and the box width: the change of e/e_dry (at separation, after the film)
    # against the same case in the validation's set-up
    for r in rows:
        b = [x for x in default if x["St_case"] == r["St_case"] and x["cpd"] == r["cpd"]]
        if default_geometry(r) or not standard_release(r) or not b or (
                r["maxOverlap"], r["saturation"], r["virtualMass"],
                                            r["startShift"]) != ("0.1", "0.001", "0.5", "0"):
            continue
        key = f"release_gap_{r['releaseGap']}_box_{r['boxWidth']}_St{r['St_case']}_{r['cpd']}"
        metrics[f"{key}_shift"] = round(float(r["e_over_edry"]) - float(b[0]["e_over_edry"]), 4)
        metrics[f"{key}_shift_after_film"] = round(
            (float(r["e_after_film"]) - float(b[0]["e_after_film"])) / E_DRY, 4)
    for (cpd, key), spread in start_spreads(rows).items():
        metrics[f"start_shift_spread{key}_{cpd}"] = round(spread, 4)
    for cpd, sel in same_gap_rows(rows).items():
        for k, h in enumerate(SAME_GAPS):
            metrics[f"max_abs_deviation_same_gap_{h:g}_{cpd}"] = round(
                max(abs(values[k] - float(r["master"])) for r, values in sel), 4)
    bounce_metrics(rows, metrics)
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("wetRebound: results/metrics.json", metrics)


def start_groups(rows):
    """{(St_case, cpd): rows}: the default-setting runs of a case released from more than one
    position (start shifts of a fraction of a cell)."""
    groups = {}
    for r in rows:
        if (r["maxOverlap"] == "0.1" and r["saturation"] == "0.001" and r["virtualMass"] == "0.5"
                and default_geometry(r) and standard_release(r)):
            groups.setdefault((r["St_case"], int(r["cpd"])), []).append(r)
    return {k: sorted(v, key=lambda r: float(r["startShift"])) for k, v in groups.items()
            if len(v) > 1}


def start_spreads(rows):
    """{(cpd, "", "_after_film" or "_same_gap_<h>"): the largest range of e/e_dry (at
    separation, after the film, at the same gap h in and out) over the release positions of a
    case at that resolution}."""
    spreads = {}
    for (st, cpd), sel in start_groups(rows).items():
        same = [same_gap_restitution(os.path.join(RESULTS, f"{r['name']}.h5"), r["name"].split("-c")[0])
                for r in sel]
        for key, values in ([("", [float(r["e_over_edry"]) for r in sel]),
                             ("_after_film", [float(r["e_after_film"]) / E_DRY for r in sel])]
                            + [(f"_same_gap_{h:g}", list(v)) for h, v in zip(SAME_GAPS, zip(*same))]):
            spreads[(cpd, key)] = max(spreads.get((cpd, key), 0.0), max(values) - min(values))
    return spreads


def start_table(rows):
    """Markdown: e/e_dry, the same after the film and the top gap of each case released from
    several positions (the release gap raised by a fraction of a cell), with their ranges."""
    groups = start_groups(rows)
    if not groups:
        return []
    lines = ["Release position: the same case released a fraction of a cell higher (`--start-shift`), "
             "so that the sphere meets the wall at another position against the cells and the "
             "steps; the default settings otherwise:", "",
             "| case | cells/d | start shift [cells] | St | e/e_dry | e/e_dry after the film | top gap/a | "
             + " | ".join(f"e({h:g} a)/e_dry" for h in SAME_GAPS) + " |",
             "|---|---|---|---|---|---|---|" + "---|" * len(SAME_GAPS)]
    for (st, cpd), sel in sorted(groups.items(), key=lambda kv: (kv[0][1], float(kv[0][0]))):
        same = [same_gap_restitution(os.path.join(RESULTS, f"{r['name']}.h5"), r["name"].split("-c")[0])
                for r in sel]
        for r, values in zip(sel, same):
            lines.append(f"| St {st} | {cpd} | {r['startShift']} | {float(r['St']):.1f} | "
                         f"{float(r['e_over_edry']):.3f} | {float(r['e_after_film']) / E_DRY:.3f} | "
                         f"{float(r['top_gap_a']):.3f} | " + " | ".join(f"{v:.3f}" for v in values) + " |")
        columns = [[float(r["e_over_edry"]) for r in sel], [float(r["e_after_film"]) / E_DRY for r in sel],
                   [float(r["top_gap_a"]) for r in sel]] + [list(v) for v in zip(*same)]
        lines.append(f"| St {st} | {cpd} | range | | "
                     + " | ".join(f"{max(c) - min(c):.3f}" for c in columns) + " |")
    return lines


def geometry_table(rows):
    """Markdown: the runs released from another gap or in a wider box (the default settings
    otherwise) beside the same case in the validation's set-up."""
    other = [r for r in rows if not default_geometry(r) and standard_release(r)]
    if not other:
        return []
    base = {(r["St_case"], r["cpd"]): r for r in rows
            if default_position(r) and (r["maxOverlap"], r["saturation"], r["virtualMass"])
            == ("0.1", "0.001", "0.5")}
    lines = ["Release gap and box width: the same case released higher (`--release-gap`, the "
             "box 3 d higher than the gap) or in a wider box (`--box-width`), the default "
             "settings otherwise:", "",
             "| case | cells/d | release gap/d | box width/d | U_in [m/s] | St | e/e_dry | "
             "exp(-35/St) | error | e/e_dry after the film | top gap/a | "
             + " | ".join(f"e({h:g} a)/e_dry" for h in SAME_GAPS) + " |",
             "|---|---|---|---|---|---|---|---|---|---|---|" + "---|" * len(SAME_GAPS)]
    shown = set()
    for r in sorted(other, key=lambda r: (int(r["cpd"]), float(r["St_case"]),
                                          float(r["releaseGap"]), float(r["boxWidth"]))):
        for x in ([base[(r["St_case"], r["cpd"])]] if (r["St_case"], r["cpd"]) in base else []) + [r]:
            if x["name"] in shown:
                continue
            shown.add(x["name"])
            same = same_gap_restitution(os.path.join(RESULTS, f"{x['name']}.h5"),
                                        x["name"].split("-c")[0])
            lines.append(f"| St {x['St_case']} | {x['cpd']} | "
                         f"{x.get('releaseGap') or f'{DEFAULT_RELEASE_GAP:g}'} | "
                         f"{x.get('boxWidth') or f'{DEFAULT_BOX_WIDTH:g}'} | "
                         f"{float(x['U_in']):.3f} | {float(x['St']):.1f} | "
                         f"{float(x['e_over_edry']):.3f} | {float(x['master']):.3f} | "
                         f"{float(x['e_over_edry']) - float(x['master']):+.3f} | "
                         f"{float(x['e_after_film']) / E_DRY:.3f} | {float(x['top_gap_a']):.3f} | "
                         + " | ".join(f"{v:.3f}" for v in same) + " |")
    return lines


def film_estimate(st, cpd, saturation):
    """e/e_dry of quasi-steady Stokes lubrication alone: the sphere loses I/St of its speed
    between the collision onset (4 resolved gaps of 0.62 cells) and the saturation gap on the
    way in, bounces with e_dry and loses I/St again on the way out, I the integral of
    Brenner's excess resistance lambda - 1 over eps = h/a between the two gaps (m du = -6 pi mu
    a (lambda - 1) dh, the far-field drag balanced by the net weight). No inertia of the fluid,
    no contact time: what the film model can give at most."""
    onset = 2 * ACTIVATION_OVER_DELTA * RESOLVED_GAP_CELLS / cpd     # h/a
    eps = np.logspace(math.log10(saturation), math.log10(onset), 400)
    lam = np.array([brenner(x) for x in eps])
    loss = float(np.sum(0.5 * (lam[1:] + lam[:-1] - 2) * np.diff(eps))) / st
    return (E_DRY * (1 - loss) - loss) / E_DRY


# Gondret et al.'s measured rebound trajectories, digitised (two columns, no header: time in s
# from the touch, gap between the sphere and the plate in m), looked for in
# ../shared/validation-data/gondret2002 (or $GONDRET_DATA)
GONDRET_DATA = os.environ.get("GONDRET_DATA", os.path.join(HERE, "..", "..", "..", "shared",
                                                            "validation-data", "gondret2002"))
GONDRET_TRAJECTORY = {"St27": "St27_trajectory.csv", "St152": "St152_trajectory.csv"}


def measured_trajectory(name):
    """(t, gap) of Gondret's trajectory of case `name` in s and m, or None where the
    digitised file is not there."""
    path = os.path.join(GONDRET_DATA, GONDRET_TRAJECTORY.get(name, ""))
    if name not in GONDRET_TRAJECTORY or not os.path.isfile(path):
        return None
    data = np.loadtxt(path, delimiter=",", ndmin=2)
    if data.shape[1] != 2 or len(data) < 3 or not np.all(np.isfinite(data)):
        sys.exit(f"wetRebound: {path}: expected two finite columns (t [s], gap [m]), "
                 f"at least three rows")
    return data[:, 0], data[:, 1]


def bounce_analysis(h5, name):
    """The whole first bounce of a --bounce run: the touch and separation times (linear
    between the samples where the gap changes sign), the contact's duration and depth, the
    rebound's top (gap over a, time from the touch) and the series against the time from the
    touch; with Gondret's trajectory of the case (measured_trajectory), the rms and mean of
    our speed minus his (his speeds the differences of consecutive samples, compared at their
    mid-times from 2 ms after the touch on, where his sphere has left the wall) and his top."""
    import h5py
    a = CASES[name][4] / 2
    with h5py.File(h5, "r", locking=False) as f:
        t = f["time"][()]
        gap = f["centre"][:, 0, 2] - a
        w = f["velocity"][:, 0, 2]
    below = np.flatnonzero(gap < 0)
    if len(below) == 0 or below[0] == 0:
        raise RuntimeError(f"{name}: no touch of the wall after an approach")
    i = below[0]
    t_touch = t[i - 1] + (t[i] - t[i - 1]) * gap[i - 1] / (gap[i - 1] - gap[i])
    left = i + np.flatnonzero(gap[i:] >= 0)
    if len(left) == 0:
        raise RuntimeError(f"{name}: the sphere does not leave the wall")
    o = left[0]
    t_sep = t[o - 1] + (t[o] - t[o - 1]) * gap[o - 1] / (gap[o - 1] - gap[o])
    top = o + int(np.argmax(gap[o:]))
    # the approach speed 1.5 a from the wall, before the wall slows the sphere much
    approach = -float(np.interp(1.5 * a, gap[:i][::-1], w[:i][::-1]))
    out = dict(t=t - t_touch, gap_a=gap / a, w=w, contact_ms=(t_sep - t_touch) * 1e3,
               approach=approach,
               depth_a=-gap[i:o].min() / a, top_a=gap[top] / a, top_ms=(t[top] - t_touch) * 1e3,
               falls_back=bool(np.any(gap[top:] < 0)))
    ref = measured_trajectory(name)
    if ref is not None:
        tr, gr = ref
        after = np.flatnonzero(tr > 0)
        if len(after) == 0:
            sys.exit(f"wetRebound: Gondret's {name} trajectory has no sample after the touch (t > 0)")
        k = after[0] + int(np.argmax(gr[after]))
        mid = 0.5 * (tr[1:] + tr[:-1])
        speed = np.diff(gr) / np.diff(tr)
        sel = (mid > 2e-3) & (mid < out["t"][-1])
        diff = np.interp(mid[sel], out["t"], w) - speed[sel]
        out.update(ref_t=tr, ref_gap_a=gr / a, ref_top_a=gr[k] / a, ref_top_ms=tr[k] * 1e3,
                   rms_speed=float(np.sqrt(np.mean(diff ** 2))), mean_speed=float(np.mean(diff)))
    return out


def quasi_steady_bounce(a, rho_f, mu, u0, h0=1.5, saturation=1e-3, cv=0.5, g=9.81,
                        finite_re=True):
    """A sphere (radius a, density RHO_P) in a fluid of density rho_f and viscosity mu,
    starting h0 radii above the wall at the speed u0 towards it, under quasi-steady forces
    only: Brenner's exact resistance lambda(h/a) (frozen below the saturation gap) times
    Stokes' drag, plus Schiller and Naumann's finite-Re excess 0.15 Re^0.687 where finite_re,
    and the weight less buoyancy, on the mass with cv times the displaced fluid's; the touch
    reverses it instantly with e_dry. No unsteady fluid force, no contact time: the bounce
    that the film law and the steady drag give alone. Returns the top (over a), its time from
    the touch [ms], the speed at the touch, and the series (time from the touch, gap/a, speed
    positive upwards) from the touch to the landing or to 1 s."""
    volume = 4 / 3 * math.pi * a ** 3
    mass = RHO_P * volume + cv * rho_f * volume
    weight = (RHO_P - rho_f) * volume * g
    # lambda tabulated from the saturation gap to 1000 a (where it is 1.0011; 1 beyond)
    eps = np.logspace(math.log10(saturation), 3.0, 400)
    lam = np.array([brenner(x) for x in eps])
    stokes = 6 * math.pi * mu * a

    def resistance(h):
        """The drag coefficient c of F = -c u at the gap h (m)."""
        x = max(h / a, saturation)
        if x >= eps[-1]:
            return stokes
        return stokes * float(np.exp(np.interp(math.log(x), np.log(eps), np.log(lam))))

    h, u, t = h0 * a, -u0, 0.0
    base = min(1e-3 * a / max(u0, 1e-9), 0.05 * mass / (stokes * lam[0]) if mu > 0 else 1.0)
    t_touch, u_touch, series = None, None, []
    while t < 1.0:
        # a step that moves the sphere by at most 2 % of its gap (of the saturation gap below
        # it), so that the film's logarithm is integrated down to the touch
        dt = min(base, 0.02 * max(h, saturation * a) / max(abs(u), 1e-12))
        c = resistance(h)
        if finite_re and mu > 0:
            c += stokes * 0.15 * (rho_f * abs(u) * 2 * a / mu) ** 0.687
        # the drag implicit, the weight explicit
        u = (mass * u - weight * dt) / (mass + c * dt)
        t += dt
        if t_touch is None and h + u * dt <= 0:
            t_touch, u_touch = t, -u
            h, u = 0.0, -E_DRY * u
            series.append((0.0, 0.0, u))
            continue
        h += u * dt
        if t_touch is not None:
            series.append((t - t_touch, h / a, u))
            if h <= 0:
                break
    if t_touch is None:
        raise RuntimeError(f"quasi_steady_bounce: no touch within 1 s (u0 {u0} m/s)")
    data = np.array(series)
    k = int(np.argmax(data[:, 1]))
    return dict(top_a=float(data[k, 1]), top_ms=float(data[k, 0]) * 1e3, u_touch=u_touch,
                t=data[:, 0], gap_a=data[:, 1], u=data[:, 2])


def force_ratio(h5, name, way, gaps=(0.1, 0.4)):
    """The force the run's sphere feels between the gaps (over a) on its way in (way "in",
    before the first touch) or out (way "out", after it leaves the wall, moving up),
    collision (film correction) plus resolved, over the quasi-steady one at its gap and speed
    (quasi_steady_bounce's drag, weight excluded); the mean over the samples there."""
    import h5py
    st, re_, rho_f, mu, d = CASES[name]
    a = d / 2
    with h5py.File(h5, "r", locking=False) as f:
        gap = f["centre"][:, 0, 2] / a - 1.0
        w = f["velocity"][:, 0, 2]
        fc = f["collisionForce"][:, 0, 2]
        fh = f["hydroForce"][:, 0, 2]
    end = first_bounce_end(gap)
    below = np.flatnonzero(gap[:end] < 0)
    if len(below) == 0:
        return float("nan")
    if way == "in":
        rows = [k for k in range(below[0]) if w[k] < 0 and gaps[0] <= gap[k] <= gaps[1]]
    else:
        o = below[0] + np.flatnonzero(gap[below[0]:end] >= 0)
        if len(o) == 0:
            return float("nan")
        rows = [k for k in range(o[0], end) if w[k] > 0 and gaps[0] <= gap[k] <= gaps[1]]
    if not rows:
        return float("nan")
    stokes = 6 * math.pi * mu * a
    ratios = []
    for k in rows:
        c = stokes * (brenner(gap[k]) + 0.15 * (rho_f * abs(w[k]) * d / mu) ** 0.687)
        ratios.append((fc[k] + fh[k]) / (-c * w[k]))
    return float(np.mean(ratios))


def bounce_rows(rows):
    """The --bounce runs, by case, resolution, box width, overlap cap, saturation and C_v."""
    return sorted((r for r in rows if (r.get("bounce") or "0") == "1"),
                  key=lambda r: (float(r["St_case"]), int(r["cpd"]), float(r["boxWidth"]),
                                 -float(r["maxOverlap"]), float(r["saturation"]),
                                 float(r["virtualMass"])))


def bounce_table(rows):
    """Markdown: the --bounce runs' whole first bounce (bounce_analysis)."""
    sel = bounce_rows(rows)
    if not sel:
        return []
    lines = ["Whole first bounce (`--bounce`, released at `--release-speed` times the case's "
             "speed so that it meets the wall at about the experiment's speed): contact and "
             "top of the rebound, times from the touch; the quasi-steady bounce from the same "
             "approach speed 1.5 a from the wall (`quasi_steady_bounce`: Brenner's film, "
             "steady drag, weight, an instant bounce); the mean force between 0.1 and 0.4 a "
             "on the way in and out over the quasi-steady one (`force_ratio`); with Gondret's "
             "trajectory where its digitised file is in `" + os.path.relpath(GONDRET_DATA, HERE)
             + "`:", "",
             "| case | cells/d | box width/d | maxOverlap | saturation | C_v | release speed | "
             "approach at 1.5 a "
             "[m/s] | the case's speed [m/s] | U_in [m/s] | St | "
             "e/e_dry | contact [ms] | depth/a | top/a | top at [ms] | quasi-steady top/a | "
             "at [ms] | force over the quasi-steady, in | out | Gondret's top/a | "
             "at [ms] | speed rms (mean) difference [m/s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in sel:
        name = r["name"].split("-c")[0]
        b = bounce_analysis(os.path.join(RESULTS, f"{r['name']}.h5"), name)
        st, re_, rho_f, mu, d = CASES[name]
        q = quasi_steady_bounce(d / 2, rho_f, mu, b["approach"], saturation=float(r["saturation"]),
                                cv=float(r["virtualMass"]))
        h5 = os.path.join(RESULTS, f"{r['name']}.h5")
        ratio_in, ratio_out = force_ratio(h5, name, "in"), force_ratio(h5, name, "out")
        ref = (f"{b['ref_top_a']:.3f} | {b['ref_top_ms']:.1f} | "
               f"{b['rms_speed']:.3f} ({b['mean_speed']:+.3f})" if "ref_top_a" in b else "- | - | -")
        lines.append(f"| St {r['St_case']} | {r['cpd']} | {r['boxWidth']} | {r['maxOverlap']} | "
                     f"{r['saturation']} | {r['virtualMass']} | "
                     f"{r['releaseSpeed']} | {b['approach']:.3f} | "
                     f"{float(r['U_release']) / float(r['releaseSpeed']):.3f} | "
                     f"{float(r['U_in']):.3f} | {float(r['St']):.0f} | "
                     f"{float(r['e_over_edry']):.3f} | {b['contact_ms']:.2f} | {b['depth_a']:.3f} | "
                     f"{b['top_a']:.3f} | {b['top_ms']:.1f} | {q['top_a']:.3f} | "
                     f"{q['top_ms']:.1f} | {ratio_in:.2f} | {ratio_out:.2f} | {ref} |")
    return lines


def bounce_metrics(rows, metrics):
    """bounce_top_a_<case>_<cpd>_ov<maxOverlap> and bounce_contact_ms_... of every --bounce
    run; with Gondret's trajectory, bounce_top_ratio_... (our top over his) and
    bounce_rms_speed_...[m/s]."""
    for r in bounce_rows(rows):
        name = r["name"].split("-c")[0]
        b = bounce_analysis(os.path.join(RESULTS, f"{r['name']}.h5"), name)
        key = (f"{name}_{r['cpd']}_ov{r['maxOverlap']}"
               + (f"_box{r['boxWidth']}" if r["boxWidth"] != f"{DEFAULT_BOX_WIDTH:g}" else "")
               + (f"_sat{r['saturation']}" if r["saturation"] != "0.001" else "")
               + (f"_cv{r['virtualMass']}" if r["virtualMass"] != "0.5" else ""))
        metrics[f"bounce_top_a_{key}"] = round(b["top_a"], 4)
        metrics[f"bounce_contact_ms_{key}"] = round(b["contact_ms"], 3)
        if "ref_top_a" in b:
            metrics[f"bounce_top_ratio_{key}"] = round(b["top_a"] / b["ref_top_a"], 4)
            metrics[f"bounce_rms_speed_{key}"] = round(b["rms_speed"], 4)


def plot_bounces(rows, plt):
    """results/bounce.png: gap over a against the time from the touch, one panel a case."""
    sel = bounce_rows(rows)
    names = sorted({r["name"].split("-c")[0] for r in sel}, key=lambda n: CASES[n][0])
    if not names:
        return
    fig, axes = plt.subplots(1, len(names), figsize=(6 * len(names), 4.2), squeeze=False)
    for ax, name in zip(axes[0], names):
        ref = None
        high = 0.0
        for k, r in enumerate(x for x in sel if x["name"].startswith(name + "-")):
            b = bounce_analysis(os.path.join(RESULTS, f"{r['name']}.h5"), name)
            high = max(high, b["top_a"], b.get("ref_top_a", 0.0))
            box = ((f", box {r['boxWidth']} d" if r["boxWidth"] != f"{DEFAULT_BOX_WIDTH:g}" else "")
                   + (f", saturation {r['saturation']}" if r["saturation"] != "0.001" else "")
                   + (f", C_v {r['virtualMass']}" if r["virtualMass"] != "0.5" else ""))
            ax.plot(b["t"] * 1e3, b["gap_a"], "-", color=f"C{k}",
                    label=f"{r['cpd']} cells/d, maxOverlap {r['maxOverlap']}{box} "
                          f"(St {float(r['St']):.0f})")
            ref = ref or ("ref_t" in b and (b["ref_t"], b["ref_gap_a"]))
        if ref:
            ax.plot(ref[0] * 1e3, ref[1], "ko", mfc="none", label="Gondret et al. 2002 (measured)")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xlim(left=-5)
        ax.set_ylim(-0.1 * high, 1.25 * high)
        ax.set_xlabel("time from the touch [ms]")
        ax.set_ylabel("gap / a")
        ax.set_title(f"{name}: whole first bounce", fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "bounce.png"), dpi=120)


def film_table(rows):
    """Markdown: the film estimate beside each run of the default maxOverlap and virtual mass."""
    lines = ["Quasi-steady Stokes film estimate (`film_estimate`: lubrication losses only, from "
             "the onset gap to the saturation gap, in and out) against the runs and the master "
             "curve:", "",
             "| case | cells/d | saturation | St | e/e_dry run | the same after the film | film estimate "
             "| exp(-35/St) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["maxOverlap"] != "0.1" or r["virtualMass"] != "0.5" or not default_position(r):
            continue
        est = film_estimate(float(r["St"]), int(r["cpd"]), float(r["saturation"]))
        lines.append(f"| St {r['St_case']} | {r['cpd']} | {r['saturation']} | {float(r['St']):.0f} | "
                     f"{float(r['e_over_edry']):.3f} | {after_film_text(r).split(' | ')[0]} | "
                     f"{est:.3f} | {float(r['master']):.3f} |")
    return lines


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_csv(RUNS_CSV)
    if not rows:
        sys.exit("wetRebound: no runs in results/runs.csv")
    lines = ["| case | cells/d | maxOverlap | saturation | C_v | U_in [m/s] | St | e | e/e_dry | exp(-35/St) | error | "
             "e_spring/e_dry | e/e_dry after the film | its error | top gap/a | J_coll | J_hydro | "
             "J_gravity | J_hydro_out | suction | max overlap/a | wall |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        r.setdefault("maxOverlap", "")
        r["virtualMass"] = r.get("virtualMass") or "0.5"
        r["maxOverlap"] = r["maxOverlap"] or "0.1"
        r["saturation"] = r.get("saturation") or "0.001"
        r["startShift"] = r.get("startShift") or "0"
    rows.sort(key=lambda r: (int(r["cpd"]), -float(r["maxOverlap"]), -float(r["saturation"]),
                             float(r["virtualMass"]), float(r["St_case"])))
    for r in rows:
        if not default_position(r):
            continue
        err = float(r["e_over_edry"]) - float(r["master"])
        lines.append(f"| St {r['St_case']} (Gondret) | {r['cpd']} | {r['maxOverlap']} | "
                     f"{r['saturation']} | {r['virtualMass']} | "
                     f"{float(r['U_in']):.3f} | "
                     f"{float(r['St']):.0f} | {float(r['e']):.3f} | {float(r['e_over_edry']):.3f} | "
                     f"{float(r['master']):.3f} | {err:+.3f} | {float(r['e_spring']) / E_DRY:.3f} | "
                     f"{after_film_text(r)} | "
                     f"{r['J_coll']} | {r['J_hydro']} | {r['J_gravity']} | "
                     f"{r.get('J_hydro_out', '-')} | {r.get('suction', '-')} | "
                     f"{float(r['max_overlap_a']):.3f} | "
                     f"{r['wall_s']} s |")
    lines += [""] + film_table(rows)
    lines += [""] + same_gap_table(rows)
    start = start_table(rows)
    lines += [""] + start if start else []
    geometry = geometry_table(rows)
    lines += [""] + geometry if geometry else []
    bounce = bounce_table(rows)
    lines += [""] + bounce if bounce else []
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    write_metrics(rows)

    # one panel per definition of the rebound speed; the same colour and marker for a
    # resolution and setting in every panel
    panels = [("e_over_edry", 1.0, "after leaving the wall (the headline e)"),
              ("e_spring", 1 / E_DRY, "end of the spring phase"),
              ("e_after_film", 1 / E_DRY, "after the film (beyond the onset gap)")]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4), sharey=True)
    st = np.logspace(0.7, 3.2, 200)
    series = sorted({(int(r["cpd"]), r["maxOverlap"], r["saturation"], r["virtualMass"])
                     for r in rows})
    markers = "osD^vPX*"
    for ax, (key, scale, title) in zip(axes, panels):
        ax.semilogx(st, np.exp(-35 / st), "k-", label="exp(-35/St) (Legendre et al.)")
        for k, (cpd, ov, sat, cv) in enumerate(series):
            sel = [r for r in rows
                   if int(r["cpd"]) == cpd and r["maxOverlap"] == ov and r["saturation"] == sat
                   and r["virtualMass"] == cv and default_position(r)]
            if not all(r.get(key) for r in sel):
                continue
            what = (f"{cpd} cells/d, maxOverlap {ov}" + (f", saturation {sat}" if sat != "0.001" else "")
                    + (f", C_v {cv}" if cv != "0.5" else ""))
            ax.semilogx([float(r["St"]) for r in sel], [float(r[key]) * scale for r in sel],
                        markers[k % len(markers)], color=f"C{k}", mfc="none" if ov != "0.1" else None,
                        label=what)
        ax.set_xlabel("St = rho_p U_in d / (9 mu)")
        ax.set_ylim(0, 1.05)
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(title, fontsize=10)
    axes[0].set_ylabel("e / e_dry")
    axes[-1].legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.suptitle("Sphere-wall rebound in a viscous fluid (Gondret et al. 2002 cases)")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "restitution.png"), dpi=120, bbox_inches="tight")

    # the rebound speed over the approach speed at the same gap, against the gap
    groups = same_gap_rows(rows)
    fig, axes = plt.subplots(1, len(groups), figsize=(4.6 * len(groups), 4), sharey=True,
                             squeeze=False)
    for ax, (cpd, sel) in zip(axes[0], sorted(groups.items())):
        for k, (r, values) in enumerate(sorted(sel, key=lambda x: float(x[0]["St"]))):
            ax.plot(SAME_GAPS, [v - float(r["master"]) for v in values], "o-", color=f"C{k}",
                    label=f"St {float(r['St']):.0f}")
        ax.axhspan(-0.05, 0.05, color="0.85", zorder=0)
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xscale("log")
        ax.set_xlabel("gap h / a where both speeds are taken")
        ax.set_title(f"{cpd} cells/d", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("e(h)/e_dry - exp(-35/St)")
    axes[0][-1].legend(fontsize=8)
    fig.suptitle("Rebound over approach speed at the same gap (grey: the target band 0.05)")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "sameGap.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(6, 4))
    for r in sorted(rows, key=lambda r: float(r["St_case"])):
        if not default_position(r):
            continue
        h5 = os.path.join(RESULTS, f"{r['name']}.h5")
        if not os.path.exists(h5):
            continue
        name = r["name"].split("-c")[0]
        x = analyse(h5, name)
        d = CASES[name][4]
        ax.plot(x["t"] * float(r["U_in"]) / d, x["gap"], label=f"{r['name']} (St {float(r['St']):.0f})")
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("t U_in / d")
    ax.set_ylabel("gap / d")
    ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "trajectories.png"), dpi=120)
    plot_bounces(rows, plt)


def do_collect():
    # under the file's lock: a run beside this one may add its row meanwhile
    with locked(RUNS_CSV):
        rows = read_csv(RUNS_CSV)
        for row in rows:
            name = row["name"].split("-c")[0]
            row.update(measured(analyse(os.path.join(RESULTS, f"{row['name']}.h5"), name)))
        write_csv(RUNS_CSV, rows, FIELDS, ignore_extra=True)
    print(f"wetRebound: {len(rows)} runs re-analysed")


def main():
    ap = argparse.ArgumentParser()
    sp = ap.add_subparsers(dest="cmd", required=True)
    r = sp.add_parser("run")
    r.add_argument("--case", action="append", default=[], choices=sorted(CASES))
    r.add_argument("--cpd", type=int, default=12)
    r.add_argument("--max-overlap", type=float, default=None,
                   help="collision maxOverlap (default: the library's, 0.1); its own rows")
    r.add_argument("--saturation", type=float, default=None,
                   help="lubrication saturation gap/R (default: the library's, 1e-3); its own rows")
    r.add_argument("--virtual-mass", type=float, default=None,
                   help="virtualMass C_v (default: the library's, 0.5); its own rows")
    r.add_argument("--start-shift", type=float, default=None,
                   help="release gap raised by this many cells, [0, 1); its own rows")
    r.add_argument("--release-gap", type=float, default=None,
                   help="gap at the release in d (default 2; the box is 3 d higher); its own rows")
    r.add_argument("--box-width", type=float, default=None,
                   help="the box's width in d (default 4); its own rows")
    r.add_argument("--release-speed", type=float, default=None,
                   help="release speed over the case's speed (default 1); its own rows")
    r.add_argument("--bounce", action="store_true",
                   help="run through the rebound's top and back to the wall; its own rows")
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
    if args.cpd < 4 or args.cpd > 64:
        sys.exit(f"wetRebound: --cpd {args.cpd}: allowed 4 to 64 cells per diameter")
    if args.max_overlap is not None and not 0 < args.max_overlap <= 0.5:
        sys.exit(f"wetRebound: --max-overlap {args.max_overlap}: allowed (0, 0.5]")
    if args.saturation is not None and not 0 < args.saturation < 0.075:
        sys.exit(f"wetRebound: --saturation {args.saturation}: allowed (0, 0.075)")
    if args.virtual_mass is not None and not 0 <= args.virtual_mass <= 10:
        sys.exit(f"wetRebound: --virtual-mass {args.virtual_mass}: allowed [0, 10]")
    if args.start_shift is not None and not 0 <= args.start_shift < 1:
        sys.exit(f"wetRebound: --start-shift {args.start_shift}: allowed [0, 1) cells")
    if args.release_gap is not None and not 1 <= args.release_gap <= 20:
        sys.exit(f"wetRebound: --release-gap {args.release_gap}: allowed [1, 20] d")
    if args.box_width is not None and not 3 <= args.box_width <= 12:
        sys.exit(f"wetRebound: --box-width {args.box_width}: allowed [3, 12] d")
    if args.release_speed is not None and not 0.5 <= args.release_speed <= 2:
        sys.exit(f"wetRebound: --release-speed {args.release_speed}: allowed [0.5, 2]")
    if args.release_speed == 1:
        args.release_speed = None
    # the default set-up given explicitly is the default set-up (its rows, not new ones)
    if args.release_gap == DEFAULT_RELEASE_GAP:
        args.release_gap = None
    if args.box_width == DEFAULT_BOX_WIDTH:
        args.box_width = None
    if args.quick:
        run_one("St152", 6, True, True)
        return
    for name in (args.case or sorted(CASES, key=lambda n: CASES[n][0])):
        run_one(name, args.cpd, args.force, False, args.max_overlap, args.saturation,
                args.virtual_mass, args.start_shift, args.release_gap, args.box_width,
                args.release_speed, args.bounce)


if __name__ == "__main__":
    main()
