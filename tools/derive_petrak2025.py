#!/usr/bin/python3
"""Petrak et al. 2025's six woven fabrics as fabform inputs: tension tables and the Cusick study.

Why: the paper (Sustainability 17(4) 1388, CC BY 4.0) gives six fabrics' KES-FB measurements,
converted to CLO3D's units, with their measured drape coefficients: what fabform's drape is
validated against (docs/drape.md, "Drape"). materials/petrak2025/fabrics.csv holds the numbers as
transcribed, with their provenance; this script turns them into what fabform reads, so that no
number is copied by hand.

What it writes (from the repository root):
  materials/petrak2025/ID_warp.csv, ID_weft.csv   linear tension tables, tension = k x strain with
      k = the stretch value / 1000 N/m (1 g/s^2 = 1e-3 N/m), tension-only (the Cusick scene's
      springs take their compression response from the first slope); the fabric's areal density
  studies/cusick_measured.toml   one case a fabric on scenes/cusick_woven.toml: its tables, areal
      mass (g/m^2), flexural rigidity per direction (bending / 1000 uN.m: 1 g.mm^2/s^2 = 1e-9 N.m)
      and shear rigidity G (shear / 1000 N/m), four specimens each, at 120 divisions

Usage: /usr/bin/python3 tools/derive_petrak2025.py [--check]   (--check: exit 1 if a file is stale;
exit 2 on a usage error or a malformed fabrics.csv, one line naming its line, nothing written)
Standard library only.
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from commented_csv import Malformed, read_rows  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
DATA = ROOT / "materials" / "petrak2025"
STUDY = ROOT / "studies" / "cusick_measured.toml"


NUMBERS = ("areal_mass_g_m2", "stretch_warp_g_s2", "stretch_weft_g_s2", "shear_g_s2", "bending_warp_g_mm2_s2",
           "bending_weft_g_mm2_s2")


def fabrics():
    path = DATA / "fabrics.csv"
    rows = []
    for n, row in read_rows(path, ("id", "composition", "weave") + NUMBERS, what="fabric"):
        for column in NUMBERS:
            try:
                value = float(row[column] or "")
            except ValueError:
                raise Malformed("%s line %d: %s = %r is not a number" % (path, n, column, row[column]))
            if not value > 0.0:
                raise Malformed("%s line %d: %s = %r must be positive" % (path, n, column, row[column]))
        rows.append(row)
    return rows


def table(fabric, direction):
    k = float(fabric["stretch_%s_g_s2" % direction]) / 1000.0
    return "\n".join([
        "# fabform material table, version 2 (format: materials/README.md)",
        "# fabric: Petrak et al. 2025 %s (%s, %s)" % (fabric["id"], fabric["composition"], fabric["weave"]),
        "# direction: %s" % direction,
        "# source: materials/petrak2025/fabrics.csv (its provenance there), stretch_%s_g_s2 = %s g/s^2"
        % (direction, fabric["stretch_%s_g_s2" % direction]),
        "# derivation: tension = k x strain, k = %s / 1000 = %.3f N/m; tension-only" % (fabric["stretch_%s_g_s2" % direction], k),
        "# regenerate (from the repository root): /usr/bin/python3 tools/derive_petrak2025.py",
        "areal_density_kg_m2,%.5f" % (float(fabric["areal_mass_g_m2"]) / 1000.0),
        "strain,tension_N_per_m",
        "0,0",
        "1,%.3f" % k,
    ]) + "\n"


def study(rows):
    lines = [
        "# Petrak et al. 2025's six woven fabrics (materials/petrak2025/fabrics.csv) on the Cusick tester",
        "# (scenes/cusick_woven.toml), four specimens each at 120 divisions (2.5 mm), where their drapes",
        "# settle (the scene's 40 do not: docs/drape.md, \"Drape\"): fabform's drape coefficients, to compare with",
        "# the measured ones (tools/drape_against_measured.py DIR). Written by tools/derive_petrak2025.py.",
        "",
        "[study]",
        'name = "cusick_measured"',
        'scene = "../scenes/cusick_woven.toml"',
        'description = "drape coefficients of six woven fabrics with measured Cusick drapes"',
        'figures = ["drape_coefficient", "drape.folds"]',
        "specimens = 4",
        "",
        "[study.set]",
        '"fabric.divisions" = 120',
    ]
    for fabric in rows:
        lines += [
            "",
            "[[case]]  # %s: %s, %s" % (fabric["id"], fabric["composition"], fabric["weave"]),
            '"fabric.warp" = "../materials/petrak2025/%s_warp.csv"' % fabric["id"],
            '"fabric.weft" = "../materials/petrak2025/%s_weft.csv"' % fabric["id"],
            '"fabric.areal_mass_g_m2" = %s' % fabric["areal_mass_g_m2"],
            '"bending.rigidity_uNm" = [%r, %r]' % (float(fabric["bending_warp_g_mm2_s2"]) / 1000.0,
                                                float(fabric["bending_weft_g_mm2_s2"]) / 1000.0),
            '"shear.rigidity_N_m" = %r' % (float(fabric["shear_g_s2"]) / 1000.0),
        ]
    return "\n".join(lines) + "\n"


def outputs():
    rows = fabrics()
    files = {STUDY: study(rows)}
    for fabric in rows:
        for direction in ("warp", "weft"):
            files[DATA / ("%s_%s.csv" % (fabric["id"], direction))] = table(fabric, direction)
    return files


def main(argv):
    check = argv == ["--check"]
    if argv and not check:
        print("usage: derive_petrak2025.py [--check]", file=sys.stderr)
        return 2
    try:
        files = outputs()
    except Malformed as error:
        print("derive_petrak2025: %s" % error, file=sys.stderr)
        return 2
    stale = []
    for path, text in files.items():
        if check:
            if not path.is_file() or path.read_text() != text:
                stale.append(str(path.relative_to(ROOT)))
        else:
            path.write_text(text)
    for path in stale:
        print("derive_petrak2025: stale or missing: %s (run tools/derive_petrak2025.py)" % path, file=sys.stderr)
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
