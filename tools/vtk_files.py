"""The VTK files fabform writes, read back: legacy ASCII polydata (fabric.vtk, bodies.vtk) and
VTK XML polydata (fabric_step_NNN.vtp, bodies_step_NNN.vtp), each into one Mesh.

Imported by tools/report.py and tools/view3d.py. A file that is missing or malformed raises
plot_convergence.InputError naming it (and the line, in a legacy file). numpy and the standard
library only.
"""
import pathlib
import sys
import typing
import xml.etree.ElementTree as ET

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import numpy as np  # noqa: E402
import plot_convergence as pc  # noqa: E402  (InputError)


class Mesh(typing.NamedTuple):
    points: np.ndarray          # (n, 3)
    polygons: list              # per polygon its point indices
    point_fields: dict          # name: (n,) array
    cell_fields: dict           # name: (len(polygons),) array


def numbers(path: pathlib.Path, line: int, words: list, count: int, what: str) -> np.ndarray:
    try:
        values = np.array(words, dtype=float)
    except ValueError:
        raise pc.InputError(f"{path}:{line}: {what} holds something that is not a number")
    if values.size != count:
        raise pc.InputError(f"{path}:{line}: {what} has {values.size} numbers, not {count}")
    return values


def read_legacy(path: pathlib.Path) -> Mesh:
    """POINTS, POLYGONS and the SCALARS of POINT_DATA and CELL_DATA of a legacy ASCII file."""
    if not path.is_file():
        raise pc.InputError(f"{path}: no such file")
    lines = path.read_text().splitlines()
    points, polygons, fields = None, [], {"POINT_DATA": {}, "CELL_DATA": {}}
    section, count, at = None, 0, 0
    while at < len(lines):
        words = lines[at].split()
        head = words[0] if words else ""
        if head == "POINTS":
            n = int(words[1])
            block, end = [], at + 1
            while len(block) < 3 * n and end < len(lines):
                block += lines[end].split()
                end += 1
            points = numbers(path, at + 1, block, 3 * n, "POINTS").reshape(n, 3)
            at = end
            continue
        if head == "POLYGONS":
            m = int(words[1])
            for k, line in enumerate(lines[at + 1: at + 1 + m]):
                corners = [int(w) for w in line.split()]
                if not corners or corners[0] != len(corners) - 1:
                    raise pc.InputError(f"{path}:{at + 2 + k}: a polygon's corner count does not match its indices")
                polygons.append(corners[1:])
            at += 1 + m
            continue
        if head in fields:
            section, count = head, int(words[1])
        elif head == "SCALARS":
            if section is None:
                raise pc.InputError(f"{path}:{at + 1}: SCALARS outside POINT_DATA or CELL_DATA")
            fields[section][words[1]] = numbers(path, at + 3, lines[at + 2: at + 2 + count], count, words[1])
            at += 2 + count
            continue
        at += 1
    if points is None:
        raise pc.InputError(f"{path}: no POINTS")
    return Mesh(points, polygons, fields["POINT_DATA"], fields["CELL_DATA"])


def read_xml(path: pathlib.Path) -> Mesh:
    """Points, polygons and PointData/CellData arrays of a VTK XML PolyData file (ASCII)."""
    try:
        piece = ET.parse(path).getroot().find("./PolyData/Piece")
    except (OSError, ET.ParseError) as error:
        raise pc.InputError(f"{path}: {error}")
    if piece is None:
        raise pc.InputError(f"{path}: no PolyData Piece")
    n, m = int(piece.get("NumberOfPoints", "0")), int(piece.get("NumberOfPolys", "0"))

    def array(where: str, name: str = None, count: int = None, kind=float) -> np.ndarray:
        found = piece.find(f"./{where}/DataArray" + (f"[@Name='{name}']" if name else ""))
        if found is None:
            raise pc.InputError(f"{path}: no {where} {name or 'array'}")
        values = (found.text or "").split()
        if count is not None and len(values) != count:
            raise pc.InputError(f"{path}: {where} {name or ''} has {len(values)} numbers, not {count}")
        try:
            return np.array(values, dtype=kind)
        except ValueError:
            raise pc.InputError(f"{path}: {where} {name or ''} holds something that is not a number")

    points = array("Points", count=3 * n).reshape(n, 3)
    connectivity = array("Polys", "connectivity", kind=np.int64)
    offsets = array("Polys", "offsets", count=m, kind=np.int64)
    starts = np.concatenate(([0], offsets[:-1]))
    polygons = [connectivity[a:b].tolist() for a, b in zip(starts, offsets)]

    def named(where: str, count: int) -> dict:
        return {a.get("Name"): array(where, a.get("Name"), count) for a in piece.findall(f"./{where}/DataArray")}

    return Mesh(points, polygons, named("PointData", n), named("CellData", m))
