#!/usr/bin/python3
"""How heavy and how quick a run's report is with its 3-D view: the size of report.html with what
it loads (view3d/, the pictures), and the time headless Chromium takes from opening it to the
view's first frame drawn, median of --runs openings (software WebGL, SwiftShader: these machines
have no GPU, so a desktop with one is faster).

Why: the issue's targets are the shipped cup's report showing its first frame in ≤ 2 s, and the
cup at 400 × 400 divisions (160 k nodes, 12 load steps) in ≤ 5 s.

Usage: /usr/bin/python3 tools/bench_view3d.py RUN_DIR [RUN_DIR ...] [--runs 3]
(each RUN_DIR with report.html written by tools/report.py). It prints, per run folder, the sizes,
the view's data-state, its first frame (ms from the page's start: data-loaded-ms, which includes
reading data.js; data-first-frame-ms from the viewer's start) with min/median/max. Exit status 2
when a folder has no report or the view did not come up ("ready").
"""
import argparse
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile

SOFTWARE_WEBGL = ["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]


def megabytes(paths) -> float:
    return sum(p.stat().st_size for p in paths if p.is_file()) / 1e6


def open_once(page: pathlib.Path) -> dict:
    """The view's data- attributes after one opening (real time: no virtual time budget)."""
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(["chromium", "--headless", "--no-sandbox", *SOFTWARE_WEBGL, f"--user-data-dir={profile}",
                               "--dump-dom", page.resolve().as_uri()], capture_output=True, text=True, timeout=300)
    tag = re.search(r'<div id="view3d"[^>]*>', done.stdout)
    return dict(re.findall(r'data-([a-z-]+)="([^"]*)"', tag.group(0))) if tag else {}


def main(argv) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs_dirs", nargs="+", type=pathlib.Path, metavar="RUN_DIR")
    parser.add_argument("--runs", type=int, default=3, help="openings per report (default 3)")
    args = parser.parse_args(argv)
    status = 0
    for run in args.runs_dirs:
        page = run / "report.html"
        if not page.is_file():
            print(f"bench_view3d.py: {page}: no such file (tools/report.py {run} writes it)", file=sys.stderr)
            return 2
        total = megabytes([page, *run.glob("*.png"), *(run / "view3d").glob("*")])
        data = megabytes([run / "view3d" / "data.js"])
        views = [open_once(page) for _ in range(args.runs)]
        states = {v.get("state", "none") for v in views}
        if states != {"ready"}:
            print(f"{run}: the view did not come up: {sorted(states)}")
            status = 2
            continue
        loaded = [float(v["loaded-ms"]) for v in views]
        drawn = [float(v["first-frame-ms"]) for v in views]
        print(f"{run}: report {total:.1f} MB with what it loads (view3d/data.js {data:.1f} MB); first frame "
              f"{statistics.median(loaded) / 1000:.2f} s after opening (min {min(loaded) / 1000:.2f}, max "
              f"{max(loaded) / 1000:.2f}; the viewer's own part {statistics.median(drawn) / 1000:.2f} s), "
              f"median of {args.runs}")
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
