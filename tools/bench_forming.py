#!/usr/bin/python3
"""What friction costs a forming run: the cup scene with and without it, in one run.

Why: the forming issue's target is that the cup, at its shipped resolution, converges at every
load step with newton in at most 3 × the time of the same scene without friction. Timings on
a shared machine drift, so the two runs take turns, the ratio is taken pair by pair, and its
median is what counts.

What it does: runs `build/fabform run scenes/cup.toml` as shipped (μ = 0.3 between the knit and
the punch) and with `--set body.0.friction=0` (the punch frictionless; the blank holder keeps
its friction, which is how it holds), --runs times each, in turns; reads each run's
result.json and prints, per scene, the median solver seconds (`solve_seconds`) and total
iterations, whether every step converged, the figures the cup is for (largest strain, largest
draw-in), and the median of the pairs' time ratios against the target.

Usage (after tools/setup.sh):
  /usr/bin/python3 tools/bench_forming.py [--runs N] [--out DIR]
Writes each run into DIR (default results/bench_forming). Exit status 0 when the target is met,
1 when not, 2 on bad input or a run that failed to run. Standard library only.
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FABFORM = ROOT / "build" / "fabform"
SCENE = ROOT / "scenes" / "cup.toml"
TARGET_RATIO = 3.0
VARIANTS = (("friction", []), ("frictionless punch", ["--set", "body.0.friction=0"]))


def run(variant: str, extra: list, out: pathlib.Path) -> dict:
    command = [str(FABFORM), "run", str(SCENE), "--out", str(out), "--quiet", *extra]
    status = subprocess.run(command, stderr=subprocess.PIPE, text=True)
    if status.returncode not in (0, 3):
        sys.exit(f"bench_forming.py: {variant}: fabform exited {status.returncode}: {status.stderr.strip()}")
    return json.loads((out / "result.json").read_text())


def every_step_converged(result: dict) -> bool:
    steps = result.get("steps", [])
    return result["converged"] and len(steps) == result.get("load_steps", -1) and all(s["converged"] for s in steps)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="runs of each variant, in turns (default 3)")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "results" / "bench_forming")
    args = parser.parse_args()
    if args.runs < 1:
        print("bench_forming.py: --runs must be at least 1", file=sys.stderr)
        return 2
    results = {variant: [] for variant, _ in VARIANTS}
    for r in range(args.runs):
        for variant, extra in VARIANTS:
            results[variant].append(run(variant, extra, args.out / f"{variant.replace(' ', '_')}_{r}"))
    print(f"cup ({results['friction'][0]['nodes']} nodes, {results['friction'][0]['load_steps']} load steps), "
          f"{args.runs} runs each, in turns")
    print("| variant | every step converged | iterations | solve seconds (median) | largest strain | largest draw-in (mm) |")
    print("|---|---|---|---|---|---|")
    for variant, _ in VARIANTS:
        runs = results[variant]
        f = runs[0]["figures"]
        strain = max(f["max_warp_strain"]["strain"], f["max_weft_strain"]["strain"])
        print(f"| {variant} | {all(every_step_converged(x) for x in runs)} | {runs[0]['iterations']} | "
              f"{statistics.median(x['solve_seconds'] for x in runs):.3f} | {100 * strain:.1f} % | "
              f"{1000 * f['draw_in_max_m']:.1f} |")
    ratios = [a["solve_seconds"] / b["solve_seconds"] for a, b in zip(*results.values())]
    ratio = statistics.median(ratios)
    converged = all(every_step_converged(x) for runs in results.values() for x in runs)
    met = converged and ratio <= TARGET_RATIO
    print(f"friction / frictionless punch, solve time: median {ratio:.2f} "
          f"(pairs {', '.join(f'{x:.2f}' for x in ratios)}); target <= {TARGET_RATIO:g} with every step "
          f"converged: {'met' if met else 'NOT met'}")
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
