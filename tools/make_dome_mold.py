#!/usr/bin/python3
"""Write the dome scene's mold: a closed hemisphere of radius 30 mm on the plane z = 0.

Why a generated mesh: DESIGN.md's dome benchmark asks for a hemisphere of radius 3 cm at the
centre of the fabric, and a mesh from this script is reproducible to the byte (`--check`
regenerates it and compares). The dome is RINGS latitude rings by SEGMENTS meridians, closed by
a flat base disc, faces counter-clockwise seen from outside, coordinates in millimetres as CAD
writes them. With 64 × 256 facets the chord error is r(1 − cos(π/256)) ≈ 2.3 µm.

Usage:  /usr/bin/python3 tools/make_dome_mold.py [--check]
"""
import argparse
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET = ROOT / "molds" / "dome_hemisphere_r30mm.obj"
RADIUS_MM = 30.0
RINGS = 64
SEGMENTS = 256


def dome_obj() -> str:
    lines = [f"# fabform dome mold: closed hemisphere, radius {RADIUS_MM:g} mm, centre at the origin, "
             f"base on z = 0 (tools/make_dome_mold.py)"]
    vertex = lambda p: lines.append("v {:.9f} {:.9f} {:.9f}".format(*(0.0 if abs(c) < 5e-10 else c for c in p)))
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
    lines += [f"f {a} {b} {c}" for a, b, c in faces]
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="fail if the shipped mold differs")
    args = parser.parse_args()
    text = dome_obj()
    if args.check:
        if TARGET.read_text() != text:
            sys.exit(f"{TARGET}: differs from what tools/make_dome_mold.py writes")
        return
    TARGET.write_text(text)
    print(f"wrote {TARGET}")


if __name__ == "__main__":
    main()
