#!/usr/bin/python3
"""Plot the rigid-body time series of spheroidFoam (an HDF5 file written by bodyOutput).

Usage:
    plotBodies.py FILE.h5 [--bodies NAME ...] [-o OUT.png] [--axis x|y|z] [--fold] [--dpi DPI]

Writes one PNG with four panels against time, one colour a body:
  1. centre components x, y, z (solid, dashed, dotted)
  2. velocity components x, y, z (solid, dashed, dotted)
  3. the angle (degrees) between the body's symmetry axis -- its body x axis, R(q) e_x for the
     orientation quaternion q = (w, x, y, z) -- and the world axis given by --axis (default z);
     0..180 degrees, or 0..90 with --fold (the axis taken as a line: a spheroid looks the same
     turned by 180 degrees)
  4. |hydroForce|, the magnitude of the hydrodynamic force

Options:
  --bodies NAME ...  only these bodies (default: all), in the order given
  -o, --output PNG   output file (default: FILE with the suffix .png)
  --axis x|y|z       world axis of panel 3 (default z)
  --fold             fold the angle of panel 3 into 0..90 degrees
  --dpi DPI          resolution of the PNG (default 120)

The file can be plotted while the run writes it (it is read without HDF5's file lock); a read
that meets an append half-way may fail: run the script again. A row counts when every dataset
has it (the file layout is documented in src/bodyOutput/include/bodyOutput/TimeSeries.hpp).

Needs Debian's python3-h5py, python3-numpy and python3-matplotlib (run with /usr/bin/python3).
Exit status: 0 on success, 1 on an error (file missing or invalid, unknown body), 2 on bad usage.
"""

import argparse
import os
import sys

FORMAT_VERSION = 1
SERIES_DATASETS = ("time", "centre", "velocity", "angularVelocity", "hydroForce", "hydroTorque",
                   "collisionForce", "collisionTorque", "orientation")
AXES = {"x": 0, "y": 1, "z": 2}


class PlotError(Exception):
    """An error reported to the user without a traceback."""


def symmetry_axis(q):
    """World components of the body x axis, R(q) e_x, for quaternions q[..., (w, x, y, z)]
    (normalised here)."""
    import numpy as np
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=-1)


def axis_angle_degrees(q, axis="z", fold=False):
    """Angle (degrees) between R(q) e_x and the world axis 'x', 'y' or 'z'; in 0..180, or 0..90
    with fold=True."""
    import numpy as np
    c = symmetry_axis(q)[..., AXES[axis]]
    if fold:
        c = np.abs(c)
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def read_series(path):
    """(names, time[N], datasets {name: array N x B x k}) of a bodyOutput file."""
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
        if int(np.asarray(version).reshape(-1)[0]) != FORMAT_VERSION:
            raise PlotError(f"{path}: formatVersion {version} is not supported (this script "
                            f"reads version {FORMAT_VERSION})")
        for name in ("bodyNames",) + SERIES_DATASETS:
            if name not in f:
                raise PlotError(f"{path}: dataset '{name}' is missing: not a body time series "
                                "written by bodyOutput")
        names = [n.decode("utf-8") if isinstance(n, bytes) else str(n)
                 for n in f["bodyNames"][()]]
        rows = min(f[name].shape[0] for name in SERIES_DATASETS)
        try:
            time = np.asarray(f["time"][:rows], dtype=float)
            data = {name: np.asarray(f[name][:rows], dtype=float)
                    for name in SERIES_DATASETS if name != "time"}
        except OSError as e:
            raise PlotError(f"{path}: cannot read it ({e}); if a run is writing it, try again") \
                from None
    for name, values in data.items():
        width = 4 if name == "orientation" else 3
        if values.ndim != 3 or values.shape[1:] != (len(names), width):
            raise PlotError(f"{path}: dataset '{name}' must be N x {len(names)} x {width}, "
                            f"got {' x '.join(map(str, values.shape))}")
    return names, time, data


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


def plot(path, output, wanted, axis, fold, dpi):
    names, time, data = read_series(path)
    if time.size == 0:
        raise PlotError(f"{path}: the file has no rows yet")
    chosen = select_bodies(names, wanted, path)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    import numpy as np

    styles = ("-", "--", ":")
    colours = plt.rcParams["axes.prop_cycle"].by_key().get("color", ["C0"])
    fig, panels = plt.subplots(4, 1, sharex=True, figsize=(9, 11), constrained_layout=True)
    angle = axis_angle_degrees(data["orientation"], axis, fold)
    force = np.linalg.norm(data["hydroForce"], axis=-1)
    for n, b in enumerate(chosen):
        colour = colours[n % len(colours)]
        for k in range(3):
            panels[0].plot(time, data["centre"][:, b, k], styles[k], color=colour, lw=1)
            panels[1].plot(time, data["velocity"][:, b, k], styles[k], color=colour, lw=1)
        panels[2].plot(time, angle[:, b], color=colour, lw=1, label=names[b])
        panels[3].plot(time, force[:, b], color=colour, lw=1)

    panels[0].set_ylabel("centre")
    panels[1].set_ylabel("velocity")
    panels[2].set_ylabel(f"angle(body x, {axis}) [deg]")
    panels[3].set_ylabel("|hydroForce|")
    panels[3].set_xlabel("time")
    if fold:
        panels[2].set_ylim(-2, 92)
        panels[2].set_yticks([0, 30, 60, 90])
    else:
        panels[2].set_ylim(-4, 184)
        panels[2].set_yticks([0, 45, 90, 135, 180])
    components = [Line2D([], [], color="0.3", ls=s, lw=1) for s in styles]
    panels[0].legend(components, ["x", "y", "z"], loc="best", fontsize="small", ncol=3)
    panels[1].legend(components, ["x", "y", "z"], loc="best", fontsize="small", ncol=3)
    if len(chosen) <= 10:
        panels[2].legend(loc="best", fontsize="small")
    for p in panels:
        p.grid(True, lw=0.3)
    fig.suptitle(f"{os.path.basename(path)}: {len(chosen)} of {len(names)} "
                 f"{'body' if len(names) == 1 else 'bodies'}, {time.size} rows, "
                 f"t = {time[0]:g} .. {time[-1]:g}")
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
                    "centre, velocity, symmetry-axis angle and |hydroForce| against time.",
        epilog="See the docstring of this script for details.")
    parser.add_argument("file", metavar="FILE.h5", help="time series written by bodyOutput")
    parser.add_argument("--bodies", nargs="+", metavar="NAME", default=[],
                        help="only these bodies (default: all)")
    parser.add_argument("-o", "--output", metavar="OUT.png",
                        help="output PNG (default: FILE with the suffix .png)")
    parser.add_argument("--axis", choices=sorted(AXES), default="z",
                        help="world axis for the angle of the symmetry axis (default z)")
    parser.add_argument("--fold", action="store_true",
                        help="fold the angle into 0..90 degrees")
    parser.add_argument("--dpi", type=int, default=120, help="PNG resolution (default 120)")
    args = parser.parse_args(argv)
    if args.dpi <= 0:
        parser.error("--dpi must be > 0")
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
        plot(args.file, output, args.bodies, args.axis, args.fold, args.dpi)
    except PlotError as e:
        print(f"plotBodies.py: error: {e}", file=sys.stderr)
        return 1
    print(f"plotBodies.py: wrote {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
