#!/usr/bin/python3
"""How much area a drape's overhang keeps: the formed area of the faces beyond the support disc
against their flat area, read from a run's folder.

Why: with tension-only tables a drape's overhang can gather in its own plane instead of folding
(issue 22, item 2); this is the figure that shows it. A face belongs to the overhang when its flat
centroid lies beyond the support's radius, sqrt(support_area_m2 / pi) from result.json's drape,
measured from the blank's centre (blank.obj: the flat blank; fabric.obj: the formed fabric, the
same vertices in the same order; the faces are fabric.obj's).

Usage: /usr/bin/python3 tools/drape_overhang.py RUN_DIR [RUN_DIR ...]
Prints one line a folder: drape coefficient, folds, overhang area flat and formed (m^2) and the
fraction lost (negative: gained). Standard library only.
"""
import json
import math
import pathlib
import sys


def read_obj(path):
    vertices, faces = [], []
    for line in path.read_text().splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            vertices.append(tuple(float(v) for v in parts[1:4]))
        elif parts[0] == "f":
            faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return vertices, faces


def triangle_area(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * math.sqrt(sum(x * x for x in w))


def face_area(x, face):  # a fan from the first corner, as fabform splits its quadrilaterals
    return sum(triangle_area(x[face[0]], x[face[k]], x[face[k + 1]]) for k in range(1, len(face) - 1))


def overhang(run_dir):
    result = json.loads((run_dir / "result.json").read_text())
    drape = result["drape"]
    radius = math.sqrt(drape["support_area_m2"] / math.pi)
    flat, _ = read_obj(run_dir / "blank.obj")
    formed, faces = read_obj(run_dir / "fabric.obj")
    if len(formed) != len(flat):
        sys.exit("drape_overhang: %s: blank.obj and fabric.obj differ in their vertices" % run_dir)
    centre = [sum(v[i] for v in flat) / len(flat) for i in range(2)]
    area_flat = area_formed = 0.0
    for face in faces:
        c = [sum(flat[k][i] for k in face) / len(face) for i in range(2)]
        if math.hypot(c[0] - centre[0], c[1] - centre[1]) > radius:
            area_flat += face_area(flat, face)
            area_formed += face_area(formed, face)
    return drape["coefficient"], drape["folds"], area_flat, area_formed


def main(argv):
    if not argv:
        sys.exit(__doc__)
    for arg in argv:
        dc, folds, flat, formed = overhang(pathlib.Path(arg))
        print("%s: DC %.2f %%, %d folds, overhang %.5f m^2 flat, %.5f m^2 formed, %.2f %% lost"
              % (arg, 100 * dc, folds, flat, formed, 100 * (1 - formed / flat)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
