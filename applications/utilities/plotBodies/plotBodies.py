#!/usr/bin/python3
"""Plot the rigid-body time series of spheroidFoam (an HDF5 file written by bodyOutput).

Usage:
    plotBodies.py FILE.h5 [--bodies NAME ...] [-o OUT.png] [--axis x|y|z] [--fold]
                  [--side-view [x|y|z|auto]] [--outline-every DT] [--snapshots N] [--floor Z]
                  [--max-named N] [--title TEXT] [--dpi DPI]

Writes one PNG. Its title names the case (the folder holding postProcessing/, else the file)
and its bodies, from their semi-axes (a, b, c along the body x, y, z axes): "sedimentingSpheroid:
1 prolate spheroid, a/b = 2.5, equal-volume D = 6 mm"; a second line gives the time span. The
left column has four panels against time t (s):
  1. centre x, y, z (solid, dashed, dotted), in mm (in m when a coordinate exceeds 1 m)
  2. velocity x, y, z (m/s)
  3. the angle (degrees) between the body's symmetry axis -- its body x axis, R(q) e_x for the
     orientation quaternion q = (w, x, y, z) -- and the world axis given by --axis (default z);
     0..180 degrees, or 0..90 with --fold (the axis taken as a line: a spheroid looks the same
     turned by 180 degrees; with --axis along gravity, 90 = broadside-on)
  4. |hydroForce|, the magnitude of the hydrodynamic force (N)
Up to --max-named bodies (default 8) are drawn one by one, one colour a body, named in the
legend of panel 2. With more (a fluidised bed), each panel shows the mean over the bodies and a
band from the smallest to the largest value, and panels 1 and 2 show only the component along
--axis (the bed's height and vertical velocity): 64 lines or names cannot be read.

--side-view adds a right column: the bodies seen from the side, in the vertical plane spanned by
--axis (up) and a horizontal world axis (x, y or z; auto: of the two, the one along which the
centres spread most), at equal scale. Each outline is the exact silhouette of the spheroid under
orthographic projection: for the ellipsoid x^T A x = 1, A = R diag(a^-2, b^-2, c^-2) R^T, the
silhouette on the plane is the ellipse p^T S p = 1 with S the Schur complement of A's entry along
the viewing direction (S = A_pp - A_pn A_nn^-1 A_np); a line through it marks the symmetry axis.
  - up to --max-named bodies: each body's path, and its outline every --outline-every seconds
    (default 0.2, from the first row, and at the last row), labelled with its time for one body
  - more bodies: --snapshots panels (default 4, evenly spaced from the first to the last row),
    each with every body's outline at that time, filled with a colour for its depth (the
    coordinate along the viewing direction; the nearer bodies drawn last)
--floor Z draws the floor (vertical coordinate Z, m) as a hatched line.

Options:
  --bodies NAME ...     only these bodies (default: all), in the order given
  -o, --output PNG      output file (default: FILE with the suffix .png)
  --axis x|y|z          the vertical: world axis of panel 3 and up in the side view (default z)
  --fold                fold the angle of panel 3 into 0..90 degrees
  --side-view [AXIS]    add the side view; AXIS its horizontal world axis (default auto; an
                        option, not FILE.h5, must follow a --side-view without AXIS)
  --outline-every DT    seconds between the outlines of the side view (default 0.2)
  --snapshots N         side-view panels when the bodies are summarised (default 4)
  --floor Z             vertical coordinate (m) of the floor drawn in the side view
  --max-named N         at most this many bodies drawn one by one (default 8)
  --title TEXT          the title's first line (default: case and bodies, as above)
  --dpi DPI             resolution of the PNG (default 120)

The file can be plotted while the run writes it (it is read without HDF5's file lock); a read
that meets an append half-way may fail: run the script again. A row counts when every dataset
has it (the file layout is documented in src/bodyOutput/include/bodyOutput/TimeSeries.hpp).

Needs Debian's python3-h5py, python3-numpy and python3-matplotlib (run with /usr/bin/python3).
Exit status: 0 on success, 1 on an error (file missing or invalid, unknown body), 2 on bad usage.
"""

import argparse
import math
import os
import sys

FORMAT_VERSIONS = (1, 2)  # 2 adds unwrappedCentre
SERIES_DATASETS = ("time", "centre", "velocity", "angularVelocity", "hydroForce", "hydroTorque",
                   "collisionForce", "collisionTorque", "orientation")
AXES = {"x": 0, "y": 1, "z": 2}


class PlotError(Exception):
    """An error reported to the user without a traceback."""


# ---- geometry

def rotation(q):
    """Rotation matrices R(q) (body to world), shape [..., 3, 3], of quaternions q[..., (w, x, y,
    z)] (normalised here)."""
    import numpy as np
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


def symmetry_axis(q):
    """World components of the body x axis, R(q) e_x, for quaternions q[..., (w, x, y, z)]
    (normalised here)."""
    return rotation(q)[..., :, 0]


def axis_angle_degrees(q, axis="z", fold=False):
    """Angle (degrees) between R(q) e_x and the world axis 'x', 'y' or 'z'; in 0..180, or 0..90
    with fold=True."""
    import numpy as np
    c = symmetry_axis(q)[..., AXES[axis]]
    if fold:
        c = np.abs(c)
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def silhouette_matrix(q, semi_axes, h, v):
    """2 x 2 matrix S of the outline p^T S p = 1 (p in the coordinates of the world axes h, v,
    relative to the centre) of the ellipsoid with semi-axes (a, b, c) along the body axes and
    orientation q, seen along the third world axis: the Schur complement of A's entry along the
    viewing direction, A = R diag(a^-2, b^-2, c^-2) R^T."""
    import numpy as np
    R = rotation(q)
    A = R @ np.diag(1.0 / np.asarray(semi_axes, dtype=float) ** 2) @ R.T
    n = 3 - h - v
    A = A[np.ix_([h, v, n], [h, v, n])]
    return A[:2, :2] - np.outer(A[:2, 2], A[2, :2]) / A[2, 2]


def outline(centre, q, semi_axes, h, v, points=73):
    """Outline (2 x points, world units) of a body seen along the third world axis, in the plane
    of the world axes h (horizontal) and v (vertical)."""
    import numpy as np
    S = silhouette_matrix(q, semi_axes, h, v)
    L = np.linalg.cholesky(np.linalg.inv(S))  # p = L (cos, sin) has p^T S p = 1
    angle = np.linspace(0, 2 * math.pi, points)
    return np.asarray(centre)[[h, v], None] + L @ np.stack([np.cos(angle), np.sin(angle)])


def shape_summary(semi_axes):
    """'1 prolate spheroid, a/b = 2.5, equal-volume D = 6 mm' for the semi-axes [B x 3] (m; a
    along the body x axis, a spheroid's symmetry axis): the bodies grouped by shape, with the
    range of D in a group of several sizes; groups joined by '; '."""
    import numpy as np

    def same(x, y):
        return abs(x - y) <= 1e-6 * max(x, y)

    groups = {}
    for a, b, c in np.asarray(semi_axes, dtype=float):
        if same(a, b) and same(b, c):
            shape = ("sphere", "")
        elif same(b, c):
            shape = (("prolate" if a > b else "oblate") + " spheroid", f", a/b = {a / b:.3g}")
        else:
            shape = ("ellipsoid", f", a:b:c = 1:{b / a:.3g}:{c / a:.3g}")
        groups.setdefault(shape, []).append(2 * (a * b * c) ** (1 / 3))
    parts = []
    for (word, ratio), d in groups.items():
        scale, unit = length_scale(np.array(d))
        size = " to ".join(sorted({f"{x * scale:.3g}" for x in (min(d), max(d))}, key=float))
        parts.append(f"{len(d)} {word}{'s' if len(d) > 1 else ''}{ratio}, "
                     f"{'D' if word == 'sphere' else 'equal-volume D'} = {size} {unit}")
    return "; ".join(parts)


# ---- reading

def read_series(path):
    """(names, time[N], datasets {name: array N x B x k}, semi-axes B x 3 or None) of a
    bodyOutput file."""
    import h5py
    import numpy as np
    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file")
    if os.path.isdir(path):
        raise PlotError(f"{path}: is a folder, not an HDF5 file")
    try:
        try:
            f = h5py.File(path, "r", locking=False)  # readable while a run holds its lock
        except TypeError:  # h5py without the locking option
            f = h5py.File(path, "r")
    except OSError as e:
        raise PlotError(f"{path}: cannot open it as an HDF5 file ({e})") from None
    with f:
        version = f.attrs.get("formatVersion")
        if version is None:
            raise PlotError(f"{path}: no attribute 'formatVersion': not a body time series "
                            "written by bodyOutput")
        version = int(np.asarray(version).reshape(-1)[0])
        if version not in FORMAT_VERSIONS:
            raise PlotError(f"{path}: formatVersion {version} is not supported (this script "
                            f"reads versions {', '.join(map(str, FORMAT_VERSIONS))})")
        datasets = SERIES_DATASETS + (("unwrappedCentre",) if version >= 2 else ())
        for name in ("bodyNames",) + datasets:
            if name not in f:
                raise PlotError(f"{path}: dataset '{name}' is missing: not a body time series "
                                "written by bodyOutput")
        names = [n.decode("utf-8") if isinstance(n, bytes) else str(n)
                 for n in f["bodyNames"][()]]
        rows = min(f[name].shape[0] for name in datasets)
        try:
            time = np.asarray(f["time"][:rows], dtype=float)
            data = {name: np.asarray(f[name][:rows], dtype=float)
                    for name in datasets if name != "time"}
            semi_axes = np.asarray(f["semiAxes"][()], dtype=float) if "semiAxes" in f else None
        except OSError as e:
            raise PlotError(f"{path}: cannot read it ({e}); if a run is writing it, try again") \
                from None
    for name, values in data.items():
        width = 4 if name == "orientation" else 3
        if values.ndim != 3 or values.shape[1:] != (len(names), width):
            raise PlotError(f"{path}: dataset '{name}' must be N x {len(names)} x {width}, "
                            f"got {' x '.join(map(str, values.shape))}")
    # the path a body took: in a periodic box the centre jumps by a period at each wrap
    if "unwrappedCentre" in data:
        data["centre"] = data.pop("unwrappedCentre")
    if semi_axes is not None and (semi_axes.shape != (len(names), 3) or not (semi_axes > 0).all()):
        semi_axes = None  # the title and the side view need positive a, b, c for each body
    return names, time, data, semi_axes


def select_bodies(names, wanted, path):
    """Indices of the wanted body names (all if wanted is empty)."""
    if not wanted:
        return list(range(len(names)))
    unknown = [w for w in wanted if w not in names]
    if unknown:
        listed = ", ".join(repr(n) for n in names[:50]) + (", ..." if len(names) > 50 else "")
        raise PlotError(f"{path}: no body named {', '.join(repr(u) for u in unknown)}; "
                        f"the file's {len(names)} bodies are: {listed}")
    seen = []
    for w in wanted:
        if w not in seen:
            seen.append(w)
    return [names.index(w) for w in seen]


def case_name(path):
    """The case folder of CASE/postProcessing/<name>/FILE.h5, else the file's name."""
    folder = os.path.dirname(os.path.abspath(path))
    if os.path.basename(os.path.dirname(folder)) == "postProcessing":
        return os.path.basename(os.path.dirname(os.path.dirname(folder)))
    return os.path.basename(path)


# ---- drawing

def length_scale(values):
    """(factor, unit) for lengths in metres: mm unless a value exceeds 1 m."""
    import numpy as np
    finite = np.abs(values[np.isfinite(values)])
    return (1.0, "m") if finite.size and finite.max() > 1 else (1e3, "mm")


def plot_time_series(panels, time, data, chosen, names, axis, fold, summarise):
    """The four panels against time: bodies one by one, or their mean and range."""
    import numpy as np
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    k = AXES[axis]
    scale, unit = length_scale(data["centre"][:, chosen])
    series = [data["centre"][:, chosen] * scale, data["velocity"][:, chosen],
              axis_angle_degrees(data["orientation"][:, chosen], axis, fold),
              np.linalg.norm(data["hydroForce"][:, chosen], axis=-1)]
    angle_label = f"angle: symmetry axis\nto {axis} (degrees)"
    if summarise:
        series[0], series[1] = series[0][..., k], series[1][..., k]
        labels = [f"centre {axis} ({unit})", f"velocity {axis} (m/s)", angle_label,
                  "|hydrodynamic force| (N)"]
        for p, values in zip(panels, series):
            p.fill_between(time, values.min(axis=1), values.max(axis=1), color="C0", alpha=0.25,
                           lw=0)
            p.plot(time, values.mean(axis=1), color="C0", lw=1.2)
        panels[0].legend([Line2D([], [], color="C0", lw=1.2), Patch(color="C0", alpha=0.25)],
                         [f"mean of the {len(chosen)} bodies", "smallest to largest"],
                         loc="best", fontsize="small")
    else:
        styles = ("-", "--", ":")
        colours = [f"C{n % 10}" for n in range(len(chosen))]
        for n, colour in enumerate(colours):
            for j in range(3):
                panels[0].plot(time, series[0][:, n, j], styles[j], color=colour, lw=1)
                panels[1].plot(time, series[1][:, n, j], styles[j], color=colour, lw=1)
            panels[2].plot(time, series[2][:, n], color=colour, lw=1)
            panels[3].plot(time, series[3][:, n], color=colour, lw=1)
        labels = [f"centre ({unit})", "velocity (m/s)", angle_label, "|hydrodynamic force| (N)"]
        components = [Line2D([], [], color="0.3", ls=s, lw=1) for s in styles]
        panels[0].legend(components, ["x", "y", "z"], loc="best", fontsize="small", ncol=3)
        panels[1].legend([Line2D([], [], color=c, lw=1.5) for c in colours],
                         [names[b] for b in chosen], loc="best", fontsize="small",
                         ncol=1 + len(chosen) // 5)
    for p, label in zip(panels, labels):
        p.set_ylabel(label)
        p.grid(True, lw=0.3)
    panels[-1].set_xlabel("time t (s)")
    panels[2].set_ylim(*((-2, 92) if fold else (-4, 184)))
    panels[2].set_yticks([0, 30, 60, 90] if fold else [0, 45, 90, 135, 180])


def horizontal_axis(choice, vertical, centres):
    """The horizontal world axis of the side view: choice, or (auto) the one of the two axes
    other than the vertical along which the centres spread most."""
    import numpy as np
    if choice != "auto":
        return AXES[choice]
    others = [k for k in range(3) if k != vertical]
    spread = [np.ptp(centres[..., k]) if centres.size else 0.0 for k in others]
    return others[int(np.argmax(spread))]


def draw_floor(ax, floor, scale):
    """The floor: a line at the vertical coordinate floor (m), hatched below."""
    if floor is None:
        return
    y = floor * scale
    low, high = ax.get_ylim()
    depth = 0.04 * (high - low)
    ax.axhspan(y - depth, y, facecolor="none", edgecolor="0.45", hatch="///", lw=0)
    ax.axhline(y, color="0.2", lw=1.5)
    ax.set_ylim(min(low, y - depth), high)


def body_outline(ax, centre, q, axes, h, v, scale, **style):
    """Fill one body's outline and draw its symmetry axis (projected) through it."""
    import numpy as np
    try:
        p = outline(centre, q, axes, h, v) * scale
    except np.linalg.LinAlgError:  # a degenerate orientation (e.g. a zero quaternion)
        return None
    if not np.all(np.isfinite(p)):
        return None
    ax.fill(p[0], p[1], **style)
    tip = symmetry_axis(q) * axes[0]
    ends = (np.asarray(centre)[[h, v], None] + np.outer(tip[[h, v]], [-1, 1])) * scale
    ax.plot(ends[0], ends[1], color=style.get("edgecolor", "k"), lw=0.6)
    return p


def outline_rows(time, every):
    """Rows of the outlines: the first at or after each multiple of `every` from the first row's
    time, and the last row."""
    import numpy as np
    targets = np.arange(time[0], time[-1] + 1e-12, every)
    rows = np.searchsorted(time, targets - 1e-9 * max(every, 1e-300))
    return sorted(set(int(r) for r in rows if r < len(time)) | {len(time) - 1})


def side_view_paths(ax, time, c, q, axes, labels, h, v, scale, every):
    """Each body's path and its outline every `every` seconds (one body: with their times)."""
    import numpy as np
    # a time label takes about 2.5 % of the panel's height
    spacing = 0.025 * (np.ptp(c[..., v]) + 2 * float(axes.max()))
    for m, label in enumerate(labels):
        colour = f"C{m % 10}"
        ax.plot(c[:, m, h] * scale, c[:, m, v] * scale, color=colour, lw=1,
                label=label if len(labels) > 1 else None)
        last = math.inf
        for r in outline_rows(time, every):
            p = body_outline(ax, c[r, m], q[r, m], axes[m], h, v, scale, facecolor=colour,
                             alpha=0.15, edgecolor=colour, lw=0.8)
            # the times beside one body's outlines, left out where they would overlap
            if len(labels) == 1 and p is not None and abs(last - c[r, m, v]) > spacing:
                ax.annotate(f"{time[r]:.3g} s", (p[0].max(), c[r, m, v] * scale), xytext=(3, 0),
                            textcoords="offset points", fontsize=7, va="center", color="0.25")
                last = c[r, m, v]
    if len(labels) > 1:
        ax.legend(loc="best", fontsize="small")
    ax.set_title(f"side view: path, outline every {every:g} s", fontsize="medium")


def snapshot_grid(count, width, height, size):
    """(rows, columns) of count panels of data extent (width, height) in a region size (inches)
    that draws them largest."""
    def scale(columns):
        rows = math.ceil(count / columns)
        return min((size[0] - 1.5) / columns / width, (size[1] - 1.0) / rows / height)
    columns = max(range(1, count + 1), key=lambda k: (scale(k), -k))
    return math.ceil(count / columns), columns


def side_view_snapshots(fig, time, c, q, axes, h, v, scale, unit, snapshots, extent, size):
    """Panels of every body's outline at `snapshots` times, coloured by depth; the panels."""
    import matplotlib
    import numpy as np
    n = 3 - h - v
    rows = sorted(set(int(np.argmin(np.abs(time - t)))
                      for t in np.linspace(time[0], time[-1], min(snapshots, len(time)))))
    columns = snapshot_grid(len(rows), extent[0], extent[1], size)[1]
    panels = fig.subplots(math.ceil(len(rows) / columns), columns, sharex=True, sharey=True,
                          squeeze=False).ravel()
    for ax in panels[len(rows):]:
        ax.set_visible(False)
    panels = panels[:len(rows)]
    for i, ax in enumerate(panels):
        # axis labels on the left column and on the lowest panel of each column
        ax.tick_params(labelbottom=i + columns >= len(rows))
        ax.set_xlabel(f"{'xyz'[h]} ({unit})" if i + columns >= len(rows) else "")
        ax.set_ylabel(f"{'xyz'[v]} ({unit})" if i % columns == 0 else "")
    depth = c[..., n] * scale
    norm = matplotlib.colors.Normalize(depth.min(), depth.max() + 1e-12)
    colours = matplotlib.cm.viridis
    # the viewer sits along h x v (h right, v up): the bodies farthest from it drawn first
    sign = float(np.cross(np.eye(3)[h], np.eye(3)[v])[n])
    for ax, r in zip(panels, rows):
        for m in np.argsort(sign * depth[r]):
            body_outline(ax, c[r, m], q[r, m], axes[m], h, v, scale, lw=0.5, alpha=0.85,
                         facecolor=colours(norm(depth[r, m])), edgecolor="0.15")
        ax.set_title(f"t = {time[r]:.3g} s", fontsize="medium")
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=colours), ax=list(panels),
                       shrink=0.6)
    bar.set_label(f"{'xyz'[n]} ({unit}), the depth: seen looking along "
                  f"{'-' if sign > 0 else '+'}{'xyz'[n]}")
    fig.suptitle(f"side view: every body at {len(rows)} times", fontsize="medium")
    return panels


def plot_side_view(fig, size, time, data, semi_axes, chosen, names, vertical, horizontal, every,
                   snapshots, floor, summarise):
    """The side view in fig (a subfigure of size inches): paths and outlines of the bodies, or
    snapshots of every body when they are summarised; equal scale, the floor drawn."""
    c = data["centre"][:, chosen]
    q = data["orientation"][:, chosen]
    axes = semi_axes[chosen]
    v = vertical
    h = horizontal_axis(horizontal, v, c)
    scale, unit = length_scale(c)
    reach = float(axes.max())
    low, high = (c[..., v].min() - reach) * scale, (c[..., v].max() + reach) * scale
    left, right = (c[..., h].min() - reach) * scale, (c[..., h].max() + reach) * scale
    if floor is not None:
        low = min(low, floor * scale)
    low -= 0.02 * (high - low)
    if summarise:
        panels = side_view_snapshots(fig, time, c, q, axes, h, v, scale, unit, snapshots,
                                     (right - left, high - low), size)
    else:
        panels = [fig.subplots(1, 1)]
        side_view_paths(panels[0], time, c, q, axes, [names[b] for b in chosen], h, v, scale,
                        every)
    for ax in panels:
        ax.set_xlim(left, right)
        ax.set_ylim(low, high)
        draw_floor(ax, floor, scale)
        # shared snapshot axes keep their limits: equal scale by the panel's shape
        ax.set_aspect("equal", adjustable="box" if summarise else "datalim")
        ax.grid(True, lw=0.3)
    if not summarise:
        panels[0].set_xlabel(f"{'xyz'[h]} ({unit})")
        panels[0].set_ylabel(f"{'xyz'[v]} ({unit})")


def plot(path, output, wanted, axis, fold, dpi, side_view=None, every=0.2, snapshots=4,
         floor=None, max_named=8, title=None):
    names, time, data, semi_axes = read_series(path)
    if time.size == 0:
        raise PlotError(f"{path}: the file has no rows yet")
    chosen = select_bodies(names, wanted, path)
    if side_view and semi_axes is None:
        raise PlotError(f"{path}: no valid dataset 'semiAxes': the side view needs the bodies' "
                        "semi-axes")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    summarise = len(chosen) > max_named
    size = (14 if side_view else 9, 11)
    fig = plt.figure(figsize=size, layout="constrained")
    if side_view:
        ratios = (1.7, 1)
        left, right = fig.subfigures(1, 2, width_ratios=ratios)
    else:
        left, right = fig, None
    panels = left.subplots(4, 1, sharex=True)
    plot_time_series(panels, time, data, chosen, names, axis, fold, summarise)
    if side_view:
        plot_side_view(right, (size[0] * ratios[1] / sum(ratios), size[1]), time, data, semi_axes,
                       chosen, names, AXES[axis], side_view, every, snapshots, floor, summarise)
    heading = title or (f"{case_name(path)}: " + (shape_summary(semi_axes) if semi_axes is not None
                        else f"{len(names)} {'body' if len(names) == 1 else 'bodies'}"))
    shown = "" if len(chosen) == len(names) else f"; {len(chosen)} of {len(names)} bodies shown"
    fig.suptitle(f"{heading}\nt = {time[0]:.4g} to {time[-1]:.4g} s, {time.size} rows{shown}")
    folder = os.path.dirname(os.path.abspath(output))
    os.makedirs(folder, exist_ok=True)
    try:
        fig.savefig(output, dpi=dpi)
    except OSError as e:
        raise PlotError(f"{output}: cannot write it ({e})") from None
    finally:
        plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="plotBodies.py",
        description="Plot the rigid-body time series of spheroidFoam (HDF5 from bodyOutput): "
                    "centre, velocity, symmetry-axis angle and |hydroForce| against time, and "
                    "optionally a side view of the paths with the bodies' outlines.",
        epilog="See the docstring of this script for details.")
    parser.add_argument("file", metavar="FILE.h5", help="time series written by bodyOutput")
    parser.add_argument("--bodies", nargs="+", metavar="NAME", default=[],
                        help="only these bodies (default: all)")
    parser.add_argument("-o", "--output", metavar="OUT.png",
                        help="output PNG (default: FILE with the suffix .png)")
    parser.add_argument("--axis", choices=sorted(AXES), default="z",
                        help="the vertical: world axis for the angle of the symmetry axis and up "
                             "in the side view (default z)")
    parser.add_argument("--fold", action="store_true",
                        help="fold the angle into 0..90 degrees")
    parser.add_argument("--side-view", nargs="?", const="auto", choices=sorted(AXES) + ["auto"],
                        metavar="AXIS", help="add a side view; AXIS is its horizontal world axis "
                                             "(x, y, z or auto, the default)")
    parser.add_argument("--outline-every", type=float, default=0.2, metavar="DT",
                        help="seconds between outlines in the side view (default 0.2)")
    parser.add_argument("--snapshots", type=int, default=4, metavar="N",
                        help="side-view panels when the bodies are summarised (default 4)")
    parser.add_argument("--floor", type=float, metavar="Z",
                        help="vertical coordinate (m) of the floor drawn in the side view")
    parser.add_argument("--max-named", type=int, default=8, metavar="N",
                        help="at most N bodies drawn one by one; more are summarised by their "
                             "mean and range (default 8)")
    parser.add_argument("--title", help="first line of the title (default: case and bodies)")
    parser.add_argument("--dpi", type=int, default=120, help="PNG resolution (default 120)")
    args = parser.parse_args(argv)
    if args.dpi <= 0:
        parser.error("--dpi must be > 0")
    if not args.outline_every > 0:
        parser.error("--outline-every must be > 0")
    if args.snapshots < 1 or args.max_named < 0:
        parser.error("--snapshots must be >= 1 and --max-named >= 0")
    if args.side_view == args.axis:
        parser.error(f"--side-view {args.side_view}: the horizontal axis must differ from "
                     f"--axis {args.axis}")
    output = args.output or os.path.splitext(args.file)[0] + ".png"
    try:
        import h5py  # noqa: F401  (checked here for a clear message)
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        print(f"plotBodies.py: error: {e}; install Debian's python3-h5py, python3-numpy and "
              "python3-matplotlib and run with /usr/bin/python3", file=sys.stderr)
        return 1
    try:
        plot(args.file, output, args.bodies, args.axis, args.fold, args.dpi, args.side_view,
             args.outline_every, args.snapshots, args.floor, args.max_named, args.title)
    except PlotError as e:
        print(f"plotBodies.py: error: {e}", file=sys.stderr)
        return 1
    print(f"plotBodies.py: wrote {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
