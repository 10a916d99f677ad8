#!/usr/bin/python3
"""Write the cup scene's mold: a closed cylindrical punch, radius 25 mm, 60 mm tall, top edge rounded.

Why a generated mesh: a cup punch is a solid of revolution whose sizes the forming scene must
know exactly (its depth decides the strains); a mesh from this script is reproducible to the
byte (`--check` regenerates it and compares). The profile runs from the top's centre across
the flat top, round a fillet of radius 6 mm (FILLET_RINGS rings), down the side (SIDE_RINGS
rings) to the base's rim, and is turned about z in SEGMENTS meridians; a flat base disc closes
it. Faces are counter-clockwise seen from outside, coordinates in millimetres as CAD writes
them, the base on z = 0. With 128 meridians the chord error is 25(1 − cos(π/128)) ≈ 7.5 µm.

Usage:  /usr/bin/python3 tools/make_cup_mold.py [--check]
"""
import math
import pathlib

from generated_mesh import obj_text, write_or_check

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET = ROOT / "molds" / "cup_punch_r25mm_h60mm.obj"
RADIUS_MM = 25.0
HEIGHT_MM = 60.0
FILLET_MM = 6.0
TOP_RINGS = 6
FILLET_RINGS = 8
SIDE_RINGS = 12
SEGMENTS = 128


def profile() -> list:
    """(r, z) from just off the top's centre to the base's rim; the centre itself is the pole."""
    flat = RADIUS_MM - FILLET_MM
    points = [(flat * ring / TOP_RINGS, HEIGHT_MM) for ring in range(1, TOP_RINGS + 1)]
    for ring in range(1, FILLET_RINGS + 1):
        angle = 0.5 * math.pi * ring / FILLET_RINGS
        points.append((flat + FILLET_MM * math.sin(angle), HEIGHT_MM - FILLET_MM + FILLET_MM * math.cos(angle)))
    side = HEIGHT_MM - FILLET_MM
    points += [(RADIUS_MM, side * (1.0 - ring / SIDE_RINGS)) for ring in range(1, SIDE_RINGS + 1)]
    return points


def cup_obj() -> str:
    comment = (f"fabform cup punch: closed cylinder, radius {RADIUS_MM:g} mm, height {HEIGHT_MM:g} mm, "
               f"top edge filleted {FILLET_MM:g} mm, base on z = 0 (tools/make_cup_mold.py)")
    rings = profile()
    vertices = [(0.0, 0.0, HEIGHT_MM)]  # 1: the top's centre
    for r, z in rings:
        for s in range(SEGMENTS):
            azimuth = 2.0 * math.pi * s / SEGMENTS
            vertices.append((r * math.cos(azimuth), r * math.sin(azimuth), z))
    vertices.append((0.0, 0.0, 0.0))  # the base's centre
    at = lambda ring, s: 2 + ring * SEGMENTS + s % SEGMENTS
    base = len(vertices)
    last = len(rings) - 1
    faces = []
    for s in range(SEGMENTS):
        faces.append((1, at(0, s), at(0, s + 1)))
        for ring in range(last):
            faces.append((at(ring, s), at(ring + 1, s), at(ring + 1, s + 1)))
            faces.append((at(ring, s), at(ring + 1, s + 1), at(ring, s + 1)))
        faces.append((base, at(last, s + 1), at(last, s)))  # the base faces down
    return obj_text(comment, vertices, faces)


def main() -> None:
    write_or_check(TARGET, cup_obj(), __doc__.splitlines()[0], "tools/make_cup_mold.py")


if __name__ == "__main__":
    main()
