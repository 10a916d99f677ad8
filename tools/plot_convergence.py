#!/usr/bin/python3
"""The convergence plot of a run: ‖V‖∞ on a log axis against iteration, as seed 003's Figure 10,
with the tolerance line; a run that did not converge says so in its title.

Why: engineers judge a run by this curve and keep it as a regression test
(tools/goldens.py overlays a golden curve on it). Reads RUN_DIR/convergence.csv and
RUN_DIR/result.json, writes RUN_DIR/convergence.png and convergence.svg (or --out BASE.png/.svg).

Usage: /usr/bin/python3 tools/plot_convergence.py RUN_DIR [--out BASE]
Needs python3-matplotlib (Debian); exits 2 with one line when an input is missing or malformed.
"""
import argparse
import csv
import json
import math
import pathlib
import sys

REQUIRED = ("iteration", "residual_N")


class InputError(Exception):
    """A file this tool reads is missing or malformed: one line naming it."""


def read_history(path: pathlib.Path) -> tuple:
    """(iterations, residuals) of a convergence.csv; InputError names the file and line."""
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        missing = [c for c in REQUIRED if c not in (reader.fieldnames or [])]
        if missing:
            raise InputError(f"{path}:1: missing column(s) {', '.join(missing)}")
        iterations, residuals = [], []
        # A run in load steps counts iterations within each step: laid end to end, step after
        # step, they make one run-long count (each step's iteration 0 is the end of the last).
        in_steps = "step" in (reader.fieldnames or [])
        step, before = None, 0
        for row in reader:
            try:
                iteration = int(row["iteration"])
                residual = float(row["residual_N"])
                if in_steps and row["step"] != step:
                    step, before = row["step"], iterations[-1] if iterations else 0
                iterations.append(before + iteration)
                residuals.append(residual)
            except (TypeError, ValueError):
                raise InputError(f"{path}:{reader.line_num}: not a number in iteration or residual_N")
    if not iterations:
        raise InputError(f"{path}: no iterations")
    return iterations, residuals


def read_result(run: pathlib.Path) -> dict:
    path = run / "result.json"
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError) as error:
        raise InputError(f"{path}: {error}")


def positive(values: list) -> list:
    """Residuals for a log axis: 0 (an exact equilibrium) and NaN drop out of the line."""
    return [v if v > 0 and math.isfinite(v) else float("nan") for v in values]


def title_of(result: dict) -> str:
    name = result.get("scene", "run")
    solver = result.get("solver", "?")
    if result.get("converged"):
        return f"{name} ({solver}): converged in {result.get('iterations')} iterations"
    return f"{name} ({solver}): DID NOT CONVERGE ({result.get('termination', '?')}) after {result.get('iterations')}"


def draw(ax, iterations, residuals, label, style="-"):
    ax.plot(iterations, positive(residuals), style, label=label, linewidth=1.2)


def finish(ax, tolerance: float, title: str) -> None:
    ax.axhline(tolerance, color="red", linestyle="--", linewidth=1, label=f"e = {tolerance:g} N")
    ax.set_yscale("log")
    ax.set_xlabel("iteration")
    ax.set_ylabel("‖V‖∞ (N)")
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()


def write_text(path: pathlib.Path, text: str) -> None:
    """Writes text under a temporary name, then renames it: never a half-written file."""
    temporary = path.with_name(path.name + ".tmp")
    temporary.write_text(text, encoding="utf-8")
    temporary.replace(path)


def save(fig, base: pathlib.Path) -> list:
    written = []
    for ext in ("png", "svg"):
        path = base.with_suffix(f".{ext}")
        temporary = path.with_name(path.name + ".tmp")
        fig.savefig(temporary, format=ext)
        temporary.replace(path)  # never a half-written picture under the real name
        written.append(path)
    return written


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def plot_run(run: pathlib.Path, base: pathlib.Path) -> list:
    iterations, residuals = read_history(run / "convergence.csv")
    result = read_result(run)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    draw(ax, iterations, residuals, "‖V‖∞")
    finish(ax, float(result["tolerance_N"]), title_of(result))
    fig.tight_layout()
    written = save(fig, base)
    plt.close(fig)
    return written


def main(argv) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="a folder `fabform run` wrote")
    parser.add_argument("--out", help="base name of the pictures (default RUN/convergence)")
    args = parser.parse_args(argv)
    run = pathlib.Path(args.run)
    try:
        written = plot_run(run, pathlib.Path(args.out) if args.out else run / "convergence")
    except InputError as error:
        print(f"plot_convergence.py: {error}", file=sys.stderr)
        return 2
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
