#!/usr/bin/python3
"""The study issue's targets, measured in one run:

1. A 24-case dome study at fabric divisions [40, 40] (41 × 41 nodes) run by `fabform study`
   with --jobs 2 against the same 24 cases one after another (--jobs 1), taking turns, best of
   --repeat each; prints both times and their ratio (target ≤ 0.6). Each way uses the whole
   machine: --jobs 1 gives its case every core, --jobs 2 shares them out.
2. With --slurm, the same study on Slurm (tools/slurm_local.sh must have started it, or give
   --start-slurm): the overhead per case, submit to collected, as the time beyond the local
   pool's with as many cases at once (the cluster's CPUs), per case on its CPU; and a one-case
   study's time on Slurm beyond its time in the local pool.

Usage: /usr/bin/python3 tools/bench_study.py [--fabform build/fabform] [--repeat N] [--slurm]
"""
import argparse
import csv
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
CASES = 24


def study_text(cases: int) -> str:
    """The dome at 41 × 41 nodes: solver (dynamic, newton) × tolerance × the starting bump's
    height, 24 cases of a speed/accuracy study (about 0.5 to 2.5 s each); or its first case."""
    grid = ('"solver.name" = ["dynamic", "newton"]\n"solver.tolerance_N" = [1e-3, 1e-4, 1e-5, 1e-6]\n'
            '"initial.height_m" = [0.04, 0.05, 0.06]' if cases == CASES else
            '"solver.name" = ["dynamic"]\n"solver.tolerance_N" = [1e-3]\n"initial.height_m" = [0.04]')
    return f"""[study]
name = "bench_dome"
scene = "{ROOT / 'scenes' / 'dome.toml'}"
figures = ["residual_recomputed_N", "figures.max_warp_strain"]

[study.set]
"fabric.divisions" = [40, 40]

[grid]
{grid}
"""


def timed_study(fabform: str, spec: pathlib.Path, out: pathlib.Path, *extra: str) -> float:
    shutil.rmtree(out, ignore_errors=True)
    start = time.monotonic()
    done = subprocess.run([fabform, "study", str(spec), "--out", str(out), "--quiet", *extra],
                          capture_output=True, text=True)
    seconds = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"bench_study.py: the study failed ({done.returncode}): {done.stderr.strip().splitlines()[-1:]}")
    return seconds


def case_seconds(out: pathlib.Path) -> list:
    with (out / "study.csv").open(newline="") as f:
        return [float(row["wall_seconds"]) for row in csv.DictReader(f)]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fabform", default=str(ROOT / "build" / "fabform"))
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--slurm", action="store_true", help="also measure the overhead per case on Slurm")
    args = parser.parse_args()
    cores = os.cpu_count() or 1
    with tempfile.TemporaryDirectory(prefix="fabform-bench-study-") as tmp:
        folder = pathlib.Path(tmp)
        spec = folder / "bench.toml"
        spec.write_text(study_text(CASES))
        one, two = [], []
        for _ in range(args.repeat):  # taking turns, so that a drift of the machine hits both
            one.append(timed_study(args.fabform, spec, folder / "one", "--jobs", "1"))
            two.append(timed_study(args.fabform, spec, folder / "two", "--jobs", "2"))
        serial = sum(case_seconds(folder / "one"))
        print(f"{CASES} dome cases at 41 x 41 nodes on {cores} cores (best of {args.repeat}):")
        print(f"  --jobs 1 (one after another): {min(one):.2f} s (the cases' own wall seconds sum to {serial:.2f} s)")
        print(f"  --jobs 2:                      {min(two):.2f} s")
        print(f"  ratio: {min(two) / min(one):.3f} (target <= 0.6)")
        if args.slurm:
            spec_one = folder / "one_case.toml"
            spec_one.write_text(study_text(1))
            local = timed_study(args.fabform, spec, folder / "local", "--jobs", str(cores))
            slurm = timed_study(args.fabform, spec, folder / "slurm", "--on", "slurm", "--threads-per-case", "1")
            single = timed_study(args.fabform, spec_one, folder / "single", "--on", "slurm", "--threads-per-case", "1")
            single_local = timed_study(args.fabform, spec_one, folder / "single_local", "--jobs", "1",
                                       "--threads-per-case", "1")
            print(f"Slurm, the same {CASES} cases, {cores} at once: {slurm:.2f} s; local pool, {cores} at once: {local:.2f} s")
            print(f"  overhead per case (submit to collected, beyond the local pool, on its CPU): "
                  f"{(slurm - local) * cores / CASES:.2f} s (target <= 2 s)")
            print(f"  a one-case study: {single:.2f} s on Slurm, {single_local:.2f} s locally: "
                  f"{single - single_local:.2f} s more from submit to collected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
