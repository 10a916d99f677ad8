"""What the mold generators share: OBJ text written to the byte, and writing it or checking that
the shipped file is what the generator writes (`--check`, run by the test suite).

Imported by tools/make_dome_mold.py, tools/make_cup_mold.py, tools/make_cusick_disc.py and
tools/make_tube_cylinder.py. Standard library only.
"""
import argparse
import math
import pathlib
import sys


def obj_text(comment: str, vertices: list, faces: list) -> str:
    """OBJ with one comment line, vertices at 9 decimals (no -0) and 1-based triangle faces."""
    lines = [f"# {comment}"]
    for p in vertices:
        lines.append("v {:.9f} {:.9f} {:.9f}".format(*(0.0 if abs(c) < 5e-10 else c for c in p)))
    lines += [f"f {a} {b} {c}" for a, b, c in faces]
    return "\n".join(lines) + "\n"


def prism_obj(comment: str, radius: float, top_z: float, bottom_z: float, segments: int) -> str:
    """A closed right prism on the z axis, `segments` sides, faces counter-clockwise seen from outside."""
    vertices = []
    for z in (top_z, bottom_z):  # 1: the top centre, 2..: its rim; then the bottom's
        vertices.append((0.0, 0.0, z))
        for s in range(segments):
            azimuth = 2.0 * math.pi * s / segments
            vertices.append((radius * math.cos(azimuth), radius * math.sin(azimuth), z))
    top, bottom = 1, 2 + segments
    rim = lambda centre, s: centre + 1 + s % segments
    faces = []
    for s in range(segments):
        faces.append((top, rim(top, s), rim(top, s + 1)))
        faces.append((bottom, rim(bottom, s + 1), rim(bottom, s)))
        faces.append((rim(top, s), rim(bottom, s), rim(bottom, s + 1)))
        faces.append((rim(top, s), rim(bottom, s + 1), rim(top, s + 1)))
    return obj_text(comment, vertices, faces)


def write_or_check(target: pathlib.Path, text: str, description: str, script: str) -> None:
    """The generator's command line: write `target`, or with --check exit 1 when it differs."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--check", action="store_true", help="fail if the shipped file differs")
    args = parser.parse_args()
    if args.check:
        if target.read_text() != text:
            sys.exit(f"{target}: differs from what {script} writes")
        return
    target.write_text(text)
    print(f"wrote {target}")
