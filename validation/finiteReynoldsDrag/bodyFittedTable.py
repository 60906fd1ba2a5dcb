"""The body-fitted sections of validation/finiteReynoldsDrag's results/table.md and their
metrics: the body-fitted drag and lift on three meshes (results/bodyFitted.csv), their
extrapolation, and the immersed runs (results/runs.csv, 16 cells/D_eq) and the published
references against them."""
import math
import os

import references

HERE = os.path.dirname(os.path.abspath(__file__))


def _read(path):
    import csv
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def extrapolate(values, ratio=2.0):
    """(observed order, extrapolated value) from values on meshes refined by ratio each
    time (coarse to fine); the order from the last three, the extrapolation Richardson's."""
    f1, f2, f3 = values[-3:]
    if (f1 - f2) * (f2 - f3) <= 0:
        return float("nan"), f3
    p = math.log(abs(f1 - f2) / abs(f2 - f3)) / math.log(ratio)
    return p, f3 + (f3 - f2) / (ratio ** p - 1.0)


def series(rows):
    """{(ar, Re, incidence): [(n_eta, C_D, C_L, cells per D at the wall, change %), ...]}
    sorted by n_eta."""
    out = {}
    for r in rows:
        key = (float(r["ar"]), float(r["Re"]), float(r.get("incidence") or 0))
        out.setdefault(key, []).append((int(r["n_eta"]), float(r["C_D"]), float(r["C_L"] or 0),
                                        float(r["wall_cells_per_D"]), float(r["C_D_change_pct"])))
    return {k: sorted(v) for k, v in out.items()}


def _extrapolated_pair(rows):
    """(order of C_D, C_D, C_L) extrapolated from the last three meshes of a series."""
    n = [r[0] for r in rows]
    ratio = n[-1] / n[-2]
    p, cd = extrapolate([r[1] for r in rows], ratio)
    _, cl = extrapolate([r[2] for r in rows], ratio)
    return p, cd, cl


def immersed(ar, re, incidence=0.0):
    """(C_D, |C_L|) of the immersed run at 16 cells/D_eq, or None."""
    name = (f"sphere-Re{re:g}-c16" if ar == 1.0 else f"prolate-Re{re:g}-i{incidence:g}-c16")
    for r in _read(os.path.join(HERE, "results", "runs.csv")):
        if r["name"] == name:
            return float(r["C_D"]), float(r["C_L"])
    return None


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
             "containing the stream; meshes n = 32, 48, 72 over the half meridian, n/2 "
             "cells over the half turn). The sphere at 90 degrees to the mesh's axis checks "
             "these meshes against the axisymmetric wedge.", "",
             "| body | Re | incidence | C_D (coarse / medium / fine) | order | extrapolated | "
             "immersed, 16 cells/D | immersed - body-fitted | reference | reference - "
             "body-fitted | abs(C_L) (coarse / medium / fine) | extrapolated | immersed | "
             "immersed - body-fitted |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
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
        if lift:
            metrics[f"body_fitted_{key}_C_L"] = round(cl, 5)
        d_imm = d_lift = float("nan")
        if imm is not None:
            d_imm = _pct(imm[0], cd)
            metrics[f"immersed_vs_body_fitted_pct_{key}_16"] = round(d_imm, 3)
            if lift:
                d_lift = _pct(imm[1], cl)
                metrics[f"immersed_vs_body_fitted_lift_pct_{key}_16"] = round(d_lift, 3)
        lines.append(
            f"| {body} | {re:g} | {inc:g} | {' / '.join(f'{r[1]:.4f}' for r in rows)} | "
            f"{p:.2f} | {cd:.4f} | {'-' if imm is None else f'{imm[0]:.4f}'} | "
            f"{'-' if imm is None else f'{d_imm:+.2f} %'} | {ref_name} {ref:.4f} | "
            f"{_pct(ref, cd):+.2f} % | "
            + (f"{' / '.join(f'{r[2]:.4f}' for r in rows)} | {cl:.4f} | "
               f"{'-' if imm is None else f'{imm[1]:.4f}'} | "
               f"{'-' if imm is None else f'{d_lift:+.2f} %'} |" if lift else "- | - | - | - |"))
    return lines


def tables(csv_path):
    """(markdown lines, metrics {key: value})."""
    metrics = {}
    all_series = series(_read(csv_path))
    lines = _along_axis(all_series, metrics)
    if any(k[2] != 0 for k in all_series):
        lines += [""] + _at_incidence(all_series, metrics)
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
    lines += ["", f"Each run: {rows[0]['iterations']} SIMPLE iterations; the largest change of "
              f"C_D over its last 100 iterations: {worst:.1e} %."]
    return lines, metrics
