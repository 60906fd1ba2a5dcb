#!/usr/bin/python3
"""Oblique impacts of a steel sphere on a wall in oil, against the rigid-body impact theory
that Joseph & Hunt (2004, JFM 510) found oblique collisions in a liquid to follow, and the
dry impacts of the collision core (validation/dryCollisions, part 6).

    obliqueWetImpact.py run [--angle DEG ...] [--cpd N] [--friction MU] [--force] [--quick]
    obliqueWetImpact.py plot
    obliqueWetImpact.py collect

run:  each impact in run/<name>/ (git-ignored), serial, nice; the body time series is
      copied to results/<name>.h5 and a line appended to results/runs.csv; finished runs
      are skipped unless --force. --quick: one impact at 30 degrees at 6 cells/d
      (run-quick/quick.csv, git-ignored).
plot: results/table.md, metrics.json, psi.png (Psi_out and mu_eff against Psi_in)
      and angles.png (rebound angle against impact angle).
collect: recompute the measured columns of results/runs.csv from results/<name>.h5.

Set-up: the St 152 case of validation/wetRebound (steel, d = 3 mm, oil rho_f 935,
mu 0.01 Pa s), released at gap 2d with the case's normal speed U and a tangential
speed U tan(theta) along x, gravity normal to the wall; the box is 4d + ceil(4 tan theta) d
long in x, 4d wide, 5d high. The normal approach is that of the normal wet rebound, so
the normal restitution e_n is (nearly) the same at every angle.

Measured, with n the wall normal (+z) and the contact point's tangential velocity
v_t = U_x - a omega_y: Psi_in = v_t/|U_z| before the first collision force, Psi_out =
v_t(out)/|U_z,in| at the largest rebound speed once the sphere has left the wall (the
sample of wetRebound's e), e_n = U_z(out)/|U_z,in|, mu_eff = (U_x,in - U_x,out)/((1 + e_n)
|U_z,in|), and the rebound angle of the centre's path, tan(theta_out) = U_x/U_z (out).
Theory (Walton 1993; Joseph & Hunt 2004): Psi_out = Psi_in - 7/2 mu (1 + e_n) when the
contact slides throughout (Psi_in > Psi_c = 7/2 mu (1 + e_n)/(1 + beta0)), Psi_out =
-beta0 Psi_in when it sticks; mu_eff = mu when sliding.
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
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "wetRebound"))
import wetRebound as wr  # noqa: E402  (the normal rebound's case, St 152)

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
DRY_CSV = os.path.join(HERE, "..", "dryCollisions", "results", "obliqueSphereWall.csv")
NORMAL_CSV = os.path.join(HERE, "..", "wetRebound", "results", "runs.csv")

# the St 152 case of Gondret et al. 2002 (validation/wetRebound): St, mu, d
ST, _, _, MU, D = wr.CASES["St152"]
RHO_P = wr.RHO_P
E_DRY = wr.E_DRY
FRICTION = 0.1
ANGLES = (5, 10, 20, 30, 40, 50, 60)

FIELDS = ["name", "angle", "cpd", "friction", "cells", "dt", "steps", "Lx_d", "U_release",
          "Un_in", "Ut_in", "psi_in", "psi_out", "e_n", "mu_eff", "beta", "tan_in", "tan_out",
          "omega_out_a_over_Un", "St_n", "max_overlap_a", "J_contact_n", "contact_ratio",
          "J_fluid_n", "mu_fluid", "mu_drag", "wall_s", "cpu_s", "host", "date",
          "commit"]


def box_length(angle):
    """The box's length along x in diameters: 2d behind the release, the path to the
    rebound (about 4d of fall time at the release's tangential speed) and 2d ahead."""
    return 4 + math.ceil(4 * math.tan(math.radians(angle)) - 1e-9)


def write_case(case, angle, cpd, friction):
    """The normal wet rebound's case (wetRebound.write_case, St 152), lengthened along x,
    with the release moved to 2d from the wall behind it, the tangential speed and the
    friction."""
    info = wr.write_case(case, "St152", cpd)
    u = info["U_release"]
    lxd = box_length(angle)
    lx, ly = lxd * D, 4 * D
    nx, ny = round(lxd * cpd), round(4 * cpd)
    mm = 1e3
    bm = f"{case}/system/blockMeshDict"
    substitute_re(bm, r"^// 4d x 4d x 5d", f"// {lxd}d x 4d x 5d")
    side = f"{ly * mm:g}"
    substitute_re(bm, rf"\(0 0 0\) \({side} 0 0\) \({side} {side} 0\)",
                  f"(0 0 0) ({lx * mm:g} 0 0) ({lx * mm:g} {side} 0)")
    substitute_re(bm, rf"\({side} 0 (\S+)\) \({side} {side} (\S+)\)",
                  rf"({lx * mm:g} 0 \1) ({lx * mm:g} {side} \2)")
    substitute_re(bm, rf"\({ny} {ny} (\d+)\)", rf"({nx} {ny} \1)")
    p = f"{case}/constant/immersedBodiesProperties"
    substitute_re(p, r"centre          \(\S+ ", f"centre          ({2 * D:g} ")
    ut = u * math.tan(math.radians(angle))
    substitute_re(p, r"velocity        \(0 ", f"velocity        ({ut:.6g} ")
    substitute_re(p, r"^    restitution     0.97;$",
                  f"    restitution     0.97;\n    friction        {friction:g};")
    return dict(info, cells=nx * ny * round(5 * cpd), Lx_d=lxd)


def analyse(h5):
    """The impact's in and out states (module docstring)."""
    import h5py
    a = D / 2
    with h5py.File(h5, "r", locking=False) as f:
        t = f["time"][()]
        z = f["centre"][:, 0, 2]
        u = f["velocity"][:, 0, 0]
        w = f["velocity"][:, 0, 2]
        oy = f["angularVelocity"][:, 0, 1]
        fcx = f["collisionForce"][:, 0, 0]
        fc = f["collisionForce"][:, 0, 2]
        fhx = f["hydroForce"][:, 0, 0]
        fhz = f["hydroForce"][:, 0, 2]
    if not all(np.all(np.isfinite(x)) for x in (z, u, w, oy)):
        raise RuntimeError(f"{h5}: non-finite body state")
    touched = np.flatnonzero(fc != 0)
    if len(touched) == 0:
        raise RuntimeError(f"{h5}: the sphere never reached the wall")
    i0 = touched[0]
    if i0 == 0:
        raise RuntimeError(f"{h5}: a collision force in the first row, no approach to measure")
    gap = z - a
    in_contact = np.flatnonzero(gap[i0:] < 0)
    left = i0 + (in_contact[-1] + 1 if len(in_contact) else 0)
    if left >= len(w) or w[left:].max() <= 0:
        raise RuntimeError(f"{h5}: no rebound after the contact")
    j = left + int(np.argmax(w[left:]))
    un = -w[i0 - 1]
    vt_in = u[i0 - 1] - a * oy[i0 - 1]
    vt_out = u[j] - a * oy[j]
    e_n = w[j] / un
    psi_in, psi_out = vt_in / un, vt_out / un
    # impulses over the steps from the first collision force to the out-state (the forces of
    # row k act over the step that ends at row k; fixed step), over m |U_z,in|: the contact's
    # tangential over normal impulse (mu when it slides), and the resolved fluid's tangential
    # and normal impulses
    dt = t[1] - t[0]
    mass = RHO_P * 4 / 3 * math.pi * a ** 3
    steps = slice(i0, j + 1)
    jc_x, jc_z = (np.sum(x[steps]) * dt / (mass * un) for x in (fcx, fc))
    jh_x, jh_z = (np.sum(x[steps]) * dt / (mass * un) for x in (fhx, fhz))
    # the sphere's ordinary drag over the same steps: the tangential fluid force of the 5 steps
    # before the first collision force, held for the window (what the fluid would take with no
    # wall and no impact)
    drag_x = np.mean(fhx[max(i0 - 5, 0):i0]) * (j + 1 - i0) * dt / (mass * un)
    return dict(t=t, Un_in=un, Ut_in=u[i0 - 1], psi_in=psi_in,
                psi_out=psi_out, e_n=e_n, mu_eff=(u[i0 - 1] - u[j]) / ((1 + e_n) * un),
                beta=-psi_out / psi_in if psi_in else float("nan"),
                tan_in=u[i0 - 1] / un, tan_out=u[j] / w[j], omega_out_a_over_Un=a * oy[j] / un,
                St_n=RHO_P * un * D / (9 * MU), max_overlap_a=max(-gap.min(), 0) / a,
                J_contact_n=jc_z, contact_ratio=-jc_x / jc_z, J_fluid_n=jh_z,
                mu_fluid=-jh_x / (1 + e_n), mu_drag=-drag_x / (1 + e_n))


def measured(r):
    keys = ("Un_in", "Ut_in", "psi_in", "psi_out", "e_n", "mu_eff", "beta", "tan_in", "tan_out",
            "omega_out_a_over_Un", "St_n", "max_overlap_a", "J_contact_n", "contact_ratio",
            "J_fluid_n", "mu_fluid", "mu_drag")
    return {k: f"{r[k]:.5g}" for k in keys}


def tag_of(angle, cpd, friction):
    return f"a{angle:g}-c{cpd}-mu{friction:g}"


def run_one(angle, cpd, friction, force, quick):
    out_csv = os.path.join(HERE, "run-quick", "quick.csv") if quick else RUNS_CSV
    tag = tag_of(angle, cpd, friction)
    if not force and not quick and any(r["name"] == tag for r in read_csv(out_csv)):
        print(f"{tag}: in {os.path.relpath(out_csv, HERE)}, skipped")
        return
    case = os.path.join(HERE, "run-quick" if quick else "run", tag)
    info = write_case(case, angle, cpd, friction)
    print(f"{tag}: {info['cells']} cells, dt {info['dt']:.3g} s, end {info['end']:.3g} s",
          flush=True)
    start = time.time()
    rc = run_logged(["nice", "-n", "5", "./Allrun"], case, "log.Allrun")
    wall = time.time() - start
    if rc != 0 or not os.path.exists(os.path.join(case, "log.immersedSpheroidFoam")):
        sys.exit(f"obliqueWetImpact: {tag} failed (see {case}/log.*)")
    cpu = cpu_seconds(case, "log.immersedSpheroidFoam")
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    r = analyse(h5)
    row = dict(name=tag, angle=f"{angle:g}", cpd=cpd, friction=f"{friction:g}",
               cells=info["cells"],
               dt=f"{info['dt']:.6g}", steps=len(r["t"]) - 1, Lx_d=info["Lx_d"],
               U_release=f"{info['U_release']:.5g}", wall_s=round(wall),
               cpu_s=round(cpu) if math.isfinite(cpu) else "", **provenance(), **measured(r))
    print(f"  Psi_in {r['psi_in']:.3f}, Psi_out {r['psi_out']:.3f}, e_n {r['e_n']:.3f}, "
          f"mu_eff {r['mu_eff']:.4f}, wall {wall:.0f} s", flush=True)
    if not quick:
        shutil.copy(h5, os.path.join(RESULTS, f"{tag}.h5"))
    merge_row(out_csv, row, "name", FIELDS, ignore_extra=True)


# ---------------------------------------------------------------------------
# theory and figures

def psi_theory(psi_in, mu, e_n, beta0):
    """Rigid-body impact of a sphere on a plane with Coulomb friction (Walton 1993)."""
    psi_c = 3.5 * mu * (1 + e_n) / (1 + beta0)
    return np.where(psi_in > psi_c, psi_in - 3.5 * mu * (1 + e_n), -beta0 * psi_in)


def mu_eff_theory(psi_in, mu, e_n, beta0):
    """mu_eff = (2/7)(Psi_in - Psi_out)/(1 + e_n) of the theory."""
    return (psi_in - psi_theory(psi_in, mu, e_n, beta0)) / (3.5 * (1 + e_n))


def f(r, k):
    return float(r[k])


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_csv(RUNS_CSV)
    if not rows:
        sys.exit(f"obliqueWetImpact: no runs in {RUNS_CSV}")
    dry = [r for r in read_csv(DRY_CSV) if f(r, "e") == E_DRY]
    groups = sorted({(int(r["cpd"]), f(r, "friction")) for r in rows})
    metrics = {}
    lines = ["# Oblique wet impacts: results\n",
             "Generated by `obliqueWetImpact.py plot` from `runs.csv`. Steel sphere, d 3 mm, "
             "oil rho_f 935, mu 0.01 Pa s, normal release speed of the St 152 case; e_dry 0.97. "
             "Psi = v_t/|U_z,in| (the contact point's tangential speed over the normal impact "
             "speed); theory: Psi_out = Psi_in - 7/2 mu (1 + e_n) (sliding), -e_dry Psi_in "
             "(sticking), with each run's e_n. Impulses over the steps from the first collision "
             "force to the out-state, over m |U_z,in|: contact J_t/J_n is the contact's "
             "tangential over normal impulse (mu when the contact slides), fluid J_n the resolved "
             "fluid's normal impulse, fluid mu the resolved fluid's tangential impulse over "
             "(1 + e_n) m |U_z,in| (its share of mu_eff), drag mu the same for the sphere's "
             "tangential drag of the 5 steps before the impact held over those steps.\n"]
    for cpd, mu in groups:
        rs = sorted([r for r in rows if int(r["cpd"]) == cpd and f(r, "friction") == mu],
                    key=lambda r: f(r, "angle"))
        lines.append(f"## {cpd} cells/d, friction {mu:g}\n")
        lines.append("| angle (deg) | St_n | Psi_in | Psi_out | theory | Psi_out - theory | e_n | "
                     "mu_eff | mu_eff theory | contact J_t/J_n | contact J_n | fluid J_n | "
                     "fluid mu | drag mu | tan theta_in | tan theta_out | omega a/U_n | "
                     "max overlap/a | cells | wall (s) |")
        lines.append("|" + "---|" * 20)
        worst = 0.0
        slide_err, contact_err, stick_err = [], [], []
        for r in rs:
            th = float(psi_theory(f(r, "psi_in"), mu, f(r, "e_n"), E_DRY))
            mth = float(mu_eff_theory(f(r, "psi_in"), mu, f(r, "e_n"), E_DRY))
            err = f(r, "psi_out") - th
            worst = max(worst, abs(err))
            psi_c = 3.5 * mu * (1 + f(r, "e_n")) / (1 + E_DRY)
            if mu > 0 and f(r, "psi_in") >= 2 * psi_c:
                slide_err.append(f(r, "mu_eff") / mu - 1)
                contact_err.append(f(r, "contact_ratio") / mu - 1)
            if f(r, "psi_in") < 0.75 * psi_c:
                stick_err.append(f(r, "beta") - E_DRY)
            lines.append(f"| {r['angle']} | {f(r, 'St_n'):.1f} | {f(r, 'psi_in'):.3f} | "
                         f"{f(r, 'psi_out'):.3f} | {th:.3f} | {err:+.3f} | {f(r, 'e_n'):.3f} | "
                         f"{f(r, 'mu_eff'):.4f} | {mth:.4f} | {f(r, 'contact_ratio'):.4f} | "
                         f"{f(r, 'J_contact_n'):.3f} | {f(r, 'J_fluid_n'):.3f} | "
                         f"{f(r, 'mu_fluid'):.4f} | {f(r, 'mu_drag'):.4f} | "
                         f"{f(r, 'tan_in'):.3f} | "
                         f"{f(r, 'tan_out'):.3f} | {f(r, 'omega_out_a_over_Un'):.3f} | "
                         f"{f(r, 'max_overlap_a'):.3f} | {r['cells']} | {r['wall_s']} |")
        lines.append("")
        key = f"{cpd}_mu{mu:g}"
        metrics[f"max_abs_psi_out_error_{key}"] = round(worst, 4)
        metrics[f"e_n_min_{key}"] = round(min(f(r, "e_n") for r in rs), 4)
        metrics[f"e_n_max_{key}"] = round(max(f(r, "e_n") for r in rs), 4)
        metrics[f"runs_{key}"] = len(rs)
        metrics[f"max_fluid_mu_{key}"] = round(max(f(r, "mu_fluid") for r in rs), 4)
        if stick_err:
            metrics[f"sticking_beta_max_abs_error_{key}"] = round(max(abs(x) for x in stick_err), 4)
            metrics[f"sticking_runs_{key}"] = len(stick_err)
        if slide_err:
            metrics[f"sliding_mu_eff_max_abs_rel_error_{key}"] = round(
                max(abs(x) for x in slide_err), 4)
            metrics[f"sliding_contact_ratio_max_abs_rel_error_{key}"] = round(
                max(abs(x) for x in contact_err), 4)
            metrics[f"sliding_runs_{key}"] = len(slide_err)
    normal = [r for r in read_csv(NORMAL_CSV) if r["name"] in ("St152-c12", "St152-c8")]
    if normal:
        lines.append("Normal impact of the same sphere (validation/wetRebound, e at the same "
                     "sample): " + ", ".join(f"{r['name']}: e {f(r, 'e'):.3f}" for r in normal)
                     + "\n")
        for r in normal:
            metrics[f"normal_e_{r['name'].split('-c')[1]}"] = round(f(r, "e"), 4)

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    markers = dict(zip(groups, ("o", "s", "^", "v", "D")))
    psi = np.linspace(0, 2.0, 400)
    for cpd, mu in groups:
        rs = [r for r in rows if int(r["cpd"]) == cpd and f(r, "friction") == mu]
        x = np.array([f(r, "psi_in") for r in rs])
        line = axes[0].plot(x, [f(r, "psi_out") for r in rs], markers[(cpd, mu)], ms=6,
                            mfc="none", label=f"in oil, {cpd} cells/d, mu {mu:g}")[0]
        e_n = np.mean([f(r, "e_n") for r in rs])
        axes[0].plot(psi, psi_theory(psi, mu, e_n, E_DRY), "-", lw=1, color=line.get_color(),
                     label=f"theory, mu {mu:g}, e_n {e_n:.2f} (mean of the runs)")
        if mu > 0:
            axes[1].plot(x, [f(r, "mu_eff") / mu for r in rs], markers[(cpd, mu)], ms=6,
                         mfc="none", color=line.get_color(), label=f"in oil, {cpd} cells/d")
            axes[1].plot(x, [(f(r, "mu_eff") - f(r, "mu_fluid")) / mu for r in rs],
                         markers[(cpd, mu)], ms=4, color=line.get_color(),
                         label=f"{cpd} cells/d, less the resolved fluid's impulse")
            axes[1].plot(psi, mu_eff_theory(psi, mu, e_n, E_DRY) / mu, "-", lw=1,
                         color=line.get_color())
    for mu in sorted({f(r, "mu") for r in dry}):
        if mu == FRICTION:
            ds = sorted([r for r in dry if f(r, "mu") == mu], key=lambda r: f(r, "psiIn"))
            ds = [r for r in ds if f(r, "psiIn") <= 2.0]
            axes[0].plot([f(r, "psiIn") for r in ds], [f(r, "psiOut") for r in ds], "k.",
                         ms=5, label=f"dry, collision core, mu {mu:g}, e 0.97")
            axes[1].plot([f(r, "psiIn") for r in ds], [f(r, "muEffective") / mu for r in ds],
                         "k.", ms=5, label="dry, collision core")
    axes[0].axhline(0, color="gray", lw=0.5)
    axes[0].set_xlabel("Psi_in = v_t / |U_n| before the impact")
    axes[0].set_ylabel("Psi_out = v_t after / |U_n| before")
    st_n = [f(r, "St_n") for r in rows]
    axes[0].set_title(f"Oblique impacts of a steel sphere in oil (St_n {min(st_n):.0f}-"
                      f"{max(st_n):.0f})")
    axes[0].legend(fontsize=7)
    axes[1].set_xlabel("Psi_in")
    axes[1].set_ylabel("mu_eff / mu")
    axes[1].set_title("Effective friction (lines: rigid-body theory)")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "psi.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.8))
    for cpd, mu in groups:
        rs = [r for r in rows if int(r["cpd"]) == cpd and f(r, "friction") == mu]
        ax.plot([f(r, "tan_in") for r in rs], [f(r, "tan_out") for r in rs], markers[(cpd, mu)],
                ms=6, mfc="none", label=f"in oil, {cpd} cells/d, mu {mu:g}")
    # the theory's rebound angle for a sphere without spin before the impact (Psi_in = tan_in):
    # U_x,out = U_x,in - mu_eff (1 + e_n) |U_z,in|, U_z,out = e_n |U_z,in|
    x = np.linspace(0, 2, 200)
    for cpd, mu in groups:
        if cpd != max(c for c, _ in groups):
            continue
        e_n = np.mean([f(r, "e_n") for r in rows
                       if int(r["cpd"]) == cpd and f(r, "friction") == mu])
        ax.plot(x, (x - mu_eff_theory(x, mu, e_n, E_DRY) * (1 + e_n)) / e_n, "-", lw=1,
                label=f"theory, mu {mu:g}, e_n {e_n:.2f}")
    ax.set_xlabel("tan(theta_in) = U_x/|U_z| before")
    ax.set_ylabel("tan(theta_out) = U_x/U_z after")
    ax.set_title("Rebound angle of the centre's path")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "angles.png"), dpi=110)
    plt.close(fig)

    with open(os.path.join(RESULTS, "table.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    with open(os.path.join(RESULTS, "metrics.json"), "w") as out:
        json.dump(metrics, out, indent=1, sort_keys=True)
        out.write("\n")
    print("wrote results/table.md, metrics.json, psi.png, angles.png")


def do_collect():
    # under the file's lock: a run beside this one may add its row meanwhile
    with locked(RUNS_CSV):
        rows = read_csv(RUNS_CSV)
        for r in rows:
            h5 = os.path.join(RESULTS, f"{r['name']}.h5")
            if os.path.exists(h5):
                r.update(measured(analyse(h5)))
        write_csv(RUNS_CSV, rows, FIELDS, ignore_extra=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--angle", type=float, action="append", default=[])
    r.add_argument("--cpd", type=int, default=12)
    r.add_argument("--friction", type=float, default=FRICTION)
    r.add_argument("--force", action="store_true")
    r.add_argument("--quick", action="store_true")
    sub.add_parser("plot")
    sub.add_parser("collect")
    args = ap.parse_args()
    if args.cmd == "plot":
        do_plot()
    elif args.cmd == "collect":
        do_collect()
    elif args.quick:
        run_one(30, 6, args.friction, True, True)
    else:
        for angle in args.angle or ANGLES:
            run_one(angle, args.cpd, args.friction, args.force, False)


if __name__ == "__main__":
    main()
