"""The body-fitted sections of validation/finiteReynoldsDrag's results/table.md and their
metrics: the body-fitted drag and lift on three meshes (results/bodyFitted.csv), their
extrapolation, and the immersed runs (results/runs.csv, 16 cells/D_eq) and the published
references against them."""
import math
import os

import references

HERE = os.path.dirname(os.path.abspath(__file__))
ASYMPTOTIC_ORDERS = (1.0, 3.0)   # observed orders taken as asymptotic (the schemes' is 2)
STEADY_PCT = 0.05                # a run whose lift changes more over its last 50 iterations
                                 # is left out of the lift's series


def _read(path):
    import csv
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def extrapolate(values, ratio=2.0):
    """(observed order, extrapolated value) from values on meshes refined by ratio each
    time (coarse to fine); the order from the last three, the extrapolation Richardson's.
    Outside ASYMPTOTIC_ORDERS (or with changes of both signs) the meshes are not in the
    asymptotic range: the value is the finest mesh's, not extrapolated."""
    f1, f2, f3 = values[-3:]
    if (f1 - f2) * (f2 - f3) <= 0:
        return float("nan"), f3
    p = math.log(abs(f1 - f2) / abs(f2 - f3)) / math.log(ratio)
    if not ASYMPTOTIC_ORDERS[0] <= p <= ASYMPTOTIC_ORDERS[1]:
        return p, f3
    return p, f3 + (f3 - f2) / (ratio ** p - 1.0)


def asymptotic(p):
    return ASYMPTOTIC_ORDERS[0] <= p <= ASYMPTOTIC_ORDERS[1]


def series(rows):
    """{(ar, Re, incidence): [(n_eta, C_D, C_L, cells per D at the wall, change %), ...]}
    sorted by n_eta."""
    out = {}
    for r in rows:
        key = (float(r["ar"]), float(r["Re"]), float(r.get("incidence") or 0))
        out.setdefault(key, []).append((int(r["n_eta"]), float(r["C_D"]), float(r["C_L"] or 0),
                                        float(r["wall_cells_per_D"]), float(r["C_D_change_pct"]),
                                        float(r.get("C_L_change_pct") or 0)))
    return {k: sorted(v) for k, v in out.items()}


def _extrapolated_pair(rows):
    """(order of C_D, C_D, C_L) extrapolated from the last three meshes of a series (for
    the lift, of those whose lift is steady)."""
    n = [r[0] for r in rows]
    p, cd = extrapolate([r[1] for r in rows], n[-1] / n[-2])
    return p, cd, _lift(rows)[1]


def _lift(rows):
    """(order, value, the meshes used) of the lift from the runs whose lift is steady."""
    steady = [r for r in rows if abs(r[5]) <= STEADY_PCT]
    if len(steady) < 3:
        return float("nan"), float("nan"), steady
    p, cl = extrapolate([r[2] for r in steady], steady[-1][0] / steady[-2][0])
    return p, cl, steady


def immersed(ar, re, incidence=0.0):
    """(C_D, |C_L|) of the immersed run at 16 cells/D_eq, or None."""
    name = (f"sphere-Re{re:g}-c16" if ar == 1.0 else f"prolate-Re{re:g}-i{incidence:g}-c16")
    for r in _read(os.path.join(HERE, "results", "runs.csv")):
        if r["name"] == name:
            return float(r["C_D"]), float(r["C_L"])
    return None


def immersed_series(ar, re, incidence=0.0):
    """[(cells/D_eq, C_D, |C_L|)] of the immersed runs of one body, Re and incidence,
    coarsest first."""
    prefix = (f"sphere-Re{re:g}-c" if ar == 1.0 else f"prolate-Re{re:g}-i{incidence:g}-c")
    return sorted((int(r["cpd"]), float(r["C_D"]), float(r["C_L"]))
                  for r in _read(os.path.join(HERE, "results", "runs.csv"))
                  if r["name"].startswith(prefix) and r["name"][len(prefix):].isdigit())


def published(ar, re, incidence=0.0):
    """(name, C_D) of the published reference."""
    if ar == 1.0:
        return "standard curve", references.standard_drag_curve(re)
    return "Zastawny", references.zastawny_drag(re, incidence)


def extrapolated(csv_path):
    """{(ar, Re, incidence): (C_D, C_L)} extrapolated, of the series with three meshes."""
    return {k: _extrapolated_pair(v)[1:] for k, v in series(_read(csv_path)).items()
            if len(v) >= 3}


def _pct(a, b):
    return 100 * (a - b) / b


def torque(csv_path, ar=2.5, incidence=45.0):
    """The body-fitted pitching torque C_T (bodyFitted.py: about the centre, positive
    towards broadside) of one body at one incidence: {Re: dict(meshes [(n_eta, C_T,
    change %)] coarse to fine, used (the meshes of the series), order, value, finest (True
    where the value is the finest mesh's))}. As for the lift, the series leaves out runs
    whose torque changed by more than STEADY_PCT over their last 50 iterations; order and
    extrapolation from the last three (extrapolate)."""
    out = {}
    for r in _read(csv_path):
        if (float(r["ar"]), float(r.get("incidence") or 0)) != (ar, incidence) \
                or r.get("C_T") in (None, ""):
            continue
        out.setdefault(float(r["Re"]), []).append(
            (int(r["n_eta"]), float(r["C_T"]), float(r["C_T_change_pct"])))
    result = {}
    for re, meshes in sorted(out.items()):
        meshes.sort()
        used = [m for m in meshes if abs(m[2]) <= STEADY_PCT]
        if len(used) < 3:
            continue
        p, value = extrapolate([m[1] for m in used], used[-1][0] / used[-2][0])
        result[re] = dict(meshes=meshes, used=used, order=p, value=value,
                          finest=not asymptotic(p))
    return result


def _along_axis(all_series, metrics):
    lines = ["## Body-fitted reference along the axis (axisymmetric)", "",
             "Produced by `validation/finiteReynoldsDrag/bodyFitted.py run` (simpleFoam, no "
             "immersed body, conformal orthogonal meshes of the meridian plane turned into a "
             "wedge, outer boundary 100 D_eq, meshes n = 32, 64, 128). C_D normalised as the "
             "immersed runs; cells/D: the cells along the body's meridian per D_eq.", "",
             "| body | Re | C_D (coarse / medium / fine) | cells/D (fine) | order | "
             "extrapolated | immersed, 16 cells/D | immersed - body-fitted | published | "
             "published - body-fitted |", "|---|---|---|---|---|---|---|---|---|---|"]
    for (ar, re, inc), rows in sorted(all_series.items()):
        if inc != 0 or len(rows) < 3:
            continue
        values = [r[1] for r in rows]
        p, ext, _ = _extrapolated_pair(rows)
        imm = immersed(ar, re)
        ref_name, ref = published(ar, re)
        body = "sphere" if ar == 1.0 else f"prolate AR {ar:g}"
        key = ("sphere" if ar == 1.0 else "prolate") + f"_Re{re:g}"
        d_imm = _pct(imm[0], ext) if imm is not None else float("nan")
        d_ref = _pct(ref, ext)
        metrics[f"body_fitted_{key}_C_D"] = round(ext, 5)
        metrics[f"body_fitted_{key}_order"] = round(p, 2)
        metrics[f"body_fitted_{key}_fine_minus_extrapolated_pct"] = round(_pct(values[-1], ext), 3)
        if imm is not None:
            metrics[f"immersed_vs_body_fitted_pct_{key}_16"] = round(d_imm, 3)
        metrics[f"{'standard_curve' if ar == 1.0 else 'zastawny'}_vs_body_fitted_pct_{key}"] = \
            round(d_ref, 3)
        lines.append(f"| {body} | {re:g} | {' / '.join(f'{v:.4f}' for v in values)} | "
                     f"{rows[-1][3]:.0f} | {p:.2f} | {ext:.4f} | "
                     f"{'-' if imm is None else f'{imm[0]:.4f}'} | {d_imm:+.2f} % | "
                     f"{ref_name} {ref:.4f} | {d_ref:+.2f} % |")
    return lines


def _at_incidence(all_series, metrics):
    lines = ["## Body-fitted reference at incidence (three-dimensional)", "",
             "Produced by `validation/finiteReynoldsDrag/bodyFitted.py run` (the meridian "
             "mesh swept about the axis over the half space z >= 0, z = 0 a symmetry plane "
             "containing the stream; meshes n = 32, 48, 72 over the half meridian, and 108 "
             "for the spheroid at Re 100, n/2 cells over the half turn). Order and "
             "extrapolation from the three finest meshes; where the observed order is outside "
             f"{ASYMPTOTIC_ORDERS[0]:g}-{ASYMPTOTIC_ORDERS[1]:g} the meshes are not in the "
             "asymptotic range and the value is the finest mesh's (marked \"finest\"); "
             "\"last change\": finest minus the mesh before it, relative. The lift's series "
             f"leaves out runs whose lift changed by more than {STEADY_PCT:g} % over their last "
             "50 iterations. The sphere at 90 "
             "degrees to the mesh's axis checks these meshes against the axisymmetric wedge.", "",
             "| body | Re | incidence | C_D on the meshes (coarse to fine) | last change | order | "
             "body-fitted | immersed, 16 cells/D | immersed - body-fitted | reference | "
             "reference - body-fitted | abs(C_L) on the meshes | order | body-fitted | immersed | "
             "immersed - body-fitted | Zastawny's lift | Zastawny - body-fitted |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    wedge = {k[:2]: _extrapolated_pair(v)[1] for k, v in all_series.items()
             if k[2] == 0 and len(v) >= 3}
    for (ar, re, inc), rows in sorted(all_series.items()):
        if inc == 0 or len(rows) < 3:
            continue
        p, cd, cl = _extrapolated_pair(rows)
        body = "sphere" if ar == 1.0 else f"prolate AR {ar:g}"
        key = ("sphere" if ar == 1.0 else "prolate") + f"_Re{re:g}_i{inc:g}"
        metrics[f"body_fitted_{key}_C_D"] = round(cd, 5)
        metrics[f"body_fitted_{key}_order"] = round(p, 2)
        if ar == 1.0:
            ref_name, ref = "axisymmetric wedge", wedge.get((ar, re), float("nan"))
            metrics[f"body_fitted_{key}_vs_wedge_pct"] = round(_pct(cd, ref), 3)
            imm = None
        else:
            ref_name, ref = published(ar, re, inc)
            metrics[f"zastawny_vs_body_fitted_pct_{key}"] = round(_pct(ref, cd), 3)
            imm = immersed(ar, re, inc)
        lift = inc not in (0, 90) and ar != 1.0
        z_lift = references.zastawny_lift(re, inc) if lift else float("nan")
        if lift:
            metrics[f"body_fitted_{key}_C_L"] = round(cl, 5)
            metrics[f"zastawny_lift_vs_body_fitted_pct_{key}"] = round(_pct(z_lift, cl), 3)
        d_imm = d_lift = float("nan")
        if imm is not None:
            d_imm = _pct(imm[0], cd)
            metrics[f"immersed_vs_body_fitted_pct_{key}_16"] = round(d_imm, 3)
            if lift:
                d_lift = _pct(imm[1], cl)
                metrics[f"immersed_vs_body_fitted_lift_pct_{key}_16"] = round(d_lift, 3)
        p_lift, _, lift_rows = _lift(rows)
        finest = "" if asymptotic(p) else " (finest)"
        finest_lift = "" if asymptotic(p_lift) else " (finest)"
        metrics[f"body_fitted_{key}_last_change_pct"] = round(_pct(rows[-1][1], rows[-2][1]), 3)
        lines.append(
            f"| {body} | {re:g} | {inc:g} | {' / '.join(f'{r[1]:.4f}' for r in rows)} | "
            f"{_pct(rows[-1][1], rows[-2][1]):+.2f} % | {p:.2f} | {cd:.4f}{finest} | "
            f"{'-' if imm is None else f'{imm[0]:.4f}'} | "
            f"{'-' if imm is None else f'{d_imm:+.2f} %'} | {ref_name} {ref:.4f} | "
            f"{_pct(ref, cd):+.2f} % | "
            + (f"{' / '.join(f'{r[2]:.4f}' for r in lift_rows)} | {p_lift:.2f} | "
               f"{cl:.4f}{finest_lift} | {'-' if imm is None else f'{imm[1]:.4f}'} | "
               f"{'-' if imm is None else f'{d_lift:+.2f} %'} | "
               f"{z_lift:.4f} | {_pct(z_lift, cl):+.2f} % |" if lift
               else "- | - | - | - | - | - | - |"))
    return lines


def _immersed_resolution(all_series, metrics):
    """The immersed runs made at more than one resolution against the body-fitted drag."""
    lines = []
    for (ar, re, inc), rows in sorted(all_series.items()):
        runs = immersed_series(ar, re, inc)
        if len(rows) < 3 or len(runs) < 2:
            continue
        cd = _extrapolated_pair(rows)[1]
        body = "sphere" if ar == 1.0 else f"prolate AR {ar:g}"
        key = ("sphere" if ar == 1.0 else "prolate") + f"_Re{re:g}_i{inc:g}"
        errors = [_pct(c, cd) for _, c, _ in runs]
        for (cpd, _, _), e in zip(runs, errors):
            metrics[f"immersed_resolution_vs_body_fitted_pct_{key}_c{cpd}"] = round(e, 3)
        lines.append(f"| {body} | {re:g} | {inc:g} | {cd:.4f} | "
                     f"{' / '.join(str(r[0]) for r in runs)} | "
                     f"{' / '.join(f'{r[1]:.4f}' for r in runs)} | "
                     f"{' / '.join(f'{e:+.2f}' for e in errors)} % |")
    if not lines:
        return []
    return (["## The immersed runs at several resolutions against the body-fitted drag", "",
             "| body | Re | incidence | body-fitted | cells/D_eq | immersed C_D | "
             "immersed - body-fitted |", "|---|---|---|---|---|---|---|"] + lines)


def _zastawny_readings(all_series, metrics):
    """The correlation read with Re on D_eq (as physics-references.md states it) and on
    the spheroid's minor diameter 2b, against the body-fitted drags."""
    rows = []
    for (ar, re, inc), series_rows in sorted(all_series.items()):
        if ar == 1.0 or len(series_rows) < 3:
            continue
        cd = _extrapolated_pair(series_rows)[1]
        minor = 1.0 / ar ** (1.0 / 3.0)          # 2b over D_eq
        z_eq, z_minor = references.zastawny_drag(re, inc), references.zastawny_drag(re * minor, inc)
        rows.append((re, inc, cd, z_eq, z_minor))
    if not rows:
        return []
    lines = ["## The Zastawny correlation read with two Reynolds numbers", "",
             "The correlation as quoted (physics-references.md section 6, Re = U D_eq/nu) and the "
             "same coefficients evaluated at Re_2b = U 2b/nu (2b the minor diameter, 0.737 D_eq "
             "for AR 2.5), against the body-fitted drag (extrapolated, or the finest mesh's; C_D normalised by "
             "pi D_eq^2/4 in all three).", "",
             "| Re | incidence | body-fitted | Zastawny(Re) | difference | Zastawny(Re_2b) | "
             "difference |", "|---|---|---|---|---|---|---|"]
    for re, inc, cd, z_eq, z_minor in rows:
        lines.append(f"| {re:g} | {inc:g} | {cd:.4f} | {z_eq:.4f} | {_pct(z_eq, cd):+.1f} % | "
                     f"{z_minor:.4f} | {_pct(z_minor, cd):+.1f} % |")
    metrics["zastawny_vs_body_fitted_max_abs_pct"] = round(
        max(abs(_pct(z, cd)) for _, _, cd, z, _ in rows), 2)
    metrics["zastawny_minor_diameter_re_vs_body_fitted_max_abs_pct"] = round(
        max(abs(_pct(z, cd)) for _, _, cd, _, z in rows), 2)
    return lines


def tables(csv_path):
    """(markdown lines, metrics {key: value})."""
    metrics = {}
    all_series = series(_read(csv_path))
    lines = _along_axis(all_series, metrics)
    if any(k[2] != 0 for k in all_series):
        lines += [""] + _at_incidence(all_series, metrics)
    resolution = _immersed_resolution(all_series, metrics)
    if resolution:
        lines += [""] + resolution
    zastawny = _zastawny_readings(all_series, metrics)
    if zastawny:
        lines += [""] + zastawny
    errors = [abs(v) for k, v in metrics.items()
              if k.startswith("immersed_vs_body_fitted_pct_prolate")]
    if errors:
        metrics["spheroid_max_abs_error_pct_16_vs_body_fitted"] = max(errors)
    along = [abs(v) for k, v in metrics.items()
             if k.startswith("immersed_vs_body_fitted_pct_prolate") and "_i" not in k]
    if along:
        metrics["spheroid_along_max_abs_error_pct_16_vs_body_fitted"] = max(along)
    rows = _read(csv_path)
    worst = max(abs(float(r["C_D_change_pct"])) for r in rows)
    metrics["body_fitted_max_abs_iteration_change_pct"] = float(f"{worst:.2e}")
    its = sorted(int(r["iterations"]) for r in rows)
    lines += ["", f"Each run: SIMPLE iterations until the initial residuals of p and U are below "
              f"1e-10 ({its[0]}-{its[-1]} iterations); the largest change of C_D over a run's "
              f"last 50 iterations: {worst:.1e} %."]
    return lines, metrics
