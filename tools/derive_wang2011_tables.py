#!/usr/bin/python3
"""Derive fabform tension-strain tables (warp, weft, shear) from Wang et al. 2011 fabric data.

Why this exists: fabform's spring model wants, for each yarn direction, a
one-dimensional curve "tension per unit width vs. engineering strain".  The
only real, measured fabric mechanics we can ship are the ARCSim
"data-driven elastic" tables of Wang, Ramamoorthi & O'Brien (SIGGRAPH 2011),
which describe a biaxial continuum (Green strain -> second Piola-Kirchhoff
stress, stiffness blended by strain and direction).  This script reads those
tables uniaxially -- stretch along warp (or weft) with zero transverse Green
strain -- and samples the result into the fabform material table format
(version 2, specified in materials/README.md).  It also turns the shear
stiffness k3 into a table for seed 004's shear springs (both diagonals of
every square cell, each family tiling the cell's area once).  Doing it in a
script, with the inputs checked against their recorded git blob ids, keeps
the shipped CSVs reproducible; `--check` lets a test prove the committed
CSVs are what this derivation produces.

Model (see materials/README.md and materials/source/wang2011_berkeley/FORMAT.md):
    w = 1 + e,  G = e + e^2/2,  t = clamp(6 e, 0, 1)
    k(e) = (1 - t) * max(2 k_row0, 0) + t * max(2 k_rowdir, 0)
    S = k(e) * G               (2nd Piola-Kirchhoff stress resultant, N/m)
    T = (1 + e) * S            (nominal tension per unit reference width, N/m)
warp: column 0 (k0) of rows 0 and 1 (0 deg); weft: column 2 (k2) of rows 0
and 5 (90 deg).

Shear: ARCSim's S_uv = k3 G_uv / 2, doubled like every component, is k3 G_uv;
the shear energy per rest area S_uv G_uv = k3 G_uv^2 = k3 gamma^2 / 4 for a
small engineering shear gamma (G_uv = gamma/2).  Under gamma a square cell's
diagonals strain +gamma/2 and -gamma/2; the tables are tension-only, so only
the stretched family resists, with energy per area k_d (gamma/2)^2 / 2 =
k_d gamma^2 / 8.  Matching gives k_d = 2 k3, blended like warp and weft:
    k_d(e) = (1 - t) * max(2 k3_row0, 0) + t * max(2 k3_row3, 0)   (row 3: 45 deg)
    T(e) = integral of k_d from 0 to e   (tension per unit spring width, N/m;
                                k_d a tangent stiffness, so T rises wherever k_d > 0)
t uses the diagonal's own strain: under pure shear the largest principal
stretch is 1 + gamma/2, so this is ARCSim's t to first order.

Usage (from anywhere; paths default relative to the repository root):
    /usr/bin/python3 tools/derive_wang2011_tables.py            # write CSVs
    /usr/bin/python3 tools/derive_wang2011_tables.py --check    # exit 1 if stale
    /usr/bin/python3 tools/derive_wang2011_tables.py --summary  # README table

Standard library only.
"""

import argparse
import hashlib
import json
import math
import re
import sys
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_SOURCE = REPO_ROOT / "materials" / "source" / "wang2011_berkeley"
DEFAULT_OUT = REPO_ROOT / "materials"
REGENERATE_COMMAND = "/usr/bin/python3 tools/derive_wang2011_tables.py"

ORIGIN_REPO = "HuangLeiDalab/Projects"
ORIGIN_COMMIT = "e134f59810fa656e7b3933325577b6554d78af1a"
ORIGIN_DIR = "VTO/data/garmentlibrary/BerkeleyGarmentLibrary/Materials"
CITATION = ("Huamin Wang, Ravi Ramamoorthi, James F. O'Brien, \"Data-Driven Elastic "
            "Models for Cloth: Modeling and Measurement\", ACM Transactions on "
            "Graphics 30(4):71:1-11, July 2011 (Proc. SIGGRAPH 2011)")

# name -> (git blob sha1 from /work/shared/data/SOURCES.md, description)
FABRICS = {
    "white-swim-solid": ("c1abc7aacea65a3da01e8b44bbade4b3d5352f65",
                         "swimwear knit, 87% nylon 13% spandex"),
    "ivory-rib-knit": ("98cb133fc19315d6aebf95ecb37306c3422fa812",
                       "rib knit (underwear), 95% cotton 5% spandex"),
    "11oz-black-denim": ("3e66f44def99ef84f77922183f49b2b1446adc68",
                         "woven denim (jeans), 99% cotton 1% spandex"),
}

# direction -> (stretching column, direction row, angle from warp in degrees); shear reads
# k3 at 45 deg, the direction of the largest principal stretch under pure shear.
DIRECTIONS = {"warp": (0, 1, 0.0), "weft": (2, 5, 90.0), "shear": (3, 3, 45.0)}

KINK = 1.0 / 6.0  # t reaches 1 at w - 1 = 1/6
SAMPLE_STRAINS = ([i * 0.02 for i in range(9)] + [KINK]
                  + [0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0])
SUMMARY_STRAINS = (0.05, 0.1667, 0.5)

HEADERS = ("strain,tension_N_per_m", "strain,stress_Pa")
NUMBER_RE = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\Z")


# ---------------------------------------------------------------- inputs

def git_blob_sha1(data):
    """The id git gives a file's bytes (what SOURCES.md records)."""
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def load_source(source_dir, fabric):
    """Return the 6x4 stretching table of `fabric` and its areal density (kg/m^2), after
    checking the file's blob id."""
    path = Path(source_dir) / (fabric + ".json")
    data = path.read_bytes()
    expected = FABRICS[fabric][0]
    actual = git_blob_sha1(data)
    if actual != expected:
        raise SystemExit("%s: git blob sha1 %s, expected %s (see SOURCES.md)"
                         % (path, actual, expected))
    source = json.loads(data.decode("utf-8"))
    table, density = source["stretching"], float(source["density"])
    if len(table) != 6 or any(len(row) != 4 for row in table):
        raise SystemExit("%s: stretching is not 6x4" % path)
    if not density > 0:
        raise SystemExit("%s: density is not positive" % path)
    return [[float(x) for x in row] for row in table], density


def used_stiffness(stretching, direction):
    """(row-0 value, direction-row value) in N/m as stored, before doubling."""
    col, row, _ = DIRECTIONS[direction]
    return stretching[0][col], stretching[row][col]


# ---------------------------------------------------------------- model

def strain_weight(e):
    """ARCSim's t = clamp((w - 1) * 6, 0, 1) with w = 1 + e."""
    return min(max(6.0 * e, 0.0), 1.0)


def stiffness(e, k_small, k_large):
    """Blended, doubled and clamped stiffness k(e) in N/m."""
    t = strain_weight(e)
    return (1.0 - t) * max(2.0 * k_small, 0.0) + t * max(2.0 * k_large, 0.0)


def uniaxial_tension(e, k_small, k_large):
    """Nominal tension per unit reference width (N/m) at engineering strain e."""
    green = e + 0.5 * e * e
    return (1.0 + e) * stiffness(e, k_small, k_large) * green


def diagonal_tension(e, k3_small, k3_large):
    """Shear-spring tension per unit width (N/m) at the diagonal's engineering strain e, the
    integral of k_d over the strain: k_d is read as the tangent stiffness, so the tension
    rises wherever k_d > 0. (As a secant, k_d(e)*e, ivory rib knit's would fall between
    e = 0.12 and 1/6, its k3 dropping from 83 to 28 N/m: negative stiffness, on which no
    solver can rest.) stiffness() doubles k3, which gives k_d = 2 k3 (module docstring)."""
    kink = min(e, KINK)
    k0, k1 = stiffness(0.0, k3_small, k3_large), stiffness(KINK, k3_small, k3_large)
    blended = k0 * kink + 3.0 * (k1 - k0) * kink * kink  # t = 6x on [0, 1/6]
    return blended + k1 * max(e - KINK, 0.0)


TENSION = {"warp": uniaxial_tension, "weft": uniaxial_tension, "shear": diagonal_tension}


def diagonal_stiffening(stretching):
    """(k3/(2 k0), k3/(2 k2)) at zero strain: the fraction by which the shear springs raise
    the warp and weft stiffness under uniaxial stretch, where both diagonals strain eps/2
    and add 2 * k_d (eps/2)^2 / 2 = k3 eps^2 / 2 per area, i.e. k3 to the 2 k0 (2 k2)."""
    k0, _, k2, k3 = (max(x, 0.0) for x in stretching[0])
    return k3 / (2 * k0), k3 / (2 * k2)


# ---------------------------------------------------------------- output

def fmt_value(x):
    """6 significant digits, never '-0'."""
    s = "%.6g" % x
    return "0" if s in ("-0", "0") else s


def fmt_strain(e):
    return "%.6f" % e


def uniaxial_derivation(direction, k_small, k_large):
    """(direction lines, derivation lines) of a warp or weft header."""
    col, row, angle = DIRECTIONS[direction]
    return [
        "# direction: %s (ARCSim material %s axis)"
        % (direction, "u" if direction == "warp" else "v"),
    ], [
        "# derivation (materials/README.md): uniaxial stretch along %s, zero transverse" % direction,
        "#   Green strain; stretching column %d, rows 0 and %d (%g deg):" % (col, row, angle),
        "#   k_small = %r N/m, k_large = %r N/m" % (k_small, k_large),
        "#   G = e + e^2/2, t = clamp(6e,0,1), k = (1-t)*max(2*k_small,0) + t*max(2*k_large,0)",
        "#   tension = (1+e)*k*G  [N/m per unit reference width]; tension-only (0 in compression);",
    ]


def shear_derivation(k_small, k_large, stretching):
    """(direction lines, derivation lines) of a shear header."""
    col, row, angle = DIRECTIONS["shear"]
    warp, weft = diagonal_stiffening(stretching)
    return [
        "# direction: shear (seed 004's diagonal springs: both diagonals of every square cell,",
        "#   each family tiling the cell's area once; strain e is the diagonal's)",
    ], [
        "# derivation (materials/README.md): ARCSim's S_uv = k3*G_uv/2, doubled, is k3*G_uv; shear",
        "#   energy per rest area k3*G_uv^2 = k3*gamma^2/4 (G_uv = gamma/2, small engineering shear",
        "#   gamma). The diagonals strain +gamma/2 and -gamma/2; only the stretched family carries",
        "#   tension: k_d*(gamma/2)^2/2 = k_d*gamma^2/8 per area, so k_d = 2*k3.",
        "#   stretching column %d (k3), rows 0 and %d (%g deg):" % (col, row, angle),
        "#   k_small = %r N/m, k_large = %r N/m" % (k_small, k_large),
        "#   t = clamp(6e,0,1), k_d = (1-t)*max(2*k_small,0) + t*max(2*k_large,0)",
        "#   tension = integral of k_d over e (k_d a tangent stiffness, so the tension rises)",
        "#   [N/m per unit spring width, width = cell area / diagonal length]; tension-only;",
        "# neglected: a warp (weft) strain eps stretches both diagonals by eps/2, adding",
        "#   k3*eps^2/2 per area: warp stiffness +k3 (%.1f %% of 2*k0), weft +k3 (%.1f %% of 2*k2)"
        % (100 * warp, 100 * weft),
        "#   at small strain, plus a warp-weft coupling; where both diagonals are taut, the shear",
        "#   stiffness doubles;",
    ]


def header_lines(fabric, direction, stretching):
    sha, desc = FABRICS[fabric]
    k_small, k_large = used_stiffness(stretching, direction)
    what, derivation = (shear_derivation(k_small, k_large, stretching) if direction == "shear"
                        else uniaxial_derivation(direction, k_small, k_large))
    return [
        "# fabform material table, version 2 (format: materials/README.md)",
        "# fabric: %s (%s)" % (fabric, desc),
    ] + what + [
        "# source: materials/source/wang2011_berkeley/%s.json" % fabric,
        "#   git blob sha1 %s" % sha,
        "#   origin: %s @ %s, %s/%s.json" % (ORIGIN_REPO, ORIGIN_COMMIT, ORIGIN_DIR, fabric),
        "# citation: %s" % CITATION,
        "# acknowledgement: material parameters from the UC Berkeley Garment Library",
        "#   (terms: materials/LICENSES/BerkeleyGarmentLibrary_README.txt)",
    ] + derivation + [
        "#   fabform extends the last segment beyond the last point.",
        "# regenerate (from the repository root): %s" % REGENERATE_COMMAND,
    ]


def table_text(fabric, direction, stretching, density):
    """Complete CSV text for one fabric and direction."""
    k_small, k_large = used_stiffness(stretching, direction)
    tension = TENSION[direction]
    lines = header_lines(fabric, direction, stretching)
    if direction == "shear":
        lines.append("# the source's areal density (its \"density\"); fabform takes gravity's from"
                     " the warp and weft files")
    else:
        lines.append("# the source's areal density (its \"density\"), what gravity acts on")
    lines.append("areal_density_kg_m2,%r" % density)
    lines.append(HEADERS[0])
    for e in SAMPLE_STRAINS:
        lines.append("%s,%s" % (fmt_strain(e), fmt_value(tension(e, k_small, k_large))))
    return "\n".join(lines) + "\n"


def table_name(fabric, direction):
    return "%s_%s.csv" % (fabric, direction)


def generate_all(source_dir):
    """{file name: text} for every fabric and direction."""
    out = {}
    for fabric in FABRICS:
        stretching, density = load_source(source_dir, fabric)
        for direction in DIRECTIONS:
            text = table_text(fabric, direction, stretching, density)
            parse_table(text)  # the output must satisfy the format spec
            out[table_name(fabric, direction)] = text
    return out


# ---------------------------------------------------------------- reader
# A reference reader for the format in materials/README.md (version 2).

class TableError(ValueError):
    pass


def parse_number(field, lineno):
    if not NUMBER_RE.match(field):
        raise TableError("line %d: not a number: %r" % (lineno, field))
    x = float(field)
    if not math.isfinite(x):
        raise TableError("line %d: not finite: %r" % (lineno, field))
    return x


def split_pair(line, lineno):
    fields = [f.strip(" \t") for f in line.split(",")]
    if len(fields) != 2:
        raise TableError("line %d: expected 2 comma-separated fields" % lineno)
    return fields


DIRECTIVES = ("thickness_m", "areal_density_kg_m2")  # each a number > 0, before the header


def parse_table(text):
    """Parse a version-2 table (areal_density_kg_m2 is checked, not returned); return
    (kind, thickness_m or None, [(strain, value)])."""
    directives, kind, points = {}, None, []
    for lineno, raw in enumerate(text.split("\n"), start=1):
        line = raw[:-1] if raw.endswith("\r") else raw
        line = line.strip(" \t")
        if not line or line.startswith("#"):
            continue
        if kind is None and line in HEADERS:
            kind = line.split(",")[1]
            continue
        a, b = split_pair(line, lineno)
        if kind is None:
            if a not in DIRECTIVES:
                raise TableError("line %d: unknown directive %r" % (lineno, a))
            if a in directives:
                raise TableError("line %d: duplicate %s" % (lineno, a))
            directives[a] = parse_number(b, lineno)
            if directives[a] <= 0:
                raise TableError("line %d: %s must be > 0" % (lineno, a))
            continue
        points.append((parse_number(a, lineno), parse_number(b, lineno)))
    thickness = directives.get("thickness_m")
    check_table(kind, thickness, points)
    return kind, thickness, points


def check_table(kind, thickness, points):
    if kind is None:
        raise TableError("no header line")
    if (kind == "stress_Pa") != (thickness is not None):
        raise TableError("thickness_m is required with stress_Pa and forbidden otherwise")
    if len(points) < 2:
        raise TableError("need at least two data points")
    for (e0, _), (e1, _) in zip(points, points[1:]):
        if not e1 > e0:
            raise TableError("strain not strictly increasing at %r" % e1)
    if points[0][0] >= 0 and points[0] != (0.0, 0.0):
        raise TableError("tension-only table must start with the point 0,0")


def evaluate(points, e):
    """Force per unit width from a parsed table (linear, ends extended)."""
    if points[0][0] >= 0 and e <= 0:
        return 0.0
    i = 1
    while i < len(points) - 1 and e > points[i][0]:
        i += 1
    (e0, v0), (e1, v1) = points[i - 1], points[i]
    return v0 + (v1 - v0) * (e - e0) / (e1 - e0)


# ---------------------------------------------------------------- commands

def write_tables(tables, out_dir):
    for name, text in tables.items():
        (Path(out_dir) / name).write_text(text, encoding="ascii", newline="\n")
        print("wrote %s" % (Path(out_dir) / name))


def check_tables(tables, out_dir):
    """Return a list of problems (empty when every table on disk is current)."""
    problems = []
    for name, text in tables.items():
        path = Path(out_dir) / name
        if not path.exists():
            problems.append("%s: missing" % path)
        elif path.read_bytes() != text.encode("ascii"):
            problems.append("%s: differs from the derivation" % path)
    return problems


def max_relative_deviation(points, tension, k_small, k_large, lo=0.02, hi=1.0, n=980):
    """Largest |table - model| / model for e in [lo, hi]: linearisation error.

    Below the first sample (0.02) the relative error is dominated by the
    first segment's slope, which the summary reports separately.
    """
    worst = 0.0
    for i in range(n + 1):
        e = lo + (hi - lo) * i / n
        model = tension(e, k_small, k_large)
        worst = max(worst, abs(evaluate(points, e) - model) / model)
    return worst


def coupling_softening(row):
    """k1^2 / (k0 k2) of one row after ARCSim's clamping.

    If the transverse direction were free (S_vv = 0) instead of held
    (G_vv = 0), the along-warp stiffness would drop by this fraction (and the
    along-weft stiffness by the same fraction); the tables neglect it.
    """
    k0, k1, k2 = (max(x, 0.0) for x in row[:3])
    return k1 * k1 / (k0 * k2) if k0 > 0 and k2 > 0 else 0.0


def negative_entries(stretching):
    """Negative entries no table uses (a used one is reported as clamped instead)."""
    used = {(r, col) for col, row, _ in DIRECTIONS.values() for r in (0, row)}
    return [(r, c, v) for r, row in enumerate(stretching)
            for c, v in enumerate(row) if v < 0 and (r, c) not in used]


def summary(source_dir, out_dir):
    """Markdown summary of the tables on disk (tension and slopes in N/m)."""
    cols = " | ".join("T(%g)" % e for e in SUMMARY_STRAINS)
    lines = ["| table | %s | first-segment slope | model slope at 0 = 2*k_row0"
             " | max rel. dev. from model, e in [0.02, 1] |" % cols,
             "|---|" + "---:|" * (len(SUMMARY_STRAINS) + 3)]
    notes = []
    for fabric in FABRICS:
        stretching, _ = load_source(source_dir, fabric)
        for direction in DIRECTIONS:
            name = table_name(fabric, direction)
            _, _, points = parse_table((Path(out_dir) / name).read_text(encoding="ascii"))
            k_small, k_large = used_stiffness(stretching, direction)
            values = " | ".join("%.4g" % evaluate(points, e) for e in SUMMARY_STRAINS)
            slope = (points[1][1] - points[0][1]) / (points[1][0] - points[0][0])
            dev = max_relative_deviation(points, TENSION[direction], k_small, k_large)
            lines.append("| %s | %s | %.4g | %.4g | %.1f %% |"
                         % (name, values, slope, max(2 * k_small, 0.0), 100 * dev))
            if min(k_small, k_large) < 0:
                notes.append("%s: a used stiffness is negative and was clamped to 0" % name)
            falling = ["%g-%g" % (e0, e1) for (e0, v0), (e1, v1) in zip(points, points[1:])
                       if v1 < v0]
            if falling:
                notes.append("%s: tension falls (negative slope, unstable) on e = %s"
                             % (name, ", ".join(falling)))
        warp, weft = diagonal_stiffening(stretching)
        notes.append("%s_shear.csv: k_d = 2*k3 = %.4g N/m at small strain (row 0), %.4g N/m from "
                     "e = 1/6 (row 3); under uniaxial stretch the diagonals add k3 = %.4g N/m, "
                     "%.1f %% of the warp's 2*k0 and %.1f %% of the weft's 2*k2"
                     % (fabric, *(max(2 * k, 0.0) for k in used_stiffness(stretching, "shear")),
                        max(stretching[0][3], 0.0), 100 * warp, 100 * weft))
        notes.append("%s.json: Poisson softening k1^2/(k0*k2) if the transverse direction were "
                     "free: row 0 %.1f %%, row 1 (warp) %.1f %%, row 5 (weft) %.1f %%"
                     % (fabric, *(100 * coupling_softening(stretching[r]) for r in (0, 1, 5))))
        for r, c, v in negative_entries(stretching):
            notes.append("%s.json stretching[%d][%d] = %r < 0 (unused here; ARCSim clamps to 0)"
                         % (fabric, r, c, v))
    if not any("used stiffness" in n for n in notes):
        notes.insert(0, "No stiffness used by these tables is negative (nothing clamped).")
    return "\n".join(lines + [""] + notes) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", default=str(DEFAULT_SOURCE),
                        help="folder with the Wang 2011 JSON files (default: %(default)s)")
    parser.add_argument("--out", default=str(DEFAULT_OUT),
                        help="folder of the CSV tables (default: %(default)s)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true",
                      help="regenerate in memory; exit 1 if a CSV on disk differs")
    mode.add_argument("--summary", action="store_true",
                      help="print tension of the tables on disk at e = 0.05, 0.1667, 0.5")
    args = parser.parse_args(argv)

    if args.summary:
        sys.stdout.write(summary(args.source, args.out))
        return 0
    tables = generate_all(args.source)
    if args.check:
        problems = check_tables(tables, args.out)
        for p in problems:
            print("derive_wang2011_tables: " + p, file=sys.stderr)
        if problems:
            print("derive_wang2011_tables: run `%s` to regenerate" % REGENERATE_COMMAND,
                  file=sys.stderr)
            return 1
        print("derive_wang2011_tables: %d tables up to date" % len(tables))
        return 0
    write_tables(tables, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
