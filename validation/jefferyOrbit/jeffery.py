#!/usr/bin/python3
"""Jeffery orbit: run one case and analyse the body's time series
(used by jefferyOrbit.py and tests/foam/jefferyOrbitQuick).

phi: the angle of the symmetry axis p = R(q) e_x from the gradient axis y,
towards the flow axis x, unwrapped (p is a line: phi and phi + pi are the
same attitude); Jeffery (1922), axis in the flow-gradient plane:
    dphi/dt = gamma (r^2 cos^2 phi + sin^2 phi)/(r^2 + 1),
    tan phi = r tan(gamma r t/(r^2 + 1)),  T = (2 pi/gamma)(r + 1/r).
"""
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import caseWriter

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import mesh_cells, run_logged  # noqa: E402


def jeffery_phi(t, r, gamma=1.0, t0=0.0, phi0=0.0):
    """Unwrapped Jeffery angle at times t for phi(t0) = phi0."""
    k = gamma * r / (r * r + 1)
    theta0 = math.atan2(math.tan(phi0), r) if abs(math.cos(phi0)) > 1e-15 else 0.5 * math.pi
    # keep theta in the branch of phi0
    theta0 += math.pi * round((phi0 - theta0) / math.pi)
    theta = theta0 + k * (np.asarray(t) - t0)
    n = np.round(theta / math.pi)
    return np.arctan(r * np.tan(theta - n * math.pi)) + n * math.pi


def jeffery_rate(phi, r, gamma=1.0):
    return gamma * (r * r * np.cos(phi) ** 2 + np.sin(phi) ** 2) / (r * r + 1)


def jeffery_period(r, gamma=1.0):
    return 2 * math.pi / gamma * (r + 1 / r)


def read_series(case):
    import h5py
    with h5py.File(os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5"), "r",
                   locking=False) as f:
        n = min(f[k].shape[0] for k in ("time", "orientation", "angularVelocity", "hydroTorque"))
        return (f["time"][:n], f["orientation"][:n, 0, :], f["angularVelocity"][:n, 0, :],
                f["hydroTorque"][:n, 0, :])


def axis_of(q):
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=-1)


def phi_of(q):
    """Unwrapped angle of the axis from y towards x, and the out-of-plane
    component |p_z|."""
    p = axis_of(q)
    phi = np.arctan2(p[:, 0], p[:, 1])
    # a line: fold into (-pi/2, pi/2] and unwrap with period pi
    phi = np.unwrap(2 * phi) / 2
    return phi, np.abs(p[:, 2])


def crossings(t, phi, level):
    """Times at which phi crosses level upwards (linear interpolation)."""
    out = []
    for i in range(1, len(t)):
        if phi[i - 1] < level <= phi[i]:
            s = (level - phi[i - 1]) / (phi[i] - phi[i - 1])
            out.append(t[i - 1] + s * (t[i] - t[i - 1]))
    return out


def fit_jeffery(t, phi, r, t_min=1.0):
    """Least-squares fit of Jeffery's curve tan(phi) = r' tan(theta),
    theta = 2 pi t/T + theta0, to phi(t) for t > t_min: for each r' on a grid
    theta(phi) is linear in t; returns dict(r_eff, T_fit, theta0, rms) or None."""
    m = t > t_min
    if np.sum(m) < 10 or phi[m][-1] - phi[m][0] < 0.5:
        return None
    best = None
    for r_eff in np.linspace(max(1.05, 0.7 * r), 1.5 * r, 241):
        theta = np.arctan2(np.sin(phi[m]), r_eff * np.cos(phi[m]))
        theta = np.unwrap(2 * theta) / 2
        theta += math.pi * np.round((phi[m] - theta) / math.pi)
        A = np.vstack([t[m], np.ones(np.sum(m))]).T
        coef, *_ = np.linalg.lstsq(A, theta, rcond=None)
        err = float(np.sum((A @ coef - theta) ** 2))
        if best is None or err < best[0]:
            best = (err, r_eff, coef[0], coef[1])
    err, r_eff, k, c = best
    return dict(r_eff=r_eff, T_fit=2 * math.pi / k, theta0=c, rms=math.sqrt(err / np.sum(m)))


def fitted_phi(t, fit):
    """phi(t) of a fit_jeffery result (unwrapped)."""
    theta = 2 * math.pi * np.asarray(t) / fit["T_fit"] + fit["theta0"]
    n = np.round(theta / math.pi)
    return np.arctan(fit["r_eff"] * np.tan(theta - n * math.pi)) + n * math.pi


def analyse(case, r, gamma=1.0):
    """Period from the crossing times of phi = pi/2 and pi and a least-squares
    fit; returns a dict."""
    t, q, omega, torque = read_series(case)
    phi, pz = phi_of(q)
    res = dict(t=t, phi=phi, omega=omega, pz=pz, T_jeffery=jeffery_period(r, gamma))
    fit = fit_jeffery(t, phi, r, min(1.0, 0.05 * t[-1]))
    if fit:
        res["fit"] = fit
    return res


def run(case, verbose=True, nice=True, **kw):
    """Write, mesh, initialise (u = gamma y) and run one case; returns
    (info, wall seconds, cells)."""
    if os.path.exists(case):
        subprocess.run(["rm", "-rf", case], check=True)
    info = caseWriter.write_case(case, **kw)
    gamma = kw.get("gamma", 1.0)
    caseWriter.write(os.path.join(case, "system", "setExprFieldsDict"), "dictionary", "system",
                     "setExprFieldsDict", f"""\
expressions
(
    U
    {{
        field       U;
        dimensions  [0 1 -1 0 0 0 0];
        expression  #{{ vector({gamma:.12g}*pos().y(), 0, 0) #}};
    }}
);
""")
    t0 = time.time()
    for app in (["blockMesh"], ["setExprFields"]):
        with open(os.path.join(case, "log." + app[0]), "w") as out:
            subprocess.run(app, cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)
    cells = mesh_cells(case)
    if verbose:
        print(f"  {os.path.basename(case)}: {cells} cells, h = {info['h']:.4g}, "
              f"nu = {info['nu']:.4g}, viscous number nu dt/h^2 = {info['lam']:.3g}", flush=True)
    cmd = (["nice", "-n", "10"] if nice else []) + ["immersedSpheroidFoam"]
    for attempt in range(10):
        rc = run_logged(cmd, case, "log.solver")
        with open(os.path.join(case, "log.solver")) as fh:
            text = fh.read(4000)
        # the project's libraries being rebuilt at that moment (a shared
        # checkout): wait and start again
        if rc != 0 and "error while loading shared libraries" in text:
            print("  (a library is being rebuilt: retrying in 60 s)", flush=True)
            time.sleep(60)
            continue
        break
    wall = time.time() - t0
    if rc != 0:
        raise RuntimeError(f"immersedSpheroidFoam failed in {case} (see log.solver)")
    return info, wall, cells
