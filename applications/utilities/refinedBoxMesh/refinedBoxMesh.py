#!/usr/bin/python3
"""Write a blockMeshDict for a box with a uniformly fine region: one hex block
whose cells are of size h inside the fine region and grow geometrically (by at
most --growth per cell, up to --max-ratio x h) towards the box faces.

    refinedBoxMesh.py --box X0 X1 Y0 Y1 Z0 Z1 --fine X0 X1 Y0 Y1 Z0 Z1 --h H
                      [--growth 1.1] [--max-ratio 4]
                      [--patch xMin:wall ... | --periodic x y ...]
                      [--scale S] -o system/blockMeshDict

Each face of the box is a patch named xMin, xMax, yMin, yMax, zMin, zMax
(type patch unless set with --patch NAME:TYPE); --periodic x makes xMin and
xMax cyclic (the grading is then made symmetric, so the faces match).
Prints the cell counts. Used by the validation cases (validation/*/Allrun).
"""
import argparse
import math
import sys


def graded_cells(length, h, growth, max_ratio):
    """A geometric segment of the given length next to a fine cell of size h:
    cells of sizes h q, h q^2, ..., h q^n (the fewest cells with q <= growth and
    the largest cell <= max_ratio h). Returns n and the expansion ratio
    (last/first) blockMesh wants."""
    if length <= 0:
        return 0, 1.0

    def total(q, n):
        return n * h if abs(q - 1) < 1e-14 else h * q * (q ** n - 1) / (q - 1)

    n = max(1, math.ceil(length / (max_ratio * h)))
    while True:
        if total(1.0, n) >= length:      # uniform cells of size <= h would do
            return n, 1.0
        lo, hi = 1.0, max_ratio          # total(q, n) grows with q
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if total(mid, n) > length:
                hi = mid
            else:
                lo = mid
        q = 0.5 * (lo + hi)
        if q <= growth and q ** n <= max_ratio * (1 + 1e-9):
            return n, q ** (n - 1)
        n += 1


def direction(lo, hi, f0, f1, h, growth, max_ratio, symmetric):
    """Multi-grading entries for one direction, and the cell count."""
    if not (lo <= f0 < f1 <= hi):
        sys.exit(f"refinedBoxMesh: the fine region [{f0}, {f1}] is not inside [{lo}, {hi}]")
    nFine = max(1, round((f1 - f0) / h))
    left, right = f0 - lo, hi - f1
    if symmetric and abs(left - right) > 1e-9 * (hi - lo):
        sys.exit("refinedBoxMesh: a periodic direction needs the fine region in the middle"
                 f" (left {left}, right {right})")
    nl, rl = graded_cells(left, (f1 - f0) / nFine, growth, max_ratio)
    nr, rr = graded_cells(right, (f1 - f0) / nFine, growth, max_ratio)
    L = hi - lo
    parts = []
    if nl:
        parts.append((left / L, nl, 1.0 / rl))
    parts.append(((f1 - f0) / L, nFine, 1.0))
    if nr:
        parts.append((right / L, nr, rr))
    n = sum(p[1] for p in parts)
    # blockMesh takes fractions of the cells too: give them as cell counts / n
    grading = "(" + " ".join(f"({p[0]:.12g} {p[1] / n:.12g} {p[2]:.12g})" for p in parts) + ")"
    return n, grading


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--box", type=float, nargs=6, required=True)
    ap.add_argument("--fine", type=float, nargs=6, required=True)
    ap.add_argument("--h", type=float, required=True, help="cell size in the fine region")
    ap.add_argument("--growth", type=float, default=1.1, help="largest size ratio of neighbour cells")
    ap.add_argument("--max-ratio", type=float, default=4.0, help="largest cell size / h")
    ap.add_argument("--patch", action="append", default=[], help="NAME:TYPE, e.g. zMin:wall")
    ap.add_argument("--periodic", action="append", default=[], choices=["x", "y", "z"])
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    if a.h <= 0 or a.growth < 1 or a.max_ratio < 1:
        sys.exit("refinedBoxMesh: need --h > 0, --growth >= 1, --max-ratio >= 1")

    counts, gradings = [], []
    for d, axis in enumerate("xyz"):
        n, g = direction(a.box[2 * d], a.box[2 * d + 1], a.fine[2 * d], a.fine[2 * d + 1],
                         a.h, a.growth, a.max_ratio, axis in a.periodic)
        counts.append(n)
        gradings.append(g)

    types = {name: "patch" for name in ("xMin", "xMax", "yMin", "yMax", "zMin", "zMax")}
    for spec in a.patch:
        name, _, typ = spec.partition(":")
        if name not in types or not typ:
            sys.exit(f"refinedBoxMesh: --patch {spec}: expected NAME:TYPE with NAME in {sorted(types)}")
        types[name] = typ
    x0, x1, y0, y1, z0, z1 = a.box
    faces = {
        "xMin": "(0 4 7 3)", "xMax": "(1 2 6 5)",
        "yMin": "(0 1 5 4)", "yMax": "(3 7 6 2)",
        "zMin": "(0 3 2 1)", "zMax": "(4 5 6 7)",
    }
    out = ["FoamFile", "{", "    version 2.0;", "    format ascii;", "    class dictionary;",
           "    object blockMeshDict;", "}", "// written by applications/utilities/refinedBoxMesh/"
           "refinedBoxMesh.py " + " ".join(sys.argv[1:]), "",
           f"scale {a.scale:.12g};", "", "vertices", "("]
    for z in (z0, z1):
        for (x, y) in ((x0, y0), (x1, y0), (x1, y1), (x0, y1)):
            out.append(f"    ({x:.12g} {y:.12g} {z:.12g})")
    out += [");", "", "blocks", "(",
            f"    hex (0 1 2 3 4 5 6 7) ({counts[0]} {counts[1]} {counts[2]})",
            "    simpleGrading", "    (", *[f"        {g}" for g in gradings], "    )", ");", "",
            "edges ();", "", "boundary", "("]
    for name, f in faces.items():
        axis = name[0]
        out.append(f"    {name}")
        out.append("    {")
        if axis in a.periodic:
            other = axis + ("Max" if name.endswith("Min") else "Min")
            out += ["        type cyclic;", f"        neighbourPatch {other};"]
        else:
            out.append(f"        type {types[name]};")
        out += [f"        faces ({f});", "    }"]
    out += [");", "", "mergePatchPairs ();", ""]
    with open(a.output, "w") as fh:
        fh.write("\n".join(out))
    total = counts[0] * counts[1] * counts[2]
    print(f"refinedBoxMesh: {counts[0]} x {counts[1]} x {counts[2]} = {total} cells -> {a.output}")


if __name__ == "__main__":
    main()
