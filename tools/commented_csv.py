"""A CSV whose '#' lines are comments (a data file's provenance), read with its line numbers.

Why: materials/petrak2025/fabrics.csv carries its source in '#' lines and is read by two tools
(derive_petrak2025.py, drape_against_measured.py), which must both name a bad file's line.
Standard library only.
"""
import csv


class Malformed(Exception):
    """The file cannot be read as asked: the message names it (and its line, where there is one)."""


def read_rows(path, columns, what="rows"):
    """[(line, row)] of the CSV at `path` with its '#' lines skipped; every one of `columns` must be
    a column and there must be a row (`what` names the rows in the message)."""
    try:
        with open(path, newline="") as f:
            numbered = [(n, line) for n, line in enumerate(f, 1) if not line.startswith("#")]
    except FileNotFoundError:
        raise Malformed("%s: no such file" % path)
    reader = csv.DictReader(line for _, line in numbered)
    rows = list(zip((n for n, _ in numbered[1:]), reader))
    missing = [c for c in columns if c not in (reader.fieldnames or [])]
    if missing:
        raise Malformed("%s: no column %s" % (path, ", ".join(missing)))
    if not rows:
        raise Malformed("%s: no %s" % (path, what))
    return rows
