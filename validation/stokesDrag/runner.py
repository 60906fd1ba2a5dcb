#!/usr/bin/python3
"""Run one fixed-spheroid Stokes-drag case to its steady state (used by
stokesDrag.py and tests/foam/stokesDragQuick).

The run is a sequence of solver runs (segments) of fixed simulated length
s = 0.4 tau_box, tau_box = L^2/(4 pi^2 nu) (the decay time of the box's
slowest mode); every decision is taken between two segments, from the
body's time series (postProcessing/immersedBodies/bodies.h5) at fixed
simulated times, so two identical runs give identical figures whatever the
machine's load:
  stage 1: steps dt1 (larger) until the drag has converged to tol1: the flow
           of the whole box is set up;
  stage 2: steps dt = lambda h^2/nu (lambda, the viscous number of a cell, is
           the same at every resolution) until the drag has converged to tol.
Convergence: the drag sampled at the times t - 2s, t - s, t decays
geometrically; Aitken's extrapolation F3 + d2 q/(1 - q) (d1, d2 the
differences, q = d2/d1) estimates the limit and the stage ends when that
correction is below tol x |F3|. The extrapolated value is the drag reported.
Each segment starts from the last written time (startFrom latestTime), and
the runner's own state is in CASE/runner.json: an interrupted run resumes
from its last segment. np > 1 runs each segment decomposed (mpirun).
"""
import json
import math
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import caseWriter

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import mesh_cells, run_logged  # noqa: E402


def read_force(case):
    """time[N], hydroForce[N, 3] of the body (bodies.h5), or None."""
    import h5py
    path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if not os.path.exists(path):
        return None
    try:
        with h5py.File(path, "r", locking=False) as f:
            n = min(f[k].shape[0] for k in ("time", "hydroForce"))
            return f["time"][:n], f["hydroForce"][:n, 0, :]
    except (OSError, KeyError):
        return None          # met an append half-way: try again later


def set_control(case, **entries):
    """Change entries of system/controlDict (atomically: the solver re-reads it)."""
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    for key, value in entries.items():
        text, n = re.subn(rf"^{key}\s+[^;]*;", f"{key} {value};", text, flags=re.M)
        if n != 1:
            raise RuntimeError(f"{path}: no entry {key}")
    with open(path + ".new", "w") as f:
        f.write(text)
    os.replace(path + ".new", path)


def aitken(times, F, t0, t, s):
    """Aitken's extrapolation of F from its values at t - 2s, t - s, t (all >= t0):
    (limit, relative correction) or (None, None) if not yet possible."""
    if t - 2 * s < t0 - 1e-12:
        return None, None
    f1, f2, f3 = (np.interp(x, times, F) for x in (t - 2 * s, t - s, t))
    d1, d2 = f2 - f1, f3 - f2
    if abs(d2) <= 1e-12 * abs(f3):
        return f3, 0.0
    if d1 == 0:
        return None, None
    q = d2 / d1
    if not 0 < q < 0.9:           # not (yet) a geometric decay
        return None, None
    corr = d2 * q / (1 - q)
    return f3 + corr, corr / abs(f3)


def _solver(case, np_, log_name):
    """Run pimpleFoam (serial or on np_ ranks) to its endTime; raises on failure."""
    cmd = ["nice", "-n", "10", "pimpleFoam"]
    if np_ > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(np_)] + cmd + ["-parallel"]
    rc = run_logged(cmd, case, log_name)
    if rc != 0:
        raise RuntimeError(f"pimpleFoam failed in {case} (see {log_name})")


def _restart_precision(case, current):
    """The timePrecision under which the latest time directory's name is the
    one OpenFOAM computes from its value at a restart: the current one if it
    is, else the one that reproduces it (OpenFOAM widens the names of times
    that accumulated round-off, beyond what it searches for at a start)."""
    folder = os.path.join(case, "processor0") if os.path.isdir(
        os.path.join(case, "processor0")) else case
    names = []
    for name in os.listdir(folder):
        try:
            names.append((float(name), name))
        except ValueError:
            pass
    if not names:
        return current
    value, name = max(names)
    for p in [current] + list(range(17, 0, -1)):
        if f"{value:.{p}g}" == name:
            return p
    return current


def _load_state(case):
    path = os.path.join(case, "runner.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def _save_state(case, state):
    path = os.path.join(case, "runner.json")
    with open(path + ".new", "w") as f:
        json.dump(state, f, indent=1)
    os.replace(path + ".new", path)


def run_case(case, ar, flow, box, cpd, lam=1.0, u=0.02, dt1=0.01, tol1=1e-3, tol=2e-4,
             t_max=None, stage1_only=False, verbose=True, np_=1, resume=True, **kw):
    """Write and run one case (or resume it from CASE/runner.json); returns a
    dict of results. Drag: the steady hydrodynamic force of the body along x
    (flow along the symmetry axis) and/or y (across it), K = F/(6 pi mu r_eq u)
    with u the superficial velocity of that component."""
    h = 1.0 / cpd
    dt = lam * h * h                  # nu = 1
    tau = box * box / (4 * math.pi ** 2)
    s = 0.4 * tau                     # the segment length and the sampling interval
    if t_max is None:
        t_max = 60 * tau
    comps = [i for i, d in enumerate("xy") if d in flow]
    norm = 6 * math.pi * 1.0 * 0.5 * u          # 6 pi mu r_eq u
    settings = dict(ar=ar, flow=flow, box=box, cpd=cpd, lam=lam, u=u, dt1=dt1, tol1=tol1,
                    tol=tol, np=np_, kw={k: v for k, v in kw.items()})
    state = _load_state(case) if resume else None
    if state is not None and state.get("settings") != settings:
        state = None                  # another set-up: start again
    t_start = time.time()
    if state is None:
        if os.path.exists(case):
            subprocess.run(["rm", "-rf", case], check=True)
        caseWriter.write_case(case, ar, flow, box, cpd, dt1, s, u=u, **kw)
        set_control(case, writeControl="runTime", writeInterval=f"{s:.12g}")
        with open(os.path.join(case, "log.blockMesh"), "w") as out:
            subprocess.run(["blockMesh"], cwd=case, stdout=out, stderr=subprocess.STDOUT,
                           check=True)
        if np_ > 1:
            with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
                # simple: Debian's OpenFOAM has no scotch
                f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                        " object decomposeParDict; }\n"
                        f"numberOfSubdomains {np_};\nmethod simple;\n"
                        f"simpleCoeffs {{ n ({np_} 1 1); delta 0.001; }}\n")
            with open(os.path.join(case, "log.decomposePar"), "w") as out:
                subprocess.run(["decomposePar"], cwd=case, stdout=out,
                               stderr=subprocess.STDOUT, check=True)
        state = dict(settings=settings, stage=1, t_stage=0.0, t=0.0, segments=0, res={},
                     wall=0.0)
        _save_state(case, state)
    cells = mesh_cells(case)
    if verbose:
        print(f"  {os.path.basename(case)}: {cells} cells, h = {h:.4g}, dt1 = {dt1:.4g}, "
              f"dt = {dt:.4g} (lambda {lam}), tau_box = {tau:.3g}, segments of {s:.3g}"
              + (f", resumed at t = {state['t']:.5g}" if state["segments"] else ""), flush=True)

    while state["stage"] < 3:
        stage = state["stage"]
        step = dt1 if stage == 1 else dt
        n = max(1, int(round(s / step)))
        t_next = state["t"] + n * step
        if t_next > t_max + 1e-9:
            raise RuntimeError(f"{case}: not converged by t = {t_max}")
        state["precision"] = _restart_precision(case, state.get("precision", 17))
        set_control(case, deltaT=f"{step:.12g}", endTime=f"{t_next:.12g}",
                    writeInterval=f"{n * step:.12g}", timePrecision=str(state["precision"]))
        _solver(case, np_, "log.solver")
        with open(os.path.join(case, "log.solver")) as f:
            cpu = re.findall(r"^ExecutionTime = (\S+) s", f.read(), flags=re.M)
        state["cpu"] = state.get("cpu", 0.0) + (float(cpu[-1]) if cpu else 0.0)
        state["segments"] += 1
        state["t"] = t_next
        times, Fall = read_force(case)
        if not np.all(np.isfinite(Fall[-1])) or np.max(np.abs(Fall[-1])) > 1e3 * norm:
            raise RuntimeError(f"{case}: the drag diverged (F = {Fall[-1]} at t = {times[-1]:.4g})")
        t = times[-1]
        est = [aitken(times, Fall[:, c], state["t_stage"], t, s) for c in comps]
        ok = all(e[0] is not None and abs(e[1]) < (tol1 if stage == 1 else tol) for e in est)
        if verbose:
            print(f"    stage {stage}{' converged' if ok else ''}: t = {t:.5g}, K = "
                  + ", ".join(f"{Fall[-1, c] / norm:.6g}" for c in comps)
                  + " (Aitken correction "
                  + ", ".join(f"{e[1] if e[1] is not None else float('nan'):.1e}" for e in est)
                  + f"), wall {state['wall'] + time.time() - t_start:.0f} s", flush=True)
        if ok:
            state["res"][str(stage)] = dict(
                t=t, F_last=[float(Fall[-1, c]) for c in comps],
                F=[float(e[0]) for e in est], correction=[float(e[1]) for e in est],
                steps=int(np.sum(times > state["t_stage"] + 1e-12)))
            if stage == 1 and not stage1_only:
                state["stage"], state["t_stage"] = 2, t
            else:
                state["stage"] = 3
        state["wall"] += time.time() - t_start
        t_start = time.time()
        _save_state(case, state)

    final = state["res"]["1" if stage1_only else "2"]
    grads = []
    log = os.path.join(case, "log.solver")
    with open(log) as f:
        grads = [float(g) for g in re.findall(r"pressure gradient = (\S+)", f.read())]
    times, Fall = read_force(case)
    out = dict(cells=cells, h=h, dt=dt, lam=lam, steps1=state["res"]["1"]["steps"],
               steps2=0 if stage1_only else final["steps"], wall=state["wall"],
               cpu=state.get("cpu", 0.0), segments=state["segments"], t=final["t"], F_other=float(abs(Fall[-1, 2])))
    for k, c in enumerate(comps):
        d = "xy"[c]
        out[f"F{d}"] = final["F"][k]
        out[f"F{d}_last"] = final["F_last"][k]
        out[f"K{d}"] = final["F"][k] / norm
        # the mean-flow check: pressure gradient x box volume = force on the body
        g = grads[-len(comps) + k] if len(grads) >= len(comps) else float("nan")
        out[f"F{d}_gradP"] = g * box ** 3
    return out
