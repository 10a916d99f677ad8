#!/usr/bin/python3
"""The report of a parameter study (`fabform study`): STUDY_DIR/study.html with each collected
figure plotted against each varied value (one line per combination of the other varied values),
and the table of cases, study.csv, as it stands (with specimens, each case's mean and scatter
from study_specimens.csv above it). It opens in a browser from the folder.

Why: a study is read as trends (what accuracy costs, how strain follows friction), which a table
hides. Rendered headless with matplotlib (Agg). Cases without a finished result (cancelled,
failed, missing) are left out of the plots and marked in the table.

Usage: /usr/bin/python3 tools/study_report.py STUDY_DIR
Writes into STUDY_DIR: study.html and study_F_K.png (figure F against varied key K), each under
a temporary name first, then renamed. `fabform study` runs it at its end.
Exits 2 with one line naming the file when an input is missing or malformed.
"""
import csv
import html
import json
import math
import multiprocessing
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import plot_convergence as pc  # noqa: E402  (InputError, write_text)
import report  # noqa: E402  (save_figure, report_main)

MAX_SERIES = 8  # more lines than this are one cloud of points


def read_study(folder: pathlib.Path) -> tuple:
    """(study.json as a dict, study.csv's rows as dicts)."""
    record, table = folder / "study.json", folder / "study.csv"
    for path in (record, table):
        if not path.is_file():
            raise pc.InputError(f"{path}: no such file")
    try:
        spec = json.loads(record.read_text())
        varied, figures = spec["varied"], spec["figures"]
    except (ValueError, KeyError) as error:
        raise pc.InputError(f"{record}: malformed ({error})")
    with table.open(newline="") as f:
        rows = list(csv.DictReader(f))
    for column in ["case", *varied, *figures, "converged", "termination"]:
        if rows and column not in rows[0]:
            raise pc.InputError(f"{table}:1: no column '{column}'")
    return spec, rows


def number(text: str):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def spread(values) -> bool:
    """Whether positive values span more than two decades (then an axis is logarithmic)."""
    return values and min(values) > 0 and max(values) / min(values) > 100


def plot(folder: pathlib.Path, rows, figure: str, key: str, others: list, name: str) -> pathlib.Path:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [r for r in rows if number(r[figure]) is not None]
    numeric_x = all(number(r[key]) is not None for r in rows)
    categories = list(dict.fromkeys(r[key] for r in rows))
    x_of = (lambda r: number(r[key])) if numeric_x else (lambda r: categories.index(r[key]))
    series = {}
    for r in done:
        label = ", ".join(f"{k} = {r[k]}" for k in others)
        series.setdefault(label, []).append((x_of(r), number(r[figure])))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    if len(series) > MAX_SERIES:
        series = {"all cases": [p for points in series.values() for p in points]}
    for label, points in series.items():
        points.sort()
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-" if len(series) > 1 or numeric_x else "o",
                label=label or None)
    if not numeric_x:
        ax.set_xticks(range(len(categories)), categories, rotation=20 if len(categories) > 3 else 0, ha="right")
    if numeric_x and spread([x_of(r) for r in rows]):
        ax.set_xscale("log")
    if spread([number(r[figure]) for r in done]):
        ax.set_yscale("log")
    ax.set_xlabel(key)
    ax.set_ylabel(figure)
    ax.grid(True, alpha=0.3)
    if any(series):
        ax.legend(fontsize="small")
    missing = len(rows) - len(done)
    ax.set_title(f"{figure} against {key}" + (f" ({missing} cases without it)" if missing else ""), fontsize="medium")
    fig.tight_layout()
    path = report.save_figure(fig, folder / name)
    plt.close(fig)
    return path


def table(rows, good) -> str:
    """An HTML table of CSV rows, a row that is not `good` marked."""
    e = html.escape
    columns = list(rows[0].keys()) if rows else []
    header = "".join(f"<th>{e(c)}</th>" for c in columns)
    body = "".join(("<tr>" if good(r) else '<tr class="bad">') +
                   "".join(f"<td>{e(r[c])}</td>" for c in columns) + "</tr>" for r in rows)
    return f"<table><tr>{header}</tr>\n{body}\n</table>"


def specimens_section(folder: pathlib.Path, spec: dict) -> str:
    """A study with specimens: each case's mean and scatter (study_specimens.csv), as a tester
    reports them; a case where some specimen did not converge is marked."""
    path = folder / "study_specimens.csv"
    specimens = spec.get("specimens", 1)
    if not isinstance(specimens, int):
        raise pc.InputError(f"{folder / 'study.json'}: malformed (specimens is not a whole number)")
    if specimens < 2 or not path.is_file():
        return ""
    with path.open(newline="") as f:
        rows = list(csv.DictReader(f))
    for column in ("specimens", "converged"):
        if rows and column not in rows[0]:
            raise pc.InputError(f"{path}:1: no column '{column}'")
    return (f"<h2>Over {specimens} specimens (initial.seed 1 to {specimens}): mean, sample "
            f"standard deviation, least and largest of the specimens that converged</h2>\n"
            + table(rows, lambda r: r["converged"] == r["specimens"]))


def page(spec: dict, rows, pictures: list, specimens: str = "") -> str:
    e = html.escape
    converged = sum(r["converged"] == "true" for r in rows)
    images = "".join(f'<figure><img src="{e(p)}" alt="{e(alt)}"><figcaption>{e(alt)}</figcaption></figure>'
                     for p, alt in pictures)
    fixed = ", ".join(f"{v['key']} = {v['text']}" for v in spec.get("set", [])) or "none"
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>fabform study: {e(spec['name'])}</title>
<style>
body {{ font-family: sans-serif; margin: 2em; color: #222; }}
table {{ border-collapse: collapse; margin-bottom: 1.5em; font-size: 0.9em; }}
th, td {{ text-align: left; padding: 0.2em 0.6em; border-bottom: 1px solid #ddd; }}
tr.bad {{ background: #fdd; }}
figure {{ display: inline-block; margin: 0 1em 1em 0; }} img {{ max-width: 36em; }}
.missing {{ color: #c00; font-weight: bold; }}
</style></head>
<body>
<h1>Study {e(spec['name'])}: {converged} of {len(rows)} cases converged</h1>
<p>Base scene {e(spec['scene'])}; set in every case: {e(fixed)}; varied: {e(", ".join(spec['varied']))}.
fabform {e(spec.get('fabform_version', '?'))}.</p>
<h2>Figures against the varied values</h2>
{images}
{specimens}
<h2>Cases</h2>
{table(rows, lambda r: r["converged"] == "true")}
<script>
// Pictures that did not load are named in place; the count is what a test checks.
window.addEventListener("load", () => {{
  const images = Array.from(document.images);
  const broken = images.filter(i => !(i.complete && i.naturalWidth > 0));
  for (const i of broken) {{
    const note = document.createElement("p");
    note.className = "missing";
    note.textContent = "missing picture: " + i.getAttribute("src");
    i.replaceWith(note);
  }}
  document.body.dataset.picturesShown = (images.length - broken.length) + "/" + images.length;
}});
</script>
</body></html>
"""


def make_report(folder: pathlib.Path) -> pathlib.Path:
    spec, rows = read_study(folder)
    varied = spec["varied"]
    plots = [(folder, rows, figure, key, [o for o in varied if o != key], f"study_{f}_{k}.png")
             for f, figure in enumerate([*spec["figures"], "iterations", "wall_seconds"])
             for k, key in enumerate(varied)]
    # The plots on every core: a study waits for its report, and its pictures are independent.
    with multiprocessing.get_context("fork").Pool(max(1, min(len(plots), os.cpu_count() or 1))) as pool:
        pool.starmap(plot, plots)
    pictures = [(name, f"{figure} against {key}") for _, _, figure, key, _, name in plots]
    path = folder / "study.html"
    pc.write_text(path, page(spec, rows, pictures, specimens_section(folder, spec)))
    return path


def main(argv) -> int:
    return report.report_main(argv, "study_report.py", "STUDY_DIR", make_report)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
