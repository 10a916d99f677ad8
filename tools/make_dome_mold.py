#!/usr/bin/python3
"""Write the dome scene's mold: a closed hemisphere of radius 30 mm on the plane z = 0.

Why a generated mesh: DESIGN.md's dome benchmark asks for a hemisphere of radius 3 cm at the
centre of the fabric, and a mesh from this script is reproducible to the byte (`--check`
regenerates it and compares). The dome is RINGS latitude rings by SEGMENTS meridians, closed by
a flat base disc, faces counter-clockwise seen from outside, coordinates in millimetres as CAD
writes them. With 64 × 256 facets the chord error is r(1 − cos(π/256)) ≈ 2.3 µm.

Usage:  /usr/bin/python3 tools/make_dome_mold.py [--check]
"""
import math
import pathlib

from generated_mesh import obj_text, write_or_check

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET = ROOT / "molds" / "dome_hemisphere_r30mm.obj"
RADIUS_MM = 30.0
RINGS = 64
SEGMENTS = 256


def dome_obj() -> str:
    comment = (f"fabform dome mold: closed hemisphere, radius {RADIUS_MM:g} mm, centre at the origin, "
               f"base on z = 0 (tools/make_dome_mold.py)")
    vertices = []
    vertex = vertices.append
    vertex((0.0, 0.0, RADIUS_MM))  # 1: the pole
    for ring in range(1, RINGS + 1):  # ring RINGS lies on z = 0
        polar = 0.5 * math.pi * ring / RINGS
        for s in range(SEGMENTS):
            azimuth = 2.0 * math.pi * s / SEGMENTS
            vertex((RADIUS_MM * math.sin(polar) * math.cos(azimuth),
                    RADIUS_MM * math.sin(polar) * math.sin(azimuth), RADIUS_MM * math.cos(polar)))
    vertex((0.0, 0.0, 0.0))  # the base centre
    at = lambda ring, s: 2 + (ring - 1) * SEGMENTS + s % SEGMENTS
    base = 2 + RINGS * SEGMENTS
    faces = []
    for s in range(SEGMENTS):
        faces.append((1, at(1, s), at(1, s + 1)))
        for ring in range(1, RINGS):
            faces.append((at(ring, s), at(ring + 1, s), at(ring + 1, s + 1)))
            faces.append((at(ring, s), at(ring + 1, s + 1), at(ring, s + 1)))
        faces.append((base, at(RINGS, s + 1), at(RINGS, s)))  # the base faces down
    return obj_text(comment, vertices, faces)


def main() -> None:
    write_or_check(TARGET, dome_obj(), __doc__.splitlines()[0], "tools/make_dome_mold.py")


if __name__ == "__main__":
    main()
