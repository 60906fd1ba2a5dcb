"""Check the VTK surfaces of a case against its body time series.

    checkSurfaceSeries.py CASE NAME=TIME [NAME=TIME ...]

postProcessing/immersedBodies/surfaces.vtk.series must list exactly the files
surfaces/surfaces_NAME.vtk at TIME, in the order given. Each file must be a
complete binary legacy-VTK polydata (big-endian float points and normals, int
triangles and body index, nothing after the normals), and each body's points
must be centred (their mean: the icosphere's points are symmetric) on the body's
centre in bodies.h5 at that time, to float precision. Exit status 1 on the
first mismatch, with a message.
"""
import json
import os
import sys

import h5py
import numpy as np


def fail(message):
    sys.exit(f"checkSurfaceSeries: {message}")


def readVtk(path):
    """points (n, 3), triangles (m, 3), body (m,) of a binary legacy-VTK polydata"""
    with open(path, "rb") as f:
        data = f.read()
    pos = 0

    def line():
        nonlocal pos
        end = data.index(b"\n", pos)
        text = data[pos:end].decode("ascii")
        pos = end + 1
        return text

    def block(dtype, count):
        nonlocal pos
        values = np.frombuffer(data, dtype=dtype, count=count, offset=pos)
        pos += 4 * count
        if line() != "":
            fail(f"{path}: no newline after a binary block at byte {pos}")
        return values

    header = [line() for _ in range(4)]
    if header[0] != "# vtk DataFile Version 3.0" or header[2:] != ["BINARY", "DATASET POLYDATA"]:
        fail(f"{path}: not a binary legacy-VTK polydata: {header}")
    word, n, kind = line().split()
    if (word, kind) != ("POINTS", "float"):
        fail(f"{path}: expected POINTS n float")
    points = block(">f4", 3 * int(n)).reshape(-1, 3).astype(float)
    word, m, size = line().split()
    if word != "POLYGONS" or int(size) != 4 * int(m):
        fail(f"{path}: expected POLYGONS m 4m")
    polygons = block(">i4", int(size)).reshape(-1, 4)
    if (polygons[:, 0] != 3).any() or polygons[:, 1:].min(initial=0) < 0 \
            or polygons[:, 1:].max(initial=-1) >= len(points):
        fail(f"{path}: bad triangles")
    if line() != f"CELL_DATA {m}" or line() != "SCALARS body int 1" \
            or line() != "LOOKUP_TABLE default":
        fail(f"{path}: bad cell data header")
    body = block(">i4", int(m))
    if line() != f"POINT_DATA {n}" or line() != "NORMALS Normals float":
        fail(f"{path}: bad point data header")
    block(">f4", 3 * int(n))
    if pos != len(data):
        fail(f"{path}: {len(data) - pos} bytes after the normals")
    return points, polygons[:, 1:], body


def main():
    if len(sys.argv) < 3:
        fail(__doc__)
    case = sys.argv[1]
    expected = []
    for arg in sys.argv[2:]:
        name, time = arg.split("=")
        expected.append((f"surfaces/surfaces_{name}.vtk", float(time)))
    out = os.path.join(case, "postProcessing", "immersedBodies")
    with open(os.path.join(out, "surfaces.vtk.series")) as f:
        listed = [(e["name"], float(e["time"])) for e in json.load(f)["files"]]
    if [n for n, _ in listed] != [n for n, _ in expected] \
            or not np.allclose([t for _, t in listed], [t for _, t in expected], rtol=1e-12):
        fail(f"the series lists {listed}, expected {expected}")

    with h5py.File(os.path.join(out, "bodies.h5"), "r", locking=False) as f:
        times = np.asarray(f["time"][:], dtype=float)
        centres = np.asarray(f["centre"][:], dtype=float).reshape(len(times), -1, 3)
    nBodies = centres.shape[1]
    for name, time in expected:
        points, _, body = readVtk(os.path.join(out, name))
        if len(points) % nBodies or len(body) % nBodies:
            fail(f"{name}: {len(points)} points for {nBodies} bodies")
        row = np.argmin(np.abs(times - time))
        if abs(times[row] - time) > 1e-9 * max(1.0, abs(time)):
            fail(f"{name}: no row of bodies.h5 at time {time}")
        mean = points.reshape(nBodies, -1, 3).mean(axis=1)
        size = np.abs(points).max()
        if not np.allclose(mean, centres[row], rtol=0, atol=1e-6 * size):
            fail(f"{name}: surfaces centred on {mean.tolist()}, bodies.h5 at {time} has "
                 f"{centres[row].tolist()}")
    print(f"checkSurfaceSeries: {len(expected)} surface files match the series and bodies.h5")


if __name__ == "__main__":
    main()
