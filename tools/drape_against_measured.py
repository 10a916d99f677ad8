#!/usr/bin/python3
"""fabform's Cusick drapes against measured ones: the table and the mean absolute error.

Why: a drape coefficient is worth what it predicts of the tester. Petrak et al. 2025 measured six
woven fabrics on KES-FB and on a drape tester and simulated them in CLO3D
(materials/petrak2025/fabrics.csv); studies/cusick_measured.toml runs them in fabform. This tool
sets fabform's mean over the specimens beside the measurement and CLO3D's figure, fabric by fabric,
and gives each simulator's mean absolute error in points of drape coefficient (issue 22's target
for fabform: at most 5).

Usage: /usr/bin/python3 tools/drape_against_measured.py STUDY_DIR
  STUDY_DIR: a finished `fabform study studies/cusick_measured.toml --out STUDY_DIR`.
Prints the table (Markdown) and writes it to STUDY_DIR/against_measured.md. Exit status 2 with one
line naming the file when an input is missing or malformed. Standard library only.
"""
import csv
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from commented_csv import Malformed, read_rows  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
MEASURED = ROOT / "materials" / "petrak2025" / "fabrics.csv"
FABRIC_OF_WARP = re.compile(r"petrak2025/(\w+)_warp\.csv$")
SUMMARY_COLUMNS = ("fabric.warp", "specimens", "converged", "drape_coefficient mean", "drape_coefficient sd",
                   "drape.folds mean")
MEASURED_COLUMNS = ("id", "composition", "areal_mass_g_m2", "measured_dc", "clo3d_dc")


def number(text, path, line, what):
    try:
        return float(text)
    except (TypeError, ValueError):
        raise Malformed("%s:%d: %s is not a number: %r" % (path, line, what, text))


def comparison(study_dir):
    measured = {row["id"]: row for _, row in read_rows(MEASURED, MEASURED_COLUMNS)}
    summary = study_dir / "study_specimens.csv"
    rows = read_rows(summary, SUMMARY_COLUMNS)
    seen = set()
    lines = ["| fabric | measured DC (%) | fabform DC (%), mean ± sd | fabform − measured | folds | CLO3D DC (%) | CLO3D − measured |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    ours, theirs = [], []
    for line, row in rows:
        match = FABRIC_OF_WARP.search(row.get("fabric.warp") or "")
        if not match or match.group(1) not in measured:
            raise Malformed("%s:%d: a case that is none of %s's fabrics" % (summary, line, MEASURED.name))
        fabric = measured[match.group(1)]
        if fabric["id"] in seen:
            raise Malformed("%s:%d: %s a second time: one case a fabric" % (summary, line, fabric["id"]))
        seen.add(fabric["id"])
        if not row.get("drape_coefficient mean"):
            raise Malformed("%s:%d: no converged specimen of %s" % (summary, line, fabric["id"]))
        mean = 100 * number(row["drape_coefficient mean"], summary, line, "drape_coefficient mean")
        sd = row.get("drape_coefficient sd") or ""
        real = 100 * number(fabric["measured_dc"], MEASURED, 0, "measured_dc")
        clo = 100 * number(fabric["clo3d_dc"], MEASURED, 0, "clo3d_dc")
        ours.append(abs(mean - real))
        theirs.append(abs(clo - real))
        lines.append("| %s (%s, %s g/m²) | %.1f | %.1f ± %s (%s of %s) | %+.1f | %s | %.1f | %+.1f |" % (
            fabric["id"], fabric["composition"], fabric["areal_mass_g_m2"], real, mean,
            "%.1f" % (100 * number(sd, summary, line, "drape_coefficient sd")) if sd else "-", row["converged"],
            row["specimens"], mean - real,
            row["drape.folds mean"], clo, clo - real))
    lines += ["", "Mean absolute error over %d fabrics: fabform %.1f points, CLO3D %.1f points (target for fabform: 5)"
              % (len(ours), sum(ours) / len(ours), sum(theirs) / len(theirs))]
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) != 1:
        print("usage: drape_against_measured.py STUDY_DIR", file=sys.stderr)
        return 2
    study_dir = pathlib.Path(argv[0])
    try:
        text = comparison(study_dir)
        (study_dir / "against_measured.md").write_text(text)
    except (Malformed, csv.Error, OSError) as error:
        print("drape_against_measured: %s" % error, file=sys.stderr)
        return 2
    print(text, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
