#!/usr/bin/python3
"""Figures and tables of the dry-collision validation from the CSVs of dryCollisions.

    /usr/bin/python3 validation/dryCollisions/plotDryCollisions.py [RESULTS_DIR]

Reads RESULTS_DIR (default: validation/dryCollisions/results) and writes there
restitution.png, spheroidWall.png, extremes.png, obliqueSphereWall.png, table.md and metrics.json (the checks of
checks.md: their number, how many failed, and the worst value of each).
"""
import json
import os
import re
import statistics
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import read_csv  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results")


def read(name):
    return read_csv(os.path.join(RESULTS, name), missing_ok=False)


def num(r, k):
    return float(r[k])


def tolerance(n):
    """|e_measured - e| allowed at N sub-steps per contact (dryCollisions.cpp)."""
    return 0.15 if n < 10 else 0.4 / n


out = []  # lines of table.md


def table(header, rows):
    out.append("| " + " | ".join(header) + " |")
    out.append("|" + "---|" * len(header))
    for r in rows:
        out.append("| " + " | ".join(str(x) for x in r) + " |")
    out.append("")


def pct(x, digits=2):
    return f"{100 * x:+.{digits}f} %"


# ---------------------------------------------------------------------------
# 1-2: head-on spheres
heads = read("sphereSphere.csv") + read("sphereWall.csv")
cases = ["1:1", "1:8", "wall"]
titles = {"1:1": "sphere-sphere, equal", "1:8": "sphere-sphere, mass 1:8", "wall": "sphere-wall"}
es = sorted({num(r, "e") for r in heads}, reverse=True)
ns = sorted({int(r["N"]) for r in heads})

fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
colors = plt.cm.viridis(np.linspace(0, 0.85, len(ns)))
for j, case in enumerate(cases):
    ax = axes[0, j]
    ax.plot([0, 1], [0, 1], "k-", lw=0.8, label="e measured = e")
    for k, n in enumerate(ns):
        rs = [r for r in heads if r["case"] == case and int(r["N"]) == n]
        x = np.array([num(r, "e") for r in rs]) + 0.012 * (k - 1.5)
        ax.plot(x, [num(r, "eMeasured") for r in rs], "o", ms=3.5, color=colors[k], label=f"N = {n}")
    ax.set_xlabel("input e")
    ax.set_ylabel("measured e (all phases)")
    ax.set_title(titles[case])
    ax.legend(fontsize=8)
    ax = axes[1, j]
    for e in es:
        worst = []
        for n in ns:
            d = [abs(num(r, "eMeasured") - e) for r in heads
                 if r["case"] == case and int(r["N"]) == n and num(r, "e") == e]
            worst.append(max(d))
        ax.loglog(ns, worst, "o-", label=f"e = {e:g}")
    ax.loglog(ns, [tolerance(n) for n in ns], "k--", label="tolerance (0.4/N; 0.15 at N = 5)")
    ax.set_xlabel("sub-steps per contact N")
    ax.set_ylabel("worst |e measured - e| over the phases")
    ax.legend(fontsize=8)
fig.suptitle("Head-on restitution: measured against input e (5 phases of the first touch in the sub-step grid)")
fig.tight_layout()
fig.savefig(os.path.join(RESULTS, "restitution.png"), dpi=110)
plt.close(fig)

out.append("# Dry collisions: measured results\n")
out.append("Produced by `plotDryCollisions.py` from the CSVs of `dryCollisions` (units: D_eq = 1, "
           "nominal contact time T_c = 1, density 1).\n")
out.append("## 1-2. Head-on spheres: e measured against e, worst and median over 5 phases\n")
out.append("Relative error e_measured/e - 1, worst (largest magnitude) over the phases of the first "
           "touch in the sub-step grid, then the median in brackets. Approach speed 0.02 D_eq/T_c (uncapped).\n")
for case in cases:
    out.append(f"**{titles[case]}**\n")
    rows = []
    for e in es:
        row = [f"{e:g}"]
        for n in ns:
            rel = [num(r, "eMeasured") / e - 1 for r in heads
                   if r["case"] == case and int(r["N"]) == n and num(r, "e") == e]
            w = max(rel, key=abs)
            row.append(f"{pct(w)} ({pct(statistics.median(rel))})")
        rows.append(row)
    table(["e"] + [f"N = {n}" for n in ns], rows)

rows = []
for case in cases:
    rs = [r for r in heads if r["case"] == case]
    mom = max(num(r, "momentumError") for r in rs)
    ke = max(num(r, "keMaxRatio") for r in rs)
    en = [num(r, "energyLossError") for r in rs if int(r["N"]) >= 20]
    sub = sorted({int(r["contactSubSteps"]) - int(r["N"]) for r in rs if int(r["N"]) >= 10})
    rows.append([titles[case], f"{mom:.1e}", f"{ke:.1e}",
                 f"{min(en):+.3f} .. {max(en):+.3f}", ", ".join(f"N{d:+d}" for d in sub)])
table(["case", "max momentum error (a)", "max KE(t)/KE(0) - 1", "energy loss / (1/2 (1 - e^2) m_eff u0^2) - 1, N >= 20",
       "sub-steps in contact (N >= 10)"], rows)
out.append("(a) pairs: |p_end - p_0| / sum |p_i|; wall: the velocity component off the normal / u0.\n")

# ---------------------------------------------------------------------------
# 3: spheroid on a wall
sw = read("spheroidWall.csv")
ars = sorted({num(r, "ar") for r in sw})
tilts = sorted({num(r, "tiltDeg") for r in sw})
speeds = [s for s in ("slower", "slow", "fast") if any(r["speedCase"] == s for r in sw)]
nShow = 20 if any(int(r["N"]) == 20 for r in sw) else int(sw[0]["N"])
swEs = sorted({num(r, "e") for r in sw}, reverse=True)


def arName(a):
    return f"1/{round(1 / a)}" if a < 1 else f"{a:g}"


fig, axes = plt.subplots(len(speeds), len(swEs), figsize=(5.5 * len(swEs), 3.6 * len(speeds)),
                         squeeze=False)
for i, sc in enumerate(speeds):
    for j, e in enumerate(swEs):
        ax = axes[i, j]
        for a in ars:
            rs = sorted([r for r in sw if r["speedCase"] == sc and num(r, "e") == e and num(r, "ar") == a
                         and int(r["N"]) == nShow], key=lambda r: num(r, "tiltDeg"))
            ax.plot([num(r, "tiltDeg") for r in rs], [num(r, "eMeasured") / e for r in rs], "o-",
                    label=f"Ar {arName(a)}")
        th = [num(r, "thetaContact") for r in sw if r["speedCase"] == sc and num(r, "e") == e]
        u = [num(r, "speed") for r in sw if r["speedCase"] == sc][0]
        ax.axhline(1, color="k", lw=0.8)
        ax.set_title(f"e = {e:g}, {sc}: u = {u:g} D_eq/T_c, turn in contact <= {max(th):.2g} rad", fontsize=9)
        ax.set_xlabel("tilt of the symmetry axis from the wall (deg)")
        ax.set_ylabel("e measured / e (contact point)")
        ax.legend(fontsize=8)
fig.suptitle(f"Spheroid on a wall, N = {nShow}: restitution of the contact point's normal velocity")
fig.tight_layout()
fig.savefig(os.path.join(RESULTS, "spheroidWall.png"), dpi=110)
plt.close(fig)

out.append("## 3. Spheroid on a wall: restitution of the contact point and spin\n")
out.append("e_measured/e - 1 of the normal velocity of the body point nearest the wall (after/before), "
           "theta_c = |omega_after| x contact duration (the angle turned during the contact, an upper bound), "
           "spin error |omega - omega_rigid|/|omega_rigid| against the rigid-impact impulse "
           "J = (1 + e) m_eff u with m_eff at the first touch.\n")
rows = []
for sc in speeds:
    for n in sorted({int(r["N"]) for r in sw}):
        for kind, pick in (("untilted (0, 90 deg)", lambda r: num(r, "thetaContact") < 1e-9),
                           ("tilted", lambda r: num(r, "thetaContact") >= 1e-9)):
            rs = [r for r in sw if r["speedCase"] == sc and int(r["N"]) == n and pick(r)]
            if not rs:
                continue
            de = [abs(num(r, "eMeasured") - num(r, "e")) for r in rs]
            rel = [num(r, "relError") for r in rs]
            th = [num(r, "thetaContact") for r in rs]
            sp = [num(r, "spinError") for r in rs if num(r, "thetaContact") >= 1e-9]
            rows.append([sc, n, kind, f"{max(th):.2g}", f"{max(de):.4f}", pct(min(rel)) + " .. " + pct(max(rel)),
                         f"{max(sp):.4f}" if sp else "-",
                         f"{max(num(r, 'maxOverlapRatio') for r in rs):.3f}"])
table(["speed", "N", "tilt", "max theta_c (rad)", "max abs(e_meas - e)", "e_meas/e - 1 range",
       "max spin error", "max overlap/a_min"], rows)

out.append(f"Per case at N = {nShow} (e_meas/e - 1; theta_c in rad):\n")
rows = []
for a in ars:
    for t in tilts:
        row = [arName(a), f"{t:g}"]
        for sc in speeds:
            for e in swEs:
                r = [r for r in sw if r["speedCase"] == sc and num(r, "e") == e and num(r, "ar") == a
                     and num(r, "tiltDeg") == t and int(r["N"]) == nShow][0]
                row.append(f"{pct(num(r, 'relError'), 1)} ({num(r, 'thetaContact'):.1g})")
        rows.append(row)
table(["Ar", "tilt"] + [f"{sc} e={e:g}" for sc in speeds for e in swEs], rows)

# energy of the wall impacts: the body must leave with less kinetic energy
rows = []
for sc in speeds:
    rs = [r for r in sw if r["speedCase"] == sc]
    gain = [r for r in rs if num(r, "keChange") > 1e-9]
    rows.append([sc, len(rs), f"{max(num(r, 'keChange') for r in rs):+.2e}", len(gain),
                 ", ".join(sorted({f"Ar {arName(num(r, 'ar'))} tilt {num(r, 'tiltDeg'):g} e {num(r, 'e'):g}"
                                   for r in gain})) or "-"])
out.append("Kinetic energy of the wall impacts, KE(end)/KE(0) - 1 (all N):\n")
table(["speed", "runs", "max KE(end)/KE(0) - 1", "runs that GAINED kinetic energy", "where"], rows)

# ---------------------------------------------------------------------------
# 4: spheroid pairs
pp = [r for r in read("spheroidPairs.csv") if r["impactSpeed"] != "miss"]
misses = len(read("spheroidPairs.csv")) - len(pp)
out.append("## 4. Oblique spheroid-spheroid impacts\n")
out.append(f"Approach 0.02 D_eq/T_c with small off-axis velocities and spins, impact offsets "
           f"0, 0.3, 0.6, 0.9 D_eq (misses skipped: {misses}), 2 random orientations, e 0.9 and 0.5; "
           "angular momentum about the origin, 2.3 D_eq from the impact, relative to "
           "sum |x_i| |p_i| + |I_i omega_i|.\n")
rows = []
pairs = sorted({(num(r, "ar1"), num(r, "ar2")) for r in pp}, key=lambda p: (-p[0], p[1]))
for p in pairs:
    for mu in sorted({num(r, "friction") for r in pp}):
        rs = [r for r in pp if (num(r, "ar1"), num(r, "ar2")) == p and num(r, "friction") == mu]
        row = [f"{arName(p[0])} / {arName(p[1])}", f"{mu:g}", len(rs),
               f"{max(num(r, 'momentumError') for r in rs):.1e}"]
        for n in sorted({int(r["N"]) for r in pp}):
            row.append(f"{max(num(r, 'angularMomentumError') for r in rs if int(r['N']) == n):.1e}")
        row += [f"{max(num(r, 'keMaxRatio') for r in rs):.1e}",
                f"{min(num(r, 'keFinalRatio') for r in rs):.3f} .. {max(num(r, 'keFinalRatio') for r in rs):.3f}",
                f"{max(num(r, 'maxOverlapRatio') for r in rs):.3f}", max(int(r["episodes"]) for r in rs)]
        rows.append(row)
table(["Ar 1 / Ar 2", "mu", "runs", "max dp"] + [f"max dL, N = {n}" for n in sorted({int(r['N']) for r in pp})]
      + ["max KE(t)/KE(0) - 1", "KE(end)/KE(0)", "max overlap/a_min", "max contacts"], rows)

# ---------------------------------------------------------------------------
# 5: cap sweep and extremes
cs = read("capSweep.csv")
ex = read("extremes.csv")
fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
ax = axes[0]
alphas = sorted({num(r, "alphaDeg") for r in ex})
cmap = plt.cm.plasma(np.linspace(0, 0.85, len(alphas)))
rng = np.random.default_rng(1)
for k, a in enumerate(alphas):
    rs = [r for r in ex if num(r, "alphaDeg") == a]
    x = np.array([num(r, "speed") for r in rs]) * np.exp(0.25 * (rng.random(len(rs)) - 0.5))
    ax.semilogx(x, [num(r, "maxOverlapRatio") for r in rs], "o", ms=2.5, alpha=0.6, color=cmap[k],
                label=f"Ar 6 vs 1/6, alpha = {a:g} deg")
for e, m in zip(sorted({num(r, "e") for r in cs}, reverse=True), ("k-", "k--", "k:")):
    rs = sorted([r for r in cs if num(r, "e") == e], key=lambda r: num(r, "speed"))
    ax.semilogx([num(r, "speed") for r in rs], [num(r, "maxOverlapRatio") for r in rs], m, lw=1.5,
                label=f"equal spheres head-on, e = {e:g}")
ax.axhline(0.1, color="gray", lw=0.8)
ax.axhline(0.15, color="r", lw=0.8, label="check limit 0.15")
ax.set_xlabel("approach speed (D_eq / T_c)")
ax.set_ylabel("max overlap / a_min")
ax.set_title("Overlap against approach speed (cap maxOverlap = 0.1)")
ax.legend(fontsize=7)
ax = axes[1]
for k, a in enumerate(alphas):
    rs = [r for r in ex if num(r, "alphaDeg") == a]
    x = np.array([num(r, "speed") for r in rs]) * np.exp(0.25 * (rng.random(len(rs)) - 0.5))
    ax.semilogx(x, [num(r, "keFinalRatio") - 1 for r in rs], "o", ms=2.5, alpha=0.6, color=cmap[k],
                label=f"alpha = {a:g} deg")
ax.axhline(0, color="r", lw=0.8)
ax.set_yscale("symlog", linthresh=1e-4)
ax.set_xlabel("approach speed (D_eq / T_c)")
ax.set_ylabel("KE(end)/KE(0) - 1")
ax.set_title("Kinetic energy change (e = 0.9): must be <= 0")
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(RESULTS, "extremes.png"), dpi=110)
plt.close(fig)

out.append("## 5. Speed sweep (equal spheres, head-on, N = 10) and extremes\n")
rows = []
for r in sorted(cs, key=lambda r: (num(r, "speed"), -num(r, "e"))):
    rows.append([f"{num(r, 'speed'):g}", r["e"], f"{num(r, 'eMeasured'):.4f}", pct(num(r, "relError")),
                 f"{num(r, 'maxOverlapRatio'):.4f}", f"{num(r, 'contactTimeModel'):.4g}",
                 r["subStepsPerFluidStep"], r["contactSubSteps"]])
table(["u (D_eq/T_c)", "e", "e measured", "rel. error", "max overlap/a_min", "T_c of the pair",
       "sub-steps per fluid step", "sub-steps in contact"], rows)

out.append("Ar 6 (prolate) against Ar 1/6 (oblate), e = 0.9, N = 10, by approach speed "
           f"({len(ex)} runs: prolate axis x, xy45, y, z; alpha 0-90 deg; offsets 0-0.999 of grazing; "
           "gaps +1e-6, 0, -1e-6 D_eq; friction 0 and 0.3):\n")
rows = []
for s in sorted({num(r, "speed") for r in ex}):
    rs = [r for r in ex if num(r, "speed") == s]
    rows.append([f"{s:g}", len(rs), f"{max(num(r, 'maxOverlapRatio') for r in rs):.3f}",
                 sum(num(r, "maxOverlapRatio") > 0.15 for r in rs),
                 f"{min(num(r, 'minCentreMargin') for r in rs):.3f}",
                 sum(num(r, "finalDistance") <= 0 for r in rs),
                 sum(r["error"] != "" for r in rs),
                 sum(int(r["notConverged"]) for r in rs), sum(int(r["distanceQueries"]) for r in rs),
                 f"{max(num(r, 'keFinalRatio') for r in rs) - 1:+.1e}",
                 sum(num(r, "keFinalRatio") > 1 + 1e-9 for r in rs),
                 max(int(r["episodes"]) for r in rs)])
table(["u (D_eq/T_c)", "runs", "max overlap/a_min", "runs > 0.15", "min (c2-c1).n0/(a1+a2)",
       "ended overlapping", "NaN/exceptions", "non-converged", "distance queries",
       "max KE(end)/KE(0) - 1", "runs gaining KE", "max contacts"], rows)

over = [r for r in ex if num(r, "maxOverlapRatio") > 0.15]
if over:
    out.append("Runs above 0.15: " + "; ".join(sorted({
        f"axis {r['prolateAxis']} alpha {num(r, 'alphaDeg'):g} f {num(r, 'fraction'):g}" for r in over}))
        + f" ({len(over)} runs, speeds " + ", ".join(sorted({f'{num(r, "speed"):g}' for r in over}, key=float)) + ").\n")
gain = [r for r in ex if num(r, "keFinalRatio") > 1 + 1e-9]
if gain:
    out.append("Runs gaining kinetic energy: " + "; ".join(sorted({
        f"axis {r['prolateAxis']} alpha {num(r, 'alphaDeg'):g} f {num(r, 'fraction'):g} mu {num(r, 'friction'):g}"
        for r in gain})) + f" ({len(gain)} runs, max {max(num(r, 'keFinalRatio') for r in gain) - 1:.1e}).\n")


# ---------------------------------------------------------------------------
# 6: oblique sphere-wall impacts with Coulomb friction
ob = read("obliqueSphereWall.csv")
fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
for (mu, e), m in zip(sorted({(num(r, "mu"), num(r, "e")) for r in ob}),
                      ("o", "s", "^", "v", "D", "x")):
    rs = sorted([r for r in ob if num(r, "mu") == mu and num(r, "e") == e],
                key=lambda r: num(r, "psiIn"))
    x = [num(r, "psiIn") for r in rs]
    line = axes[0].plot(x, [num(r, "psiOut") for r in rs], m, ms=4,
                        label=f"core, mu = {mu:g}, e = {e:g}")[0]
    axes[0].plot(x, [num(r, "psiOutTheory") for r in rs], "-", lw=0.8, color=line.get_color())
    axes[1].plot(x, [num(r, "muEffective") / mu for r in rs], m + "-", ms=4, lw=0.8,
                 color=line.get_color(), label=f"mu = {mu:g}, e = {e:g}")
axes[0].set_xlabel("Psi_in = v_t,contact / u_n (impact)")
axes[0].set_ylabel("Psi_out = v_t,contact after / u_n (impact)")
axes[0].set_title("Oblique sphere-wall impacts (lines: rigid-body impact theory)")
axes[0].legend(fontsize=7)
axes[1].set_xscale("log")
axes[1].set_xlabel("Psi_in")
axes[1].set_ylabel("mu_eff / mu = dU_t / (mu (1 + e_n) u_n)")
axes[1].set_title("Effective friction over the input mu")
axes[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(RESULTS, "obliqueSphereWall.png"), dpi=110)
plt.close(fig)

out.append("## 6. Oblique sphere-wall impacts (tangential spring with Coulomb's limit, N = 10)\n")
out.append("Psi = v_t/u_n: the tangential speed of the contact point over the normal impact speed "
           "(Joseph & Hunt 2004; Walton 1993). Rigid-body impact theory: Psi_out = Psi_in - 7/2 mu (1 + e_n) "
           "when the contact slides throughout (Psi_in > Psi_c = 7/2 mu (1 + e_n)/(1 + e)), "
           "Psi_out = -e Psi_in when it sticks. mu_eff = (U_t,in - U_t,out)/((1 + e_n) u_n): mu when "
           "sliding.\n")
rows = []
for mu, e in sorted({(num(r, "mu"), num(r, "e")) for r in ob}):
    rs = [r for r in ob if num(r, "mu") == mu and num(r, "e") == e]
    psic = [3.5 * mu * (1 + num(r, "eMeasured")) / (1 + e) for r in rs]
    slide = [r for r, c in zip(rs, psic) if num(r, "psiIn") >= 2 * c]
    stick = [r for r, c in zip(rs, psic) if num(r, "psiIn") < 0.75 * c]
    rows.append([f"{mu:g}", f"{e:g}", len(rs), f"{min(psic):.3f}",
                 f"{max(abs(num(r, 'muEffective') / mu - 1) for r in slide):.4f}" if slide else "-",
                 f"{max(abs(num(r, 'psiOut') / num(r, 'psiIn') + e) for r in stick):.4f}" if stick else "-",
                 f"{max(abs(num(r, 'psiOut') - num(r, 'psiOutTheory')) for r in rs):.4f}"])
table(["mu", "e", "runs", "Psi_c", "max abs(mu_eff/mu - 1), Psi_in >= 2 Psi_c",
       "max abs(Psi_out/Psi_in + e), Psi_in < 0.75 Psi_c", "max abs(Psi_out - theory), all"], rows)
out.append("Between the regimes the spring model passes smoothly from sticking to sliding (the "
           "contact sticks at its start and slips partly at its end, as in Maw, Barber & Fawcett's "
           "elastic theory), where the rigid-body theory has a corner: the largest differences from "
           "the theory are there.\n")

def check_metrics(path):
    """Flat metrics from checks.md (written by dryCollisions): checks, checks_failed and
    worst_<check> for each check (its worst value over the cases it covers), and
    extremes_distance_queries (the distance queries of the extremes)."""
    metrics = {"checks": 0, "checks_failed": 0}
    with open(path) as f:
        for line in f:
            queries = re.match(r"- 5 extremes: .* in (\d+) queries", line)
            if queries:
                metrics["extremes_distance_queries"] = int(queries.group(1))
            if not re.match(r"\| \d", line):
                continue
            cells = [c.strip().replace("\\|", "|")
                     for c in line.replace("\\|", "\\!").strip().strip("|").split(" | ")]
            cells = [c.replace("\\!", "|") for c in cells]
            name, worst, failed = cells[0], cells[2], int(cells[5])
            key = "worst_" + re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")
            metrics[key] = float(worst)
            metrics["checks"] += 1
            metrics["checks_failed"] += int(failed > 0)
    return metrics


def failed_checks(path):
    """The names of the checks of checks.md with failed cases."""
    names = []
    with open(path) as f:
        for line in f:
            if re.match(r"\| \d", line):
                cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
                if int(cells[5]) > 0:
                    names.append(cells[0].replace("\\|", "|"))
    return names


metrics = check_metrics(os.path.join(RESULTS, "checks.md"))

# the approach check's bound (Allrun -approach-scale F): the figures it moves
APPROACH_KEYS = [
    ("worst_5_extremes_max_overlap_a_min_model", "extremes: max overlap / a_min"),
    ("worst_3_spheroid_wall_max_overlap_a_min", "spheroid-wall: max overlap / a_min"),
    ("worst_5_cap_sweep_spheres_e_meas_e_n_10", "cap sweep: max abs(e_meas - e)"),
    ("extremes_distance_queries", "extremes: distance queries"),
    ("checks_failed", "checks failed"),
]
variants = {1.0: (metrics, failed_checks(os.path.join(RESULTS, "checks.md")))}
for d in Path(RESULTS).glob("approachScale-*"):
    if (d / "checks.md").is_file():
        scale = float(d.name.split("-", 1)[1])
        variants[scale] = (check_metrics(d / "checks.md"), failed_checks(d / "checks.md"))
if len(variants) > 1:
    out.append("## The approach check's bound\n")
    out.append("The full set with `CollisionSettings::approachContactTimeScale` (the shortest contact "
               "time the approach check stiffens a spring to, in subStepsPerContact sub-steps; "
               "default 1) halved and doubled: `Allrun -approach-scale F`, checks in "
               "`results/approachScale-F/checks.md`.\n")
    table(["approachContactTimeScale"] + [label for _, label in APPROACH_KEYS] + ["failed checks"],
          [[f"{scale:g}"] + [f"{m[k]:g}" if k in m else "-" for k, _ in APPROACH_KEYS]
           + ["; ".join(n.replace("|", "\\|") for n in failed) or "-"] for scale, (m, failed) in sorted(variants.items())])
    for scale, (m, _) in variants.items():
        if scale == 1.0:
            continue
        for k, _ in APPROACH_KEYS:
            if k in m:
                metrics[f"approach_scale_{scale:g}_{k}"] = m[k]

with open(os.path.join(RESULTS, "table.md"), "w") as f:
    f.write("\n".join(out) + "\n")

with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
    json.dump(metrics, f, indent=1, sort_keys=True)
    f.write("\n")
print("wrote", ", ".join(os.path.join(RESULTS, x) for x in
                         ("restitution.png", "spheroidWall.png", "extremes.png", "obliqueSphereWall.png", "table.md",
                          "metrics.json")))
