#!/usr/bin/python3
"""Derive fabform uniaxial tension-strain tables from Wang et al. 2011 fabric data.

Why this exists: fabform's spring model wants, for each yarn direction, a
one-dimensional curve "tension per unit width vs. engineering strain".  The
only real, measured fabric mechanics we can ship are the ARCSim
"data-driven elastic" tables of Wang, Ramamoorthi & O'Brien (SIGGRAPH 2011),
which describe a biaxial continuum (Green strain -> second Piola-Kirchhoff
stress, stiffness blended by strain and direction).  This script reads those
tables uniaxially -- stretch along warp (or weft) with zero transverse Green
strain -- and samples the result into the fabform material table format
(version 2, specified in materials/README.md).  Doing it in a script, with
the inputs checked against their recorded git blob ids, keeps the shipped
CSVs reproducible; `--check` lets a test prove the committed CSVs are what
this derivation produces.

Model (see materials/README.md and materials/source/wang2011_berkeley/FORMAT.md):
    w = 1 + e,  G = e + e^2/2,  t = clamp(6 e, 0, 1)
    k(e) = (1 - t) * max(2 k_row0, 0) + t * max(2 k_rowdir, 0)
    S = k(e) * G               (2nd Piola-Kirchhoff stress resultant, N/m)
    T = (1 + e) * S            (nominal tension per unit reference width, N/m)
warp: column 0 (k0) of rows 0 and 1 (0 deg); weft: column 2 (k2) of rows 0
and 5 (90 deg).

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

# direction -> (stretching column, direction row, angle from warp in degrees)
DIRECTIONS = {"warp": (0, 1, 0.0), "weft": (2, 5, 90.0)}

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


def tension(e, k_small, k_large):
    """Nominal tension per unit reference width (N/m) at engineering strain e."""
    green = e + 0.5 * e * e
    return (1.0 + e) * stiffness(e, k_small, k_large) * green


# ---------------------------------------------------------------- output

def fmt_value(x):
    """6 significant digits, never '-0'."""
    s = "%.6g" % x
    return "0" if s in ("-0", "0") else s


def fmt_strain(e):
    return "%.6f" % e


def header_lines(fabric, direction, k_small, k_large):
    sha, desc = FABRICS[fabric]
    col, row, angle = DIRECTIONS[direction]
    return [
        "# fabform material table, version 2 (format: materials/README.md)",
        "# fabric: %s (%s)" % (fabric, desc),
        "# direction: %s (ARCSim material %s axis)"
        % (direction, "u" if direction == "warp" else "v"),
        "# source: materials/source/wang2011_berkeley/%s.json" % fabric,
        "#   git blob sha1 %s" % sha,
        "#   origin: %s @ %s, %s/%s.json" % (ORIGIN_REPO, ORIGIN_COMMIT, ORIGIN_DIR, fabric),
        "# citation: %s" % CITATION,
        "# acknowledgement: material parameters from the UC Berkeley Garment Library",
        "#   (terms: materials/LICENSES/BerkeleyGarmentLibrary_README.txt)",
        "# derivation (materials/README.md): uniaxial stretch along %s, zero transverse" % direction,
        "#   Green strain; stretching column %d, rows 0 and %d (%g deg):" % (col, row, angle),
        "#   k_small = %r N/m, k_large = %r N/m" % (k_small, k_large),
        "#   G = e + e^2/2, t = clamp(6e,0,1), k = (1-t)*max(2*k_small,0) + t*max(2*k_large,0)",
        "#   tension = (1+e)*k*G  [N/m per unit reference width]; tension-only (0 in compression);",
        "#   fabform extends the last segment beyond the last point.",
        "# regenerate (from the repository root): %s" % REGENERATE_COMMAND,
    ]


def table_text(fabric, direction, stretching, density):
    """Complete CSV text for one fabric and direction."""
    k_small, k_large = used_stiffness(stretching, direction)
    lines = header_lines(fabric, direction, k_small, k_large)
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


def max_relative_deviation(points, k_small, k_large, lo=0.02, hi=1.0, n=980):
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
    return [(r, c, v) for r, row in enumerate(stretching)
            for c, v in enumerate(row) if v < 0]


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
            dev = max_relative_deviation(points, k_small, k_large)
            lines.append("| %s | %s | %.4g | %.4g | %.1f %% |"
                         % (name, values, slope, max(2 * k_small, 0.0), 100 * dev))
            if min(k_small, k_large) < 0:
                notes.append("%s: a used stiffness is negative and was clamped to 0" % name)
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
