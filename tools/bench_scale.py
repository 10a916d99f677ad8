#!/usr/bin/python3
"""How newton's time grows with the dome's size: `tools/bench_solvers.py --scale` (issue 23, item 7).

Why: the issue's targets are a million nodes (N = 1001) to 1e-6 N in 60 s and 4 GiB, and a time
that grows near-linearly, t(1001) / t(201) <= 30. This measures them, and says plainly what it
could not measure: a size that does not finish within --timeout is reported as over the timeout
(with the timeout), and the larger sizes after it are not run.

What it does: for each N in --sizes (nodes a side; default 101,201,401,1001) it runs
`fabform run scenes/dome.toml --set fabric.divisions=[N-1,N-1] --solver newton --tol 1e-6`
(with `--set solver.linear_solver=` --linear-solver: auto, cholesky or multigrid, and
`--set solver.continuation_levels=` --continuation unless it is `auto`, fabform's own choice) once for each thread count
in --threads, each up to --runs times (again only while the size's runs so far and one more fit
in --timeout: several runs where affordable, medians), and records per N and thread count:
wall seconds (result.json's wall_seconds, the whole run) and solve seconds (solve_seconds, plus
the coarser grids' where there are any), medians over the runs; iterations (on the scene's own
grid); peak memory (the largest resident size of the runs, from wait4's rusage); and
result.json's position_error_m, the estimate of the largest node distance from the exact rest.
Newton's path near the rest is sensitive to rounding-level differences (which nodes touch the
faceted dome, how many iterations the tail takes), so one run cannot tell a change of algorithm
from chance: --seeds S1,S2,... runs each size once per seed instead of --runs times, each start
moved by a seeded imperfection (`--set initial.perturbation_m=` --perturbation, default 1e-6 m,
`initial.seed=S`), and reports the median iterations with their range over the seeds.
Where N <= --reference-max it also solves to --reference-tol (the reference) and measures the
largest node distance of the first run from it, the figure the estimate is checked against
(first thread count only; with continuation the reference's coarser rests differ from the
run's, so the two can settle on neighbouring rests of the faceted dome, and the distance is then
that of the rests, not the estimate's error).
Then, for each thread count: the exponent p of time against nodes, t ~ nodes^p, fitted by least
squares on log t against log nodes over the sizes that finished (solve and wall), and
t(1001) / t(201); per N, each thread count's speed-up over the first's (wall and solve).
--baseline names another fabform binary (an older build, say) run on the same sizes, with the
first thread count and none of the --set options above (it may predate them); per N the report
gives its wall seconds over this build's, the issue's "× faster than newton at efbbdec". It runs a
copy of the dome scene written into --out without the keys newer than such a build may know
(NEWER_KEYS), its file paths made absolute.

Writes scale.csv and scale.md into --out (default results/bench_scale) and prints scale.md.
The machine's load average is printed with it: timings on a shared machine are under load.
Exit status 0, or 2 for bad options (one line).
"""
import argparse
import csv
import dataclasses
import json
import math
import os
import pathlib
import re
import shutil
import statistics
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import fabform_process as bench  # noqa: E402  (running fabform)

SIZES = "101,201,401,1001"
TOLERANCE_N = 1e-6     # the dome scene's e
SOLVER = "newton"
LINEAR_SOLVERS = ("auto", "cholesky", "multigrid")
# Keys the dome scene sets that an older build (--baseline) would refuse as unknown.
NEWER_KEYS = ("slack_stiffness",)
COLUMNS = ["N", "build", "threads", "nodes", "status", "runs", "wall_s", "solve_s", "iterations", "iterations_min",
           "iterations_max", "linear_solver", "cg_iterations",
           "peak_MiB", "position_error_m", "measured_distance_m", "note"]


def fail(message: str) -> None:
    print(f"bench_solvers.py --scale: {message}", file=sys.stderr)
    sys.exit(2)


def parse_sizes(text: str) -> list:
    """'101,201' -> [101, 201], ascending without duplicates; nodes a side, 3 ... 10001."""
    try:
        sizes = sorted({int(v) for v in text.split(",") if v.strip()})
    except ValueError:
        fail(f"--sizes: not a comma-separated list of integers: '{text}'")
    if not sizes:
        fail("--sizes: empty list")
    if not all(3 <= n <= 10001 for n in sizes):
        fail("--sizes: nodes a side must be 3 ... 10001")
    return sizes


def parse_threads(text: str) -> list:
    """'1,2' -> [1, 2], in the order given without duplicates; each 1 ... 64."""
    try:
        counts = list(dict.fromkeys(int(v) for v in text.split(",") if v.strip()))
    except ValueError:
        fail(f"--threads: not a comma-separated list of integers: '{text}'")
    if not counts or not all(1 <= t <= 64 for t in counts):
        fail("--threads: thread counts must be 1 ... 64")
    return counts


def parse_seeds(text: str) -> list:
    """'3,1,3' -> [3, 1], in the order given without duplicates; each 0 ... 2^64 - 1; '' -> []."""
    try:
        seeds = list(dict.fromkeys(int(v) for v in text.split(",") if v.strip()))
    except ValueError:
        fail(f"--seeds: not a comma-separated list of integers: '{text}'")
    if not all(0 <= s < 2 ** 64 for s in seeds):
        fail("--seeds: seeds must be 0 ... 2^64 - 1")
    return seeds


def parse_args(argv: list) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="bench_solvers.py --scale", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scale", action="store_true", required=True, help="this mode")
    p.add_argument("--sizes", default=SIZES, help=f"nodes a side (default {SIZES})")
    p.add_argument("--timeout", type=float, default=600.0, help="seconds for each size's runs (600)")
    p.add_argument("--runs", type=int, default=3, help="runs a size at most, for the medians (3)")
    p.add_argument("--threads", default="1", help="thread counts, each run in turn, e.g. 1,2 (1)")
    p.add_argument("--continuation", default="auto",
                   help="newton's grid continuation, solver.continuation_levels: 0 (none) ... 10, "
                        "or auto, fabform's choice (auto)")
    p.add_argument("--seeds", default="",
                   help="one run a size per seed, each start with a seeded imperfection, e.g. 1,2,3 (none)")
    p.add_argument("--perturbation", type=float, default=1e-6,
                   help="the imperfection with --seeds, initial.perturbation_m, m (1e-6)")
    p.add_argument("--baseline", default="", help="another fabform binary to time on the same sizes")
    p.add_argument("--linear-solver", default="auto",
                   help="newton's linear solve, solver.linear_solver: " + ", ".join(LINEAR_SOLVERS) + " (auto)")
    p.add_argument("--reference-max", type=int, default=201,
                   help="largest N solved to --reference-tol to measure the distance (201)")
    p.add_argument("--reference-tol", type=float, default=1e-11, help="newton's e for the reference (1e-11)")
    p.add_argument("--out", default=str(bench.ROOT / "results" / "bench_scale"), help="output folder")
    args = p.parse_args(argv)
    args.sizes = parse_sizes(args.sizes)
    if not (math.isfinite(args.timeout) and args.timeout > 0):
        fail("--timeout: must be a positive number of seconds")
    if args.runs < 1:
        fail("--runs: at least 1")
    args.threads = parse_threads(args.threads)
    args.seeds = parse_seeds(args.seeds)
    if not (math.isfinite(args.perturbation) and args.perturbation > 0):
        fail("--perturbation: must be a positive distance in metres")
    if args.continuation != "auto":
        if not (args.continuation.isdigit() and 0 <= int(args.continuation) <= 10):
            fail("--continuation: must be 0 ... 10 or auto")
    if args.baseline and not pathlib.Path(args.baseline).is_file():
        fail(f"--baseline: {args.baseline}: no such file")
    if args.linear_solver not in LINEAR_SOLVERS:
        fail(f"--linear-solver: '{args.linear_solver}' is not one of " + ", ".join(LINEAR_SOLVERS))
    if not (math.isfinite(args.reference_tol) and args.reference_tol > 0):
        fail("--reference-tol: must be a positive force")
    return args


# --- the fits --------------------------------------------------------------------------------

def fit_exponent(points: list):
    """p of t = c * nodes^p by least squares on (log nodes, log t); None with fewer than two
    distinct sizes."""
    pts = [(math.log(n), math.log(t)) for n, t in points if n > 0 and t > 0]
    if len({x for x, _ in pts}) < 2:
        return None
    mx = statistics.fmean(x for x, _ in pts)
    my = statistics.fmean(y for _, y in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def time_ratio(rows: list, key: str, big: int = 1001, small: int = 201) -> tuple:
    """(t(big) / t(small), "") or (None, why it could not be computed)."""
    by_n = {r["N"]: r for r in rows}
    for n in (big, small):
        if n not in by_n:
            return None, f"N={n} was not asked for"
        if by_n[n]["status"] != "converged":
            return None, f"N={n} {by_n[n]['status']}" + (f" ({by_n[n]['note']})" if by_n[n].get("note") else "")
    return by_n[big][key] / by_n[small][key], ""


# --- the runs --------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class Build:
    """A fabform to time: which binary, with how many threads and which scene settings."""
    label: str        # "this" or "baseline"
    binary: str
    threads: int
    sets: tuple       # "KEY=VALUE" for --set
    scene: str = ""   # the scene file; "" for the dome as shipped

    def name(self) -> str:
        return f"{self.label}, {self.threads} thread(s)"


def baseline_scene(out: pathlib.Path) -> pathlib.Path:
    """The dome for an older build: a copy in `out` without NEWER_KEYS, its relative paths
    (resolved from the scene's folder) made absolute."""
    source = bench.scene_path("dome")
    absolute = lambda m: '"' + str((source.parent / m.group(1)).resolve()) + '"'  # noqa: E731
    lines = [re.sub(r'"(\.\.?/[^"]*)"', absolute, line) for line in source.read_text().splitlines()
             if line.split("=", 1)[0].strip() not in NEWER_KEYS]
    out.mkdir(parents=True, exist_ok=True)
    copy = out / "baseline_dome.toml"
    copy.write_text("\n".join(lines) + "\n")
    return copy


def builds(args, out: pathlib.Path = None) -> list:
    """This build once per thread count, then the baseline (if any) with the first; with `out`,
    the baseline's scene is written there."""
    sets = [f"solver.linear_solver={args.linear_solver}"]
    if args.continuation != "auto":
        sets.append(f"solver.continuation_levels={args.continuation}")
    this = [Build("this", str(bench.FABFORM), t, tuple(sets)) for t in args.threads]
    if not args.baseline:
        return this
    return this + [Build("baseline", args.baseline, args.threads[0], (), str(baseline_scene(out)) if out else "")]


def command(n: int, tolerance: float, build: Build, out: pathlib.Path, seed_sets: tuple = ()) -> list:
    sets = [item for kv in build.sets + seed_sets for item in ("--set", kv)]
    return [build.binary, "run", build.scene or str(bench.scene_path("dome")), "--out", str(out), "--solver", SOLVER,
            "--tol", repr(tolerance), "--threads", str(build.threads), "--max-iter", str(bench.MAX_ITERATIONS),
            "--set", f"fabric.divisions=[{n - 1},{n - 1}]", *sets, "--quiet"]


def run_once(n: int, tolerance: float, build: Build, out: pathlib.Path, budget: float, seed_sets: tuple = ()) -> dict:
    """One fabform run within `budget` seconds: its figures, and its positions when it finished."""
    if out.exists():
        shutil.rmtree(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    log = out.parent / f"{out.name}.stderr.txt"
    code, peak, wall = bench.wait_within(bench.launch(command(n, tolerance, build, out, seed_sets), log), budget)
    if code is None:
        return {"status": "over the timeout", "peak_MiB": peak, "note": f"killed after {budget:g} s"}
    result_file = out / "result.json"
    result = json.loads(result_file.read_text()) if code in (0, 3) and result_file.exists() else {}
    if not result:
        return {"status": "failed", "peak_MiB": peak, "note": bench.last_line(log) or f"exit {code}"}
    coarser = sum(level["solve_seconds"] for level in result.get("continuation", []))
    return {"status": bench.status_of(code, result), "peak_MiB": peak, "wall_s": result["wall_seconds"],
            "solve_s": result["solve_seconds"] + coarser, "iterations": result["iterations"],
            "nodes": result["nodes"],
            "linear_solver": result.get("linear_solver"), "cg_iterations": result.get("linear_iterations"),
            "position_error_m": result.get("position_error_m"), "positions": bench.read_positions(out), "note": ""}


def folder(build: Build, n: int, out: pathlib.Path) -> pathlib.Path:
    return out / f"N{n}" / f"{build.label}-T{build.threads}"


def seeded(args, build: Build) -> bool:
    """Whether the build runs once per seed: the baseline, which may predate the keys, does not."""
    return bool(args.seeds) and build.label != "baseline"


def seed_sets(args, build: Build, run: int) -> tuple:
    """The --set options of a size's run-th run (from 0): its seed's imperfection, if seeded."""
    if not seeded(args, build):
        return ()
    return (f"initial.perturbation_m={args.perturbation!r}", f"initial.seed={args.seeds[run]}")


def measure_size(n: int, build: Build, args, out: pathlib.Path) -> dict:
    """Up to --runs runs of one size (one per seed with --seeds), all within --timeout; the row of
    their medians."""
    runs, spent = [], 0.0
    row = {"N": n, "build": build.label, "threads": build.threads}
    wanted = len(args.seeds) if seeded(args, build) else args.runs
    while len(runs) < wanted:
        left = args.timeout - spent
        if runs and runs[-1]["wall_s"] > left:  # one more would not fit in the timeout
            break
        run = run_once(n, TOLERANCE_N, build, folder(build, n, out) / f"run{len(runs) + 1}", left,
                       seed_sets(args, build, len(runs)))
        print(f"  N={n} {build.name()} run {len(runs) + 1}: {run['status']}, {run.get('wall_s', '-')} s",
              file=sys.stderr)
        if run["status"] != "converged":
            if not runs:
                return dict(run, **row, nodes=n * n, runs=0)
            break
        runs.append(run)
        spent += run["wall_s"]
    first = runs[0]
    return dict(row, nodes=first["nodes"], status="converged", runs=len(runs),
                wall_s=statistics.median(r["wall_s"] for r in runs),
                solve_s=statistics.median(r["solve_s"] for r in runs),
                iterations=statistics.median_low(r["iterations"] for r in runs),
                iterations_min=min(r["iterations"] for r in runs), iterations_max=max(r["iterations"] for r in runs),
                linear_solver=first["linear_solver"],
                cg_iterations=statistics.median_low(r["cg_iterations"] or 0 for r in runs), peak_MiB=max(r["peak_MiB"] for r in runs),
                position_error_m=first["position_error_m"], positions=first["positions"], note="")


def add_measured_distance(row: dict, build: Build, args, out: pathlib.Path) -> None:
    """The first run's largest node distance from newton at --reference-tol (from the same start),
    where affordable."""
    if row["status"] != "converged" or row["N"] > args.reference_max:
        return
    ref = run_once(row["N"], args.reference_tol, build, folder(build, row["N"], out) / "reference", args.timeout,
                   seed_sets(args, build, 0))
    if ref.get("positions") is None:
        row["note"] = f"reference {ref['status']}"
        return
    row["measured_distance_m"] = bench.largest_distance(row["positions"], ref["positions"])


def measure(args, out: pathlib.Path) -> list:
    """Every size with every build, smaller sizes first; a build over the timeout runs no larger size."""
    rows = []
    every = builds(args, out)  # the baseline's scene copy written once
    for n in args.sizes:
        for build in every:
            reached = [r for r in rows if r["status"] == "over the timeout"
                       and (r["build"], r["threads"]) == (build.label, build.threads)]
            if reached:
                rows.append({"N": n, "build": build.label, "threads": build.threads, "nodes": n * n,
                             "status": "not run", "runs": 0,
                             "note": f"N={reached[0]['N']} was already over the timeout ({args.timeout:g} s)"})
                continue
            row = measure_size(n, build, args, out)
            if build.label == "this" and build.threads == args.threads[0]:
                add_measured_distance(row, build, args, out)
            row.pop("positions", None)
            rows.append(row)
    return rows


# --- the report ------------------------------------------------------------------------------

def cell(row: dict, key: str, form: str) -> str:
    v = row.get(key)
    return "" if v is None or (isinstance(v, float) and math.isnan(v)) else format(v, form)


def ratio_cell(row: dict) -> str:
    est, measured = row.get("position_error_m"), row.get("measured_distance_m")
    return f"{est / measured:.2f}" if est and measured else ""


def iteration_range(row: dict) -> str:
    low, high = row.get("iterations_min"), row.get("iterations_max")
    return "" if low is None else f"{low}–{high}"


def table(rows: list) -> list:
    lines = ["| N | build | threads | nodes | status | runs | wall s (median) | solve s (median) | iterations "
             "(median) | iterations (range) | linear solve | CG iterations (median) | peak MiB | position_error_m "
             "| measured distance (m) | estimate / measured | note |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| " + " | ".join([
            str(r["N"]), r["build"], str(r["threads"]), str(r["nodes"]), r["status"], str(r["runs"]),
            cell(r, "wall_s", ".3g"), cell(r, "solve_s", ".3g"), cell(r, "iterations", "d"), iteration_range(r),
            r.get("linear_solver") or "", cell(r, "cg_iterations", "d"), cell(r, "peak_MiB", ".0f"),
            cell(r, "position_error_m", ".2e"), cell(r, "measured_distance_m", ".2e"), ratio_cell(r),
            r.get("note", "")]) + " |")
    return lines


def of_build(rows: list, build: Build) -> list:
    return [r for r in rows if (r["build"], r["threads"]) == (build.label, build.threads)]


def fits(rows: list) -> list:
    lines = []
    for key, what in (("solve_s", "solve seconds"), ("wall_s", "wall seconds")):
        done = [r for r in rows if r["status"] == "converged"]
        p = fit_exponent([(r["nodes"], r[key]) for r in done])
        over = ", ".join(str(r["N"]) for r in done)
        lines.append(f"- {what} ~ nodes^p: p = {p:.2f} (least squares over N = {over})" if p is not None
                     else f"- {what} ~ nodes^p: not fitted (fewer than two sizes finished)")
        ratio, why = time_ratio(rows, key)
        lines.append(f"- {what}, t(1001) / t(201) = {ratio:.1f}" if ratio is not None
                     else f"- {what}, t(1001) / t(201): could not be computed: {why}")
    return lines


def speed_ups(rows: list, slow: Build, fast: Build) -> list:
    """Per N where both finished: slow's seconds over fast's, wall and solve."""
    lines = []
    fast_rows = {r["N"]: r for r in of_build(rows, fast) if r["status"] == "converged"}
    for r in of_build(rows, slow):
        f = fast_rows.get(r["N"])
        if r["status"] == "converged" and f:
            lines.append(f"- N={r['N']}: {fast.name()} against {slow.name()}: {r['wall_s'] / f['wall_s']:.2f} x "
                         f"faster (wall seconds), {r['solve_s'] / f['solve_s']:.2f} x (solve seconds)")
    return lines


def summary(rows: list, args) -> list:
    every = builds(args)
    lines = []
    for build in every:
        lines += [f"{build.name()}:", ""] + fits(of_build(rows, build)) + [""]
    first = every[0]
    for build in every[1:]:
        slow, fast = (build, first) if build.label == "baseline" else (first, build)
        lines += speed_ups(rows, slow, fast)
    return lines


def report(rows: list, args, load_before: tuple, load_after: tuple) -> str:
    threads = ",".join(str(t) for t in args.threads)
    head = ["# Dome scaling, newton to 1e-6 N", "",
            f"`bench_solvers.py {' '.join(sys.argv[1:])}`, {bench.fabform_version()}, {os.cpu_count()} cores, "
            f"threads {threads}, linear solve {args.linear_solver}, continuation levels {args.continuation}"
            + (f", baseline {args.baseline}" if args.baseline else "")
            + (f", seeds {','.join(map(str, args.seeds))} ({args.perturbation:g} m imperfection)" if args.seeds else "")
            + f"; timeout {args.timeout:g} s a size and build; load average "
            f"{load_before[0]:.2f} before, {load_after[0]:.2f} after (a shared machine: timings under load). "
            f"Distances measured from newton at {args.reference_tol:g} N where N <= {args.reference_max}.", ""]
    return "\n".join(head + table(rows) + [""] + summary(rows, args)) + "\n"


def write_csv(rows: list, path: pathlib.Path) -> None:
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)


def main(argv: list) -> int:
    args = parse_args(argv)
    if not bench.FABFORM.exists():
        fail(f"{bench.FABFORM} is missing: build it first (tools/setup.sh), or name it in FABFORM_BINARY")
    out = pathlib.Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    load_before = os.getloadavg()
    rows = measure(args, out)
    text = report(rows, args, load_before, os.getloadavg())
    write_csv(rows, out / "scale.csv")
    (out / "scale.md").write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
