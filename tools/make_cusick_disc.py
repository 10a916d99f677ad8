#!/usr/bin/python3
"""Write the cusick scene's support: a closed disc of diameter 180 mm, 10 mm thick, top on z = 0.

Why a generated mesh: a Cusick drape tester holds the specimen on a horizontal disc of 18 cm
(DESIGN.md; BS EN ISO 9073-9 and BS 5058 use 18 cm under a 30 cm specimen). The disc is a
SEGMENTS-sided prism, faces counter-clockwise seen from outside, in millimetres, reproducible
to the byte (`--check` regenerates it and compares). With 256 sides its top's area is
0.9999 of the true circle's (1 − sin(2π/n)/(2π/n)).

Usage:  /usr/bin/python3 tools/make_cusick_disc.py [--check]
"""
import pathlib

from generated_mesh import prism_obj, write_or_check

ROOT = pathlib.Path(__file__).resolve().parent.parent
TARGET = ROOT / "molds" / "cusick_disc_d180mm.obj"
RADIUS_MM = 90.0
THICKNESS_MM = 10.0
SEGMENTS = 256


def disc_obj() -> str:
    comment = (f"fabform Cusick support disc: diameter {2 * RADIUS_MM:g} mm, {THICKNESS_MM:g} mm thick, "
               f"centre on the z axis, top on z = 0 (tools/make_cusick_disc.py)")
    return prism_obj(comment, RADIUS_MM, 0.0, -THICKNESS_MM, SEGMENTS)


def main() -> None:
    write_or_check(TARGET, disc_obj(), __doc__.splitlines()[0], "tools/make_cusick_disc.py")


if __name__ == "__main__":
    main()
