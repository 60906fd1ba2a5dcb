#!/usr/bin/python3
"""Table, metrics and figures of validation/hinderedSettling from DIR/results/runs.csv (the
suspensions) and DIR/results/reference.csv (the single sphere); called by
`hinderedSettling.py plot` (Debian's python3 with numpy and matplotlib):

  results/table.md       the single sphere's terminal velocity per mesh, every suspension
                         with its hindrance factor against Richardson-Zaki, the effect of the
                         packing, the box and the resolution
  results/metrics.json   flat: max_abs_hindrance_error_pct (the largest |error| of the three
                         solid fractions of the core runs, 8 cells/D in a 6 D box, null until
                         all three exist), hindrance_error_pct_<run> and hindrance_<run> per run,
                         V_t and Re_t per mesh
                         max_abs_error_vs_yin_koch_pct (the same against the resolved
                         simulations of Yin & Koch 2007, the larger of the two readings of
                         their Reynolds number), hindrance_error_vs_yin_koch_pct_<run>
  results/hindrance.png  the hindrance factor against the solid fraction with Richardson-Zaki
                         and Yin & Koch
  results/settling.png   the mean settling speed of every run against time

Hindrance factor: the mean settling speed over the bodies and over [AVERAGE_FROM, end], in
the frame of zero volume flux, divided by the single sphere's terminal velocity V_t on the
same mesh. Richardson-Zaki: (1 - phi)^n with Rowe's n at Re_t = V_t D/nu of that mesh, phi
the run's actual solid fraction. Error = measured/predicted - 1.

Yin & Koch (2007): k (1 - phi)^n with their fitted k and n (yinKoch2007.csv) interpolated
linearly in ln Re to this mesh's Re_t; their Reynolds number is read once on the diameter
(Re = Re_t) and once on the radius (Re = Re_t/2), since the length they use is not checked.
"""
import json
import os
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import hinderedSettling as hs  # noqa: E402
from validationTools import read_csv  # noqa: E402

CORE = ("phi0.05-c8-L6-s1", "phi0.1-c8-L6-s1", "phi0.2-c8-L6-s1")
YIN_KOCH = Path(__file__).resolve().parent / "yinKoch2007.csv"
# their Re against our Re_t = V_t D/nu: read on the diameter, or on the radius
YIN_KOCH_READINGS = (("diameter", 1.0), ("radius", 0.5))


def yin_koch_table():
    """Yin & Koch's fits: arrays Re, k, n (ascending Re)."""
    rows = [line.strip().split(",") for line in YIN_KOCH.read_text().splitlines()
            if line.strip() and not line.startswith("#")]
    header, data = rows[0], np.array(rows[1:], dtype=float)
    col = {name: data[:, i] for i, name in enumerate(header)}
    return col["Re"], col["k"], col["n"]


def yin_koch(re):
    """(k, n) of Yin & Koch at their Reynolds number re, linear in ln Re between their
    points; ValueError outside their range (no extrapolation)."""
    res, ks, ns = yin_koch_table()
    if not res[0] <= re <= res[-1]:
        raise ValueError(f"{YIN_KOCH}: Re {re:g} is outside the tabulated range "
                         f"{res[0]:g}-{res[-1]:g}")
    x = np.log(re)
    return float(np.interp(x, np.log(res), ks)), float(np.interp(x, np.log(res), ns))


def key(name):
    """A run's name as a metrics key suffix: phi0.1-c8-L6-s1 -> phi0p1_c8_L6_s1."""
    return name.replace(".", "p").replace("-", "_")


def terminal(results, cpd):
    """(V_t, Re_t, source) on the mesh of cpd cells per D: measured, or the
    Schiller-Naumann estimate when no reference run exists for it."""
    re_t = hs.terminal_re(results, cpd)
    if re_t is not None:
        return re_t * hs.NU, re_t, "measured"
    re_t = hs.predicted_re([])
    return re_t * hs.NU, re_t, "Schiller-Naumann estimate"


def evaluate(results):
    runs = read_csv(os.path.join(results, "runs.csv"), missing_ok=False)
    for r in runs:
        for k in ("phi", "w", "w_se", "rms_w", "rms_h", "max_force_over_weight", "flux_residue",
                  "w_first_half", "w_second_half", "average_from", "end_time",
                  "g_near_vertical", "g_near_horizontal", "g_near_start"):
            r[k] = float(r[k]) if r.get(k) else float("nan")
        r["cpd"] = int(r["cpd"])
        v_t, re_t, source = terminal(results, r["cpd"])
        n = hs.rowe(re_t)
        r.update(V_t=v_t, Re_t=re_t, source=source, n=n, rz=(1 - r["phi"]) ** n,
                 hindrance=r["w"] / v_t, hindrance_se=r["w_se"] / v_t)
        r["error_pct"] = 100 * (r["hindrance"] / r["rz"] - 1)
        for reading, scale in YIN_KOCH_READINGS:
            k, n_yk = yin_koch(scale * re_t)
            r[f"yk_{reading}"] = k * (1 - r["phi"]) ** n_yk
            r[f"yk_error_pct_{reading}"] = 100 * (r["hindrance"] / r[f"yk_{reading}"] - 1)
    return runs


def metrics_of(runs, results):
    m = {}
    for r in runs:
        m[f"hindrance_{key(r['name'])}"] = round(r["hindrance"], 5)
        m[f"hindrance_error_pct_{key(r['name'])}"] = round(r["error_pct"], 3)
        for reading, _ in YIN_KOCH_READINGS:
            suffix = "" if reading == "diameter" else "_radius_reading"
            m[f"hindrance_error_vs_yin_koch_pct_{key(r['name'])}{suffix}"] = round(
                r[f"yk_error_pct_{reading}"], 3)
    core = [r for r in runs if r["name"] in CORE]
    fit = fitted_k_n(runs)
    if fit:
        m["fitted_prefactor_k"], m["fitted_exponent_n"] = round(fit[0], 4), round(fit[1], 4)
    m["max_abs_hindrance_error_pct"] = (round(max(abs(r["error_pct"]) for r in core), 3)
                                        if len(core) == len(CORE) else None)
    # how far the resolved simulations' fits lie from Richardson-Zaki at the core runs' phi
    gaps = [100 * (r[f"yk_{reading}"] / r["rz"] - 1) for r in core
            for reading, _ in YIN_KOCH_READINGS]
    if len(core) == len(CORE):
        m["yin_koch_vs_richardson_zaki_pct_min"] = round(min(gaps), 3)
        m["yin_koch_vs_richardson_zaki_pct_max"] = round(max(gaps), 3)
    m["max_abs_error_vs_yin_koch_pct"] = (
        round(max(abs(r[f"yk_error_pct_{reading}"]) for r in core
                  for reading, _ in YIN_KOCH_READINGS), 3)
        if len(core) == len(CORE) else None)
    for cpd in sorted({r["cpd"] for r in runs}):
        v_t, re_t, source = terminal(results, cpd)
        m[f"V_t_c{cpd}"] = round(v_t, 6)
        m[f"Re_t_c{cpd}"] = round(re_t, 4)
        m[f"V_t_c{cpd}_measured"] = source == "measured"
        for reading, scale in YIN_KOCH_READINGS:
            suffix = "" if reading == "diameter" else "_radius_reading"
            k, n_yk = yin_koch(scale * re_t)
            m[f"yin_koch_k_c{cpd}{suffix}"] = round(k, 4)
            m[f"yin_koch_n_c{cpd}{suffix}"] = round(n_yk, 4)
    diffs = [abs(float(r["difference_pct"])) for r in read_csv(os.path.join(results, "array.csv"))]
    if diffs:
        m["settling_array_max_abs_difference_pct"] = round(max(diffs), 4)
    for r in read_csv(os.path.join(results, "held.csv")):
        cpd = r["name"].split("-")[1]
        m[f"moving_vs_fixed_force_difference_pct_{cpd}"] = round(float(r["difference_pct"]), 3)
        m[f"moving_vs_fixed_speed_difference_pct_{cpd}"] = round(
            -float(r["velocity_equivalent_pct"]), 3)
    wide = hs.terminal_re(results, 8, 2.0)
    base = hs.terminal_re(results, 8)
    if wide is not None and base is not None:
        m["V_t_c8_domain_x2_change_pct"] = round(100 * (wide / base - 1), 3)
    return m


def tables(runs, results):
    md = ["# Hindered settling of spheres: results", "",
          f"Ga {hs.GA:g}, rho_p/rho_f {hs.RATIO:g}, units D = 1, V_g = 1 (nu = {hs.NU:.6g}), "
          "times in D/V_g. Written by `hinderedSettling.py plot`.", ""]
    md += array_table(results)
    md += held_table(results)
    md += [
          "## The single sphere (fixed in a uniform stream, the frame of steady settling)", "",
          "| run | cells/D | domain | Re | C_D | (3/4) C_D Re^2/Ga^2 | C_D change over the last "
          "10 D/U | cells | CPU s |", "|---|---|---|---|---|---|---|---|---|"]
    for r in read_csv(os.path.join(results, "reference.csv")):
        md.append(f"| {r['name']} | {r['cpd']} | x{float(r['domain_scale']):g} | {r['Re']} | "
                  f"{r['C_D']} | {r['balance']} | {r['C_D_change_pct']} % | {r['cells']} | "
                  f"{r['cpu_s']} |")
    md += ["", "| cells/D | domain | Re_t | V_t [V_g] | Rowe's n | source |",
           "|---|---|---|---|---|---|"]
    measured = {int(r["cpd"]) for r in read_csv(os.path.join(results, "reference.csv"))}
    for cpd in sorted({r["cpd"] for r in runs} | measured):
        for scale in (1.0, 2.0):
            re_t = hs.terminal_re(results, cpd, scale)
            if re_t is None and scale != 1.0:
                continue
            v_t, re_t, source = (terminal(results, cpd) if scale == 1.0
                                 else (re_t * hs.NU, re_t, "measured"))
            md.append(f"| {cpd} | x{scale:g} | {re_t:.4f} | {v_t:.5f} | {hs.rowe(re_t):.4f} | "
                      f"{source} |")
    md += ["", "Schiller-Naumann: Re_t = " f"{hs.predicted_re([]):.4f}.", "",
           "## The suspensions", "",
           "-<v_z>: the mean over the bodies and over the window (t from, to); its standard "
           "error from five equal batches of the window; the halves: the means over the first "
           "and second half of the window (a drift shows there). Flux residue: the largest "
           "mean velocity over the box logged by meanFlow, against -<v_z>.", "",
           "| run | spheres | phi | box | cells/D | window | steps | -<v_z> [V_g] | +- (s.e.) "
           "| halves | hindrance | Richardson-Zaki | error | Yin & Koch, Re on D / on D/2 | "
           "error | rms v_z' / V_t | rms v_x' / V_t | "
           "g(1-1.5 D) vertical, horizontal (t = 0) | flux residue | max |F_h|/W | CPU s |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        md.append(f"| {r['name']} | {r['bodies']} | {r['phi']:.4f} | {r['L']} D | {r['cpd']} | "
                  f"{r['average_from']:g}-{r['end_time']:g} | "
                  f"{r['steps']} | {r['w']:.5f} | {r['w_se']:.5f} | {r['w_first_half']:.4f}, "
                  f"{r['w_second_half']:.4f} | {r['hindrance']:.4f} "
                  f"+- {r['hindrance_se']:.4f} | {r['rz']:.4f} | {r['error_pct']:+.2f} % | "
                  f"{r['yk_diameter']:.4f} / {r['yk_radius']:.4f} | "
                  f"{r['yk_error_pct_diameter']:+.2f} / {r['yk_error_pct_radius']:+.2f} % | "
                  f"{r['rms_w'] / r['V_t']:.3f} | {r['rms_h'] / r['V_t']:.3f} | "
                  f"{r['g_near_vertical']:.2f}, {r['g_near_horizontal']:.2f} "
                  f"({r['g_near_start']:.2f}) | "
                  f"{r['flux_residue']:.2g} | {r['max_force_over_weight']:.3g} | {r['cpu_s']} |")
    fit = fitted_k_n(runs)
    if fit:
        re_t = terminal(results, 8)[1]
        yk = [yin_koch(scale * re_t) for _, scale in YIN_KOCH_READINGS]
        md += ["", f"Fit of the core runs to k (1 - phi)^n: k = {fit[0]:.4f}, n = {fit[1]:.4f} "
               f"(Rowe's n at Re_t of 8 cells/D: {hs.rowe(re_t):.4f}; Yin & Koch at that Re_t: "
               f"k = {yk[0][0]:.4f}, n = {yk[0][1]:.4f} with their Re on D, "
               f"k = {yk[1][0]:.4f}, n = {yk[1][1]:.4f} on D/2)."]
    return md


def fitted_k_n(runs):
    """(k, n) of the least-squares fit ln H = ln k + n ln(1 - phi) over the core runs, or
    None until all exist."""
    core = [r for r in runs if r["name"] in CORE]
    if len(core) != len(CORE):
        return None
    n, lnk = np.polyfit([np.log(1 - r["phi"]) for r in core],
                        [np.log(r["hindrance"]) for r in core], 1)
    return float(np.exp(lnk)), float(n)


def array_table(results):
    """The settling simple cubic array in Stokes flow against the fixed one (the check of
    the zero-flux frame)."""
    rows = read_csv(os.path.join(results, "array.csv"))
    if not rows:
        return []
    md = ["## The zero-flux frame: a simple cubic array settling in Stokes flow", "",
          "One sphere per triply periodic box, free, `meanFlow zeroFlux`, Re <= 0.02, on the "
          "uniform mesh of `../periodicArray`'s run at the same phi and cells/D; K_settling = "
          "V_s/W (W its settling speed, V_s the Stokes speed of the sphere alone) against K of "
          "the fixed array on the same mesh (`../periodicArray/results/runs.csv`) and Zick & "
          "Homsy (1982). Written by `hinderedSettling.py array`.", "",
          "| run | phi | cells | cells/D | steps | change of W over the last 10 % | K_settling | "
          "K_fixed | difference | Zick & Homsy | error | flux residue at the end | CPU s |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append(f"| {r['name']} | {r['phi']} | {r['cells']} | {r['cpd_eff']} | {r['steps']} | "
                  f"{r['w_change']} | {r['K_settling']} | {r['K_fixed']} | "
                  f"{float(r['difference_pct']):+.3f} % | {r['K_ref']} | "
                  f"{float(r['error_pct']):+.2f} % | {r['flux_residue']} | {r['cpu_s']} |")
    return md + [""]


def held_table(results):
    """The free sphere of a settling array at Re_t against the same sphere held fixed (the
    check of the moving sphere's coupling)."""
    rows = read_csv(os.path.join(results, "held.csv"))
    if not rows:
        return []
    md = ["## The moving sphere against the fixed one at Re_t", "",
          "The free sphere of `single-c8-L4` or `single-c12-L4` (one sphere per 4 D box, "
          "`meanFlow zeroFlux`) settles at W; the same sphere held fixed in the same box and "
          "mesh with the superficial velocity W held along z (meanVelocityForce) carries the "
          "force F. By "
          "Galilean invariance F equals the net weight W_net; F/W_net - 1 is the difference of "
          "the moving sphere's coupling against the fixed sphere's (the reference V_t is a "
          "fixed sphere), and the speed the free sphere would have with the fixed sphere's "
          "drag follows with the local slope dln F/dln U of the Schiller-Naumann law. Written "
          "by `hinderedSettling.py held`.", "",
          "| run | W [V_g] | Re | F/W_net | change of F over the last 10 % | dln F/dln U | "
          "free sphere's speed against the fixed sphere's | cells | steps | CPU s |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append(f"| {r['name']} | {r['W']} | {r['Re']} | {r['force_over_weight']} "
                  f"({float(r['difference_pct']):+.2f} %) | {r['force_change']} | {r['slope']} | "
                  f"{-float(r['velocity_equivalent_pct']):+.2f} % | {r['cells']} | {r['steps']} | "
                  f"{r['cpu_s']} |")
    return md + [""]


def figures(runs, results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    re_t = min((r["Re_t"] for r in runs), default=hs.predicted_re([]))
    phi = np.linspace(0, 0.3, 200)
    rz = (1 - phi) ** hs.rowe(re_t)
    ax.plot(phi, rz, "k-", label=f"Richardson-Zaki, Rowe's n = {hs.rowe(re_t):.2f}")
    ax.fill_between(phi, 0.9 * rz, 1.1 * rz, color="0.85", label="+-10 %")
    for (reading, scale), style in zip(YIN_KOCH_READINGS, ("-.", ":")):
        k, n_yk = yin_koch(scale * re_t)
        ax.plot(phi, k * (1 - phi) ** n_yk, "b" + style, lw=1.2,
                label=f"Yin & Koch 2007 (LB), Re on the {reading}: {k:.3f} (1 - phi)^{n_yk:.2f}")
    fit = fitted_k_n(runs)
    if fit:
        ax.plot(phi, fit[0] * (1 - phi) ** fit[1], "k--", lw=1,
                label=f"fit to the core runs: {fit[0]:.3f} (1 - phi)^{fit[1]:.2f}")
    styles = {"s1": ("o", "tab:red"), "s2": ("v", "tab:orange")}
    for r in runs:
        label = r["name"]
        marker, colour = styles.get(r["name"].rsplit("-", 1)[-1], ("o", "tab:red"))
        if "-L8-" in r["name"]:
            marker, colour = "s", "tab:blue"
        if r["cpd"] != 8:
            marker, colour = "D", "tab:green"
        if r["name"].startswith("single-"):
            marker, colour = "x", "0.3"
            label += " (one sphere per box: a settling array)"
        ax.errorbar(r["phi"], r["hindrance"], yerr=2 * r["hindrance_se"], fmt=marker,
                    color=colour, capsize=3, label=label)
    ax.set_xlabel("solid fraction phi")
    ax.set_ylabel("hindrance factor <w>/V_t")
    ax.set_title(f"Hindered settling of spheres, Ga {hs.GA:g}, rho_p/rho_f {hs.RATIO:g}\n"
                 "(error bars: 2 standard errors of the time mean)")
    ax.set_xlim(0, 0.3)
    ax.set_ylim(0, 1.15)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "hindrance.png"), dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7.4, 4.6))
    for i, r in enumerate(runs):
        path = os.path.join(results, f"{r['name']}.dat")
        if not os.path.exists(path):
            continue
        t, w = np.loadtxt(path, unpack=True)
        line, = ax.plot(t, w / r["V_t"], lw=0.8, label=f"{r['name']} (phi {r['phi']:.3f})")
        ax.axhline(r["rz"], color=line.get_color(), ls="--", lw=0.8)
    ax.axvline(hs.AVERAGE_FROM, color="0.5", lw=0.8)
    ax.set_xlabel("time t [D/V_g]")
    ax.set_ylabel("mean settling speed -<v_z>/V_t")
    ax.set_title("Mean settling speed of the spheres (dashed: Richardson-Zaki; grey line: "
                 "start of the statistics)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(results, "settling.png"), dpi=120)
    plt.close(fig)


def report(results):
    runs = evaluate(results)
    md = tables(runs, results)
    m = metrics_of(runs, results)
    with open(os.path.join(results, "table.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.join(results, "metrics.json"), "w") as f:
        json.dump(m, f, indent=1, sort_keys=True)
        f.write("\n")
    figures(runs, results)
    print("\n".join(md))
    print(json.dumps(m, indent=1, sort_keys=True))


if __name__ == "__main__":
    report(sys.argv[1] if len(sys.argv) > 1 else str(Path(__file__).resolve().parent / "results"))
