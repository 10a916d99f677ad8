#!/usr/bin/python3
"""Write the tube scene's body: a closed cylinder of radius 60 mm, 200 mm tall, base on z = 0.

Why a generated mesh: Laplace's law p = T / r holds on a circular cylinder, which a tube scene
checks its pressure against; with 512 sides the facets' radius varies by 1 − cos(π/512) = 2e-5
of it. A prism, faces counter-clockwise seen from outside, in millimetres, reproducible to the
byte (`--check` regenerates it and compares).

Usage:  /usr/bin/python3 tools/make_tube_cylinder.py [--check]
"""
import pathlib

from generated_mesh import prism_obj, write_or_check

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET = ROOT / "molds" / "cylinder_r60mm_h200mm.obj"
RADIUS_MM = 60.0
HEIGHT_MM = 200.0
SEGMENTS = 512


def main() -> None:
    comment = (f"fabform tube scene cylinder: radius {RADIUS_MM:g} mm, {HEIGHT_MM:g} mm tall, "
               f"axis z, base on z = 0 (tools/make_tube_cylinder.py)")
    write_or_check(TARGET, prism_obj(comment, RADIUS_MM, HEIGHT_MM, 0.0, SEGMENTS), __doc__.splitlines()[0],
                   "tools/make_tube_cylinder.py")


if __name__ == "__main__":
    main()
