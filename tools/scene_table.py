#!/usr/bin/python3
"""Run every shipped scene and print the README's table of measured figures.

Why: the README must give each scene's iterations and time as measured, by a command anyone can
re-run. This runs `build/fabform run scenes/NAME.toml` for each scene, reads result.json and
convergence.csv, and prints one Markdown row per scene. Standard library only.

Usage (after tools/setup.sh):  /usr/bin/python3 tools/scene_table.py [--out DIR]
"""
import argparse
import csv
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
SEED_MOLD_CRITERION_N = 2.4e-2  # seed 003's stop criterion for its mold experiment


def run_scene(scene: pathlib.Path, out: pathlib.Path) -> dict:
    command = [str(ROOT / "build" / "fabform"), "run", str(scene), "--out", str(out), "--quiet"]
    status = subprocess.run(command, stderr=subprocess.PIPE, text=True).returncode
    if status != 0:
        sys.exit(f"{scene.name}: fabform exited {status}")
    return json.loads((out / "result.json").read_text())


def first_iteration_at_or_below(history: pathlib.Path, threshold: float) -> str:
    """The first iteration whose residual is at most `threshold`; a run in load steps meets a
    criterion in every step, so it has none to give."""
    with history.open() as f:
        reader = csv.DictReader(f)
        if "step" in (reader.fieldnames or []):
            return "(in steps)"
        for row in reader:
            if float(row["residual_N"]) <= threshold:
                return row["iteration"]
    return "never"


def figure(value, spec: str) -> str:
    """A result.json figure as the table shows it; null (none to measure: no body) as a dash."""
    return "–" if value is None else format(value, spec)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "results"), help="folder for the runs")
    args = parser.parse_args()
    print("| scene | nodes | e (N) | iterations | wall time (s) | final ‖V‖∞ (N) | "
          "iteration at ‖V‖∞ ≤ 2.4e-2 N | contact nodes | max penetration (m) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for scene in sorted((ROOT / "scenes").glob("*.toml")):
        out = pathlib.Path(args.out) / scene.stem
        r = run_scene(scene, out)
        seed_it = first_iteration_at_or_below(out / "convergence.csv", SEED_MOLD_CRITERION_N)
        print(f"| {scene.stem} | {r['nodes']} | {r['tolerance_N']:.3g} | {r['iterations']} | "
              f"{r['wall_seconds']:.1f} | {r['residual_recomputed_N']:.3g} | {seed_it} | "
              f"{r['contact_nodes']} | {figure(r['max_penetration_m'], '.2g')} |")


if __name__ == "__main__":
    main()
