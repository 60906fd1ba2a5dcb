#!/usr/bin/python3
"""Run one fixed-spheroid Stokes-drag case to its steady state (used by
stokesDrag.py and tests/foam/stokesDragQuick).

One pimpleFoam process (Euler steps, serial, nice) is watched through the
body's time series (postProcessing/immersedBodies/bodies.h5) and steered
through system/controlDict (runTimeModifiable yes):
  stage 1: steps dt1 (larger) until the drag has converged to tol1: the flow
           of the whole box is set up (its slowest mode decays in
           ~ L^2/(4 pi^2 nu));
  stage 2: deltaT is changed to the measuring step dt = lambda h^2/nu
           (lambda, the viscous number of a cell, is the same at every
           resolution) and the run continues until the drag has converged
           to tol; then stopAt writeNow.
Convergence: the drag sampled at the times t - 2s, t - s, t (s = 0.4 tau_box,
tau_box = L^2/(4 pi^2 nu)) decays geometrically; Aitken's extrapolation
F3 + d2 q/(1 - q) (d1, d2 the differences, q = d2/d1) estimates the limit and
the stage ends when that correction is below tol x |F3|. The extrapolated
value is the drag reported.
The steady drag depends on lambda (see README.md): the cut-cell penalty
coefficient alpha/(eta + (1 - alpha) dt/c) depends on dt.
"""
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
from validationTools import mesh_cells  # noqa: E402


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


def run_case(case, ar, flow, box, cpd, lam=1.0, u=0.02, dt1=0.01, tol1=1e-3, tol=2e-4,
             t_max=None, stage1_only=False, verbose=True, poll=2.0, **kw):
    """Write and run one case; returns a dict of results. Drag: the steady
    hydrodynamic force of the body along x (flow along the symmetry axis)
    and/or y (across it), K = F/(6 pi mu r_eq u) with u the superficial
    velocity of that component."""
    if os.path.exists(case):
        subprocess.run(["rm", "-rf", case], check=True)
    h = 1.0 / cpd
    dt = lam * h * h                  # nu = 1
    tau = box * box / (4 * math.pi ** 2)
    s = 0.4 * tau                     # the sampling interval of the convergence test
    if t_max is None:
        t_max = 60 * tau
    caseWriter.write_case(case, ar, flow, box, cpd, dt1, t_max, u=u, **kw)
    t_start = time.time()
    with open(os.path.join(case, "log.blockMesh"), "w") as out:
        subprocess.run(["blockMesh"], cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)
    cells = mesh_cells(case)
    comps = [i for i, d in enumerate("xy") if d in flow]
    if verbose:
        print(f"  {os.path.basename(case)}: {cells} cells, h = {h:.4g}, dt1 = {dt1:.4g}, "
              f"dt = {dt:.4g} (lambda {lam}), tau_box = {tau:.3g}", flush=True)

    for attempt in range(10):
        log = open(os.path.join(case, "log.solver"), "w")
        proc = subprocess.Popen(["nice", "-n", "10", "pimpleFoam"], cwd=case, stdout=log,
                                stderr=subprocess.STDOUT)
        time.sleep(1.0)
        with open(os.path.join(case, "log.solver")) as fh:
            text = fh.read(4000)
        # the project's libraries being rebuilt at that moment (a shared
        # checkout): wait and start again
        if proc.poll() is not None and "error while loading shared libraries" in text:
            log.close()
            print("  (a library is being rebuilt: retrying in 60 s)", flush=True)
            time.sleep(60)
            continue
        break
    stage, t_stage, res = 1, 0.0, {}
    last_report = 0.0
    t_stage2_wall = None
    norm = 6 * math.pi * 1.0 * 0.5 * u          # 6 pi mu r_eq u
    try:
        while True:
            try:
                rc = proc.wait(timeout=poll)
            except subprocess.TimeoutExpired:
                rc = None
            data = read_force(case)
            if rc is not None:
                if rc != 0:
                    raise RuntimeError(f"pimpleFoam failed in {case} (see log.solver)")
                break
            if data is None or len(data[0]) < 3 or stage == 3:
                continue
            times, Fall = data
            t = times[-1]
            if not np.all(np.isfinite(Fall[-1])) or np.max(np.abs(Fall[-1])) > 1e3 * norm:
                proc.terminate()
                raise RuntimeError(f"{case}: the drag diverged (F = {Fall[-1]} at t = {t:.4g})")
            est = [aitken(times, Fall[:, c], t_stage, t, s) for c in comps]
            ok = all(e[0] is not None and abs(e[1]) < (tol1 if stage == 1 else tol)
                     for e in est)
            if verbose and (time.time() - last_report > 60 or ok):
                last_report = time.time()
                print(f"    stage {stage}{' converged' if ok else ''}: t = {t:.5g}, K = "
                      + ", ".join(f"{Fall[-1, c] / norm:.6g}" for c in comps)
                      + " (Aitken correction "
                      + ", ".join(f"{e[1] if e[1] is not None else float('nan'):.1e}" for e in est)
                      + f"), wall {time.time() - t_start:.0f} s", flush=True)
            if not ok:
                continue
            res[stage] = dict(t=t, F_last=[Fall[-1, c] for c in comps], F=[e[0] for e in est],
                              correction=[e[1] for e in est],
                              steps=int(np.sum(times > t_stage + 1e-12)))
            if stage == 1 and not stage1_only:
                set_control(case, deltaT=f"{dt:.12g}")
                stage, t_stage = 2, t
                t_stage2_wall = time.time()
            else:
                set_control(case, stopAt="writeNow")
                stage = 3
    finally:
        if proc.poll() is None:
            proc.terminate()
            proc.wait()
        log.close()
    wall = time.time() - t_start
    final = res.get(1 if stage1_only else 2)
    if final is None:
        raise RuntimeError(f"{case}: not converged by t = {t_max}")
    with open(os.path.join(case, "log.solver")) as f:
        grads = [float(g) for g in re.findall(r"pressure gradient = (\S+)", f.read())]
    times, Fall = read_force(case)
    out = dict(cells=cells, h=h, dt=dt, lam=lam, steps1=res[1]["steps"],
               steps2=0 if stage1_only else final["steps"], wall=wall,
               wall2=(time.time() - t_stage2_wall) if t_stage2_wall else 0.0, t=final["t"],
               F_other=float(abs(Fall[-1, 2])))
    for k, c in enumerate(comps):
        d = "xy"[c]
        out[f"F{d}"] = final["F"][k]
        out[f"F{d}_last"] = final["F_last"][k]
        out[f"K{d}"] = final["F"][k] / norm
        # the mean-flow check: pressure gradient x box volume = force on the body
        g = grads[-len(comps) + k] if len(grads) >= len(comps) else float("nan")
        out[f"F{d}_gradP"] = g * box ** 3
    return out
