#!/usr/bin/python3
"""Convergence-plot regression tests: every shipped scene keeps its golden history in
tests/goldens/SCENE.csv; `check` re-runs the scene and compares, `bless` rewrites the goldens
after an intended change and says what changed.

The comparison (the band):
  - iterations to converge within ±10 % of the golden count (at least ±1);
  - the residual curve within ±0.5 decades of the golden one, compared at the same fraction of
    the run (golden iteration i against new iteration round(i · n_new / n_golden)), so a run
    that converges a few iterations sooner or later is not flagged for the shift alone.
On a failure, `check` writes DIR/overlay_SCENE.png (golden and new curves) and says where
they part. Exit status: 0 inside the band, 1 outside it, 2 bad input (one line naming the file).

Usage (after tools/setup.sh):
  /usr/bin/python3 tools/goldens.py check SCENE [--out DIR]
  /usr/bin/python3 tools/goldens.py bless [SCENE ...]        # default: every shipped scene
"""
import argparse
import math
import os
import pathlib
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import plot_convergence as pc  # noqa: E402  (the tools share the history reader and the plot style)

ROOT = pathlib.Path(__file__).resolve().parent.parent
GOLDENS = ROOT / "tests" / "goldens"
# OpenBLAS picks its kernels by the CPU (the dome's newton took 27 to 45 iterations under
# different ones, all converged): the goldens pin those of any x86-64 with AVX2, so that a
# history depends on the code, not on which machine of the kind runs it.
PINNED_ENVIRONMENT = {**os.environ, "OPENBLAS_CORETYPE": "Haswell"}
ITERATION_TOLERANCE = 0.10
BAND_DECADES = 0.5


def run_scene(scene: str, out: pathlib.Path) -> pathlib.Path:
    path = ROOT / "scenes" / f"{scene}.toml"
    if not path.is_file():
        raise pc.InputError(f"{path}: no such scene")
    command = [str(ROOT / "build" / "fabform"), "run", str(path), "--out", str(out), "--quiet"]
    status = subprocess.run(command, stderr=subprocess.PIPE, text=True, env=PINNED_ENVIRONMENT)
    if status.returncode not in (0, 3):
        raise pc.InputError(f"{path}: fabform exited {status.returncode}: {status.stderr.strip()}")
    return out


def log10(value: float) -> float:
    return math.log10(value) if value > 0 else -300.0


def first_parting(golden: tuple, new: tuple) -> tuple:
    """(golden iteration, new iteration, decades apart) where the curves first leave the band,
    or None."""
    g_it, g_res = golden
    n_it, n_res = new
    scale = (len(n_it) - 1) / max(len(g_it) - 1, 1)
    for i, residual in enumerate(g_res):
        j = min(round(i * scale), len(n_res) - 1)
        apart = abs(log10(n_res[j]) - log10(residual))
        if apart > BAND_DECADES:
            return g_it[i], n_it[j], apart
    return None


def overlay(scene: str, golden: tuple, new: tuple, tolerance: float, out: pathlib.Path) -> pathlib.Path:
    plt = pc.pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    pc.draw(ax, *golden, "golden", "-")
    pc.draw(ax, *new, "new", "--")
    pc.finish(ax, tolerance, f"{scene}: golden and new")
    fig.tight_layout()
    out.mkdir(parents=True, exist_ok=True)
    written = pc.save(fig, out / f"overlay_{scene}")
    plt.close(fig)
    return written[0]


def compare(scene: str, out: pathlib.Path) -> int:
    golden = pc.read_history(GOLDENS / f"{scene}.csv")
    with tempfile.TemporaryDirectory() as work:
        run = run_scene(scene, pathlib.Path(work) / scene)
        new = pc.read_history(run / "convergence.csv")
        result = pc.read_result(run)
    g_n, n_n = golden[0][-1], new[0][-1]
    allowed = max(1, round(ITERATION_TOLERANCE * g_n))
    problems = []
    if not result["converged"]:
        problems.append(f"did not converge ({result['termination']}) after {n_n} iterations")
    if abs(n_n - g_n) > allowed:
        problems.append(f"converged in {n_n} iterations, golden {g_n} (allowed ±{allowed})")
    parting = first_parting(golden, new)
    if parting:
        problems.append(f"curves part at golden iteration {parting[0]} / new {parting[1]}: "
                        f"{parting[2]:.2f} decades apart (band {BAND_DECADES})")
    if not problems:
        print(f"{scene}: {n_n} iterations (golden {g_n}), curve inside the band")
        return 0
    picture = overlay(scene, golden, new, float(result["tolerance_N"]), out)
    for p in problems:
        print(f"{scene}: {p}")
    print(f"{scene}: overlay in {picture}")
    return 1


def write_golden(scene: str, history: tuple) -> None:
    GOLDENS.mkdir(parents=True, exist_ok=True)
    path = GOLDENS / f"{scene}.csv"
    temporary = path.with_name(path.name + ".tmp")
    with temporary.open("w") as f:
        f.write("iteration,residual_N\n")
        for it, res in zip(*history):
            f.write(f"{it},{res:.10g}\n")
    temporary.replace(path)


def bless(scenes: list) -> int:
    for scene in scenes:
        path = GOLDENS / f"{scene}.csv"
        old = pc.read_history(path) if path.is_file() else None
        with tempfile.TemporaryDirectory() as work:
            new = pc.read_history(run_scene(scene, pathlib.Path(work) / scene) / "convergence.csv")
        write_golden(scene, new)
        if old is None:
            print(f"{scene}: new golden, {new[0][-1]} iterations, final {new[1][-1]:.3g} N")
            continue
        parting = first_parting(old, new)
        change = "curve inside the old band" if not parting else \
            f"curve leaves the old band at iteration {parting[0]} ({parting[2]:.2f} decades)"
        print(f"{scene}: {old[0][-1]} -> {new[0][-1]} iterations, final {old[1][-1]:.3g} -> "
              f"{new[1][-1]:.3g} N; {change}")
    return 0


def shipped() -> list:
    return sorted(p.stem for p in (ROOT / "scenes").glob("*.toml"))


def main(argv) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    check = sub.add_parser("check", help="re-run a scene and compare with its golden")
    check.add_argument("scene")
    check.add_argument("--out", default=str(ROOT / "results" / "goldens"), help="where overlays go")
    again = sub.add_parser("bless", help="re-run scenes and rewrite their goldens")
    again.add_argument("scenes", nargs="*")
    args = parser.parse_args(argv)
    try:
        if args.command == "check":
            return compare(args.scene, pathlib.Path(args.out))
        return bless(args.scenes or shipped())
    except pc.InputError as error:
        print(f"goldens.py: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
