#!/usr/bin/python3
"""Write the cusick scene's support: a closed disc of diameter 180 mm, 10 mm thick, top on z = 0.

Why a generated mesh: a Cusick drape tester holds the specimen on a horizontal disc of 18 cm
(DESIGN.md; BS EN ISO 9073-9 and BS 5058 use 18 cm under a 30 cm specimen). The disc is a
SEGMENTS-sided prism, faces counter-clockwise seen from outside, in millimetres, reproducible
to the byte (`--check` regenerates it and compares). With 256 sides its top's area is
0.9999 of the true circle's (1 − sin(2π/n)/(2π/n)).

Usage:  /usr/bin/python3 tools/make_cusick_disc.py [--check]
"""
import math
import pathlib

from generated_mesh import obj_text, write_or_check

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET = ROOT / "molds" / "cusick_disc_d180mm.obj"
RADIUS_MM = 90.0
THICKNESS_MM = 10.0
SEGMENTS = 256


def disc_obj() -> str:
    comment = (f"fabform Cusick support disc: diameter {2 * RADIUS_MM:g} mm, {THICKNESS_MM:g} mm thick, "
               f"centre on the z axis, top on z = 0 (tools/make_cusick_disc.py)")
    vertices = []
    vertex = vertices.append
    for z in (0.0, -THICKNESS_MM):  # 1: the top centre, 2..: its rim; then the bottom's
        vertex((0.0, 0.0, z))
        for s in range(SEGMENTS):
            azimuth = 2.0 * math.pi * s / SEGMENTS
            vertex((RADIUS_MM * math.cos(azimuth), RADIUS_MM * math.sin(azimuth), z))
    top, bottom = 1, 2 + SEGMENTS
    rim = lambda centre, s: centre + 1 + s % SEGMENTS
    faces = []
    for s in range(SEGMENTS):
        faces.append((top, rim(top, s), rim(top, s + 1)))
        faces.append((bottom, rim(bottom, s + 1), rim(bottom, s)))
        faces.append((rim(top, s), rim(bottom, s), rim(bottom, s + 1)))
        faces.append((rim(top, s), rim(bottom, s + 1), rim(top, s + 1)))
    return obj_text(comment, vertices, faces)


def main() -> None:
    write_or_check(TARGET, disc_obj(), __doc__.splitlines()[0], "tools/make_cusick_disc.py")


if __name__ == "__main__":
    main()
