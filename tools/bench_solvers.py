#!/usr/bin/python3
"""Speed against accuracy of every solver, measured: the trade curve of each scene.

Why: users trade speed for accuracy, so the trade is measured, not assumed, and the issue's
targets (newton 100x faster than relax on the dome, a million nodes in 60 s and 4 GiB, 1.6x from
two threads, the harsh start converging, newton agreeing with relax on the shipped scenes) are
shown by one command anyone can re-run.

What it does: for each case (DESIGN.md's dome at each N, smooth and harsh start, and each
shipped scene) it first computes a reference, newton at --reference-tol, then runs
`build/fabform run` with every solver (as `fabform solvers` lists them) at every tolerance and
thread count, and records wall time (result.json's wall_seconds), iterations, final residual
(residual_recomputed_N), peak memory (the child's maximum resident size, from wait4) and the
largest node distance from the reference, in metres and as a fraction of the grid spacing. A run
longer than --budget seconds is killed and recorded as "over budget", its time a lower bound;
the tighter tolerances of that solver and thread count are then not run but recorded the same
way (they would take longer still).

The reference is cached in OUT/reference/CASE and reused while its key matches: a hash of the
fabform binary, the scene file, the tables and meshes it names, the --set overrides and
--reference-tol. Delete the folder to force a new one.

Writes into --out (default results/bench): bench.csv (one row a run, rewritten after every run
so a long benchmark can be read as it goes), summary.md (references, the table of runs and the
targets, each met / not met / not measured; printed too), trade_CASE.png and .svg (time against
error, one line per solver; only when matplotlib is installed) and runs/ (each run's
result.json, convergence.csv and stderr; the positions are deleted).

Usage (after tools/setup.sh):
  /usr/bin/python3 tools/bench_solvers.py                  # everything: hours, relax dominates
  /usr/bin/python3 tools/bench_solvers.py --sizes 41,101 --scenes dome --tolerances 1e-2,1e-4,1e-6
  /usr/bin/python3 tools/bench_solvers.py --sizes 401,1001 --starts smooth --solvers newton --threads 1,2
  /usr/bin/python3 tools/bench_solvers.py --smoke          # seconds: the test suite's check
  /usr/bin/python3 tools/bench_solvers.py --scale --sizes 101,201,401 --timeout 600
--scale measures newton's time against the dome's size instead (tools/bench_scale.py says how).
--smoke runs dome N=21, smooth start, every solver at 1e-2 and 1e-5 N, one thread, 60 s budget
(it overrides the case options) and exits 1 unless every run converged below its tolerance,
was compared with the reference and has its row in bench.csv.
Standard library only; matplotlib (python3-matplotlib) is optional, for the plots.
FABFORM_BINARY names the fabform to run (default build/fabform).
"""
import argparse
import array
import csv
import datetime
import hashlib
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import tomllib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fabform_process import (FABFORM, MAX_ITERATIONS, ROOT, fabform_version, largest_distance, launch,  # noqa: E402
                             last_line, read_positions, scene_path, status_of, wait_within)

FAST = "newton"                       # the reference solver and the one the targets are about


def frictionless(path: pathlib.Path) -> bool:
    return all(body.get("friction", 0.0) == 0.0 for body in tomllib.loads(path.read_text()).get("body", []))


# Every shipped scene but the dome, whose cases are built from its sizes and starts, and those
# with friction: their rest depends on the path to it, so no solver's rest is another's reference
# (and relax refuses friction).
SHIPPED = tuple(sorted(p.stem for p in (ROOT / "scenes").glob("*.toml") if p.stem != "dome" and frictionless(p)))
DOME_HEIGHT_M = 0.04                  # DESIGN.md: both dome starts are 4 cm high
# "Relax run to a tight tolerance", judged at the e for its targets. At a looser e both
# solvers can stop where they started: a drape's start, a flat fabric under its weight, meets 1e-2 N.
AGREEMENT_TOL_N = 1e-6
COLUMNS = ["case", "scene", "N", "start", "spacing_m", "nodes", "solver", "tolerance_N", "threads", "status",
           "exit_code", "iterations", "seconds", "residual_N", "peak_MiB", "max_distance_m",
           "distance_per_spacing", "distance_to_newton_m", "note"]


# --- options ---------------------------------------------------------------------------------

def fail(message: str) -> None:
    """Bad options or a missing binary: say so and exit 2, like fabform on bad input."""
    print(f"bench_solvers.py: {message}", file=sys.stderr)
    sys.exit(2)


def parse_list(text: str, kind, what: str) -> list:
    """'1e-2,1e-4' -> [0.01, 0.0001], without duplicates, in the given order."""
    try:
        values = [kind(v) for v in text.split(",") if v.strip()]
    except ValueError:
        fail(f"--{what}: not a comma-separated list of {kind.__name__}s: '{text}'")
    if not values:
        fail(f"--{what}: empty list")
    return list(dict.fromkeys(values))


def parse_args(argv: list) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default=str(ROOT / "results" / "bench"), help="output folder")
    p.add_argument("--scenes", default="dome," + ",".join(SHIPPED), help="dome and/or shipped scenes")
    p.add_argument("--sizes", default="41,101,201,401,1001", help="dome: nodes a side")
    p.add_argument("--starts", default="smooth,harsh", help="dome: smooth (bump) and/or harsh (lift)")
    p.add_argument("--solvers", default="", help="default: every solver `fabform solvers` lists")
    p.add_argument("--tolerances", default="1e-1,1e-2,1e-3,1e-4,1e-5,1e-6,1e-7,1e-8", help="e, N")
    p.add_argument("--threads", default="1", help="thread counts, e.g. 1,2")
    p.add_argument("--budget", type=float, default=600.0, help="seconds a run may take (600)")
    p.add_argument("--reference-tol", type=float, default=1e-10, help="newton's e for the reference")
    p.add_argument("--reference-budget", type=float, default=3600.0, help="seconds for a reference")
    p.add_argument("--smoke", action="store_true", help="tiny run for the test suite (see the description)")
    args = p.parse_args(argv)
    if args.smoke:
        args.scenes, args.sizes, args.starts, args.solvers = "dome", "21", "smooth", ""
        args.tolerances, args.threads, args.budget = "1e-2,1e-5", "1", 60.0
    return args


def fabform_solvers() -> list:
    """The solver names the binary offers, one a line."""
    if not FABFORM.exists():
        fail(f"{FABFORM} is missing: build it first (tools/setup.sh)")
    listed = subprocess.run([str(FABFORM), "solvers"], capture_output=True, text=True)
    if listed.returncode != 0 or not listed.stdout.split():
        fail(f"`{FABFORM} solvers` failed: {listed.stderr.strip()}")
    return listed.stdout.split()


def check_names(given: list, allowed: list, what: str) -> None:
    for name in given:
        if name not in allowed:
            fail(f"unknown {what} '{name}' (known: {', '.join(allowed)})")


def validate(args: argparse.Namespace) -> argparse.Namespace:
    """Turn the option strings into lists and refuse anything fabform or the targets can't use."""
    known = fabform_solvers()
    if FAST not in known:
        fail(f"`fabform solvers` does not list '{FAST}', the reference solver")
    args.solvers = parse_list(args.solvers, str, "solvers") if args.solvers else known
    args.scenes = parse_list(args.scenes, str, "scenes")
    args.starts = parse_list(args.starts, str, "starts")
    check_names(args.solvers, known, "solver")
    check_names(args.scenes, ["dome", *SHIPPED], "scene")
    check_names(args.starts, ["smooth", "harsh"], "start")
    args.solvers.sort(key=lambda s: s != FAST)  # newton first: the others are compared with it
    args.sizes = parse_list(args.sizes, int, "sizes")
    args.threads = parse_list(args.threads, int, "threads")
    args.tolerances = sorted(parse_list(args.tolerances, float, "tolerances"), reverse=True)
    if not all(2 <= n <= 10001 for n in args.sizes):
        fail("--sizes: nodes a side must be 2 ... 10001")
    if not all(t >= 1 for t in args.threads):
        fail("--threads: at least 1")
    if not all(e > 0 for e in args.tolerances + [args.reference_tol]):
        fail("tolerances must be > 0")
    if not (args.budget > 0 and args.reference_budget > 0):
        fail("budgets must be > 0 s")
    return args


# --- cases -----------------------------------------------------------------------------------

class Case:
    """One scene with the --set overrides that make it a benchmark case."""

    def __init__(self, name, scene, n, start, overrides, spacing_m):
        self.name, self.scene, self.n, self.start = name, scene, n, start
        self.overrides, self.spacing_m = overrides, spacing_m




def load_scene(name: str) -> dict:
    return tomllib.loads(scene_path(name).read_text())


def spacing(fabric: dict, divisions: list) -> float:
    """A rectangle's smaller spring rest length, m: the scale node distances are judged on."""
    return min(size / d for size, d in zip(fabric["size_m"], divisions))


def circle_grid(fabric: dict) -> tuple:
    """A circle's mesh label and spacing, m: the lattice's for a lattice, the rings' for an arc
    (its spokes' spacing varies with the radius)."""
    if fabric.get("mesh") == "arc":
        return f"{fabric['rings']} rings x {fabric['spokes']} spokes", fabric["diameter_m"] / 2 / fabric["rings"]
    return f"{fabric['divisions']} across", fabric["diameter_m"] / fabric["divisions"]


def dome_case(n: int, start: str) -> Case:
    divisions = [n - 1, n - 1]
    overrides = [f"fabric.divisions=[{n - 1},{n - 1}]"]
    if start == "harsh":  # DESIGN.md: every interior node at z = 0.04 m, as seed 003 starts
        overrides += ["initial.shape=lift", f"initial.height_m={DOME_HEIGHT_M}"]
    fabric = load_scene("dome")["fabric"]
    return Case(f"dome-{start}-N{n}", "dome", str(n), start, overrides, spacing(fabric, divisions))


def shipped_case(name: str) -> Case:
    scene = load_scene(name)
    fabric = scene["fabric"]
    start = scene.get("initial", {}).get("shape", "flat")
    if fabric.get("shape") == "circle":
        grid, h = circle_grid(fabric)
        return Case(name, name, grid, start, [], h)
    divisions = fabric["divisions"]
    grid = "x".join(str(d + 1) for d in divisions)
    return Case(name, name, grid, start, [], spacing(fabric, divisions))


def build_cases(args) -> list:
    cases = []
    for scene in args.scenes:
        if scene == "dome":
            cases += [dome_case(n, start) for n in args.sizes for start in args.starts]
        else:
            cases.append(shipped_case(scene))
    return cases


# --- one fabform run -------------------------------------------------------------------------

def command_for(case: Case, solver: str, tolerance: float, threads: int, out: pathlib.Path) -> list:
    command = [str(FABFORM), "run", str(scene_path(case.scene)), "--out", str(out), "--solver", solver,
               "--tol", repr(tolerance), "--threads", str(threads), "--max-iter", str(MAX_ITERATIONS),
               "--quiet"]
    for setting in case.overrides:
        command += ["--set", setting]
    return command










def run_once(case, solver, tolerance, threads, out, budget) -> tuple:
    """Run fabform once: (its row, its node positions or None)."""
    if out.exists():
        shutil.rmtree(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    # Beside the results folder, not in it: fabform refuses a folder holding files it did not write.
    log = out.parent / f"{out.name}.stderr.txt"
    code, peak, wall = wait_within(launch(command_for(case, solver, tolerance, threads, out), log), budget)
    row = {"solver": solver, "tolerance_N": tolerance, "threads": threads,
           "peak_MiB": round(peak, 1), "seconds": round(wall, 3), "exit_code": "" if code is None else code}
    if code is None:
        return dict(row, status="over budget", note=f"killed after {budget:g} s"), None
    result_file = out / "result.json"
    result = json.loads(result_file.read_text()) if code in (0, 3) and result_file.exists() else {}
    row["status"] = status_of(code, result)
    if not result:
        return dict(row, note=last_line(log) or f"exit {code}"), None
    row.update(nodes=result["nodes"], iterations=result["iterations"],
               seconds=round(result["wall_seconds"], 3), residual_N=result["residual_recomputed_N"])
    return row, read_positions(out)






# --- the reference ---------------------------------------------------------------------------

def scene_inputs(case: Case) -> list:
    """The scene file and the tables and meshes it names: what the answer depends on."""
    path = scene_path(case.scene)
    scene = tomllib.loads(path.read_text())
    named = [scene["fabric"]["warp"], scene["fabric"]["weft"]] + [b["mesh"] for b in scene.get("body", [])]
    return [FABFORM, path] + [path.parent / n for n in named]


def reference_key(case: Case, args) -> str:
    digest = hashlib.sha256()
    for f in scene_inputs(case):
        digest.update(f.read_bytes() if f.exists() else b"missing")
    digest.update(repr((case.overrides, args.reference_tol)).encode())
    return digest.hexdigest()


def cached_reference(folder: pathlib.Path, key: str):
    """The stored reference (info, positions) if it was made from the same inputs, else None."""
    info_file = folder / "reference.json"
    if not info_file.exists():
        return None
    info = json.loads(info_file.read_text())
    if info.get("key") != key or not (folder / "positions.bin").exists():
        return None
    positions = array.array("d")
    positions.frombytes((folder / "positions.bin").read_bytes())
    return dict(info, cached=True), positions


def compute_reference(case: Case, args, folder: pathlib.Path, key: str):
    """newton at --reference-tol with the most threads asked for; stored for the next run."""
    row, positions = run_once(case, FAST, args.reference_tol, max(args.threads), folder / "run",
                              args.reference_budget)
    info = {k: row.get(k, "") for k in ("status", "iterations", "seconds", "residual_N", "note")}
    info.update(key=key, tolerance_N=args.reference_tol, cached=False)
    if positions is not None:
        (folder / "positions.bin").write_bytes(positions.tobytes())
        (folder / "reference.json").write_text(json.dumps(info, indent=1))
    return info, positions


def reference(case: Case, args, out: pathlib.Path):
    """(info, positions or None). A reference that hit the iteration cap is used, and flagged."""
    folder = out / "reference" / case.name
    folder.mkdir(parents=True, exist_ok=True)
    key = reference_key(case, args)
    info, positions = cached_reference(folder, key) or compute_reference(case, args, folder, key)
    print(f"  reference: {FAST} e={args.reference_tol:g}: {info['status']}"
          f"{' (cached)' if info['cached'] else ''}", file=sys.stderr)
    return info, positions


# --- the benchmark ---------------------------------------------------------------------------

def case_fields(case: Case) -> dict:
    return {"case": case.name, "scene": case.scene, "N": case.n, "start": case.start,
            "spacing_m": case.spacing_m}


def add_distances(row, positions, ref, fast_positions, case) -> None:
    """Distance from the reference and from newton's run at the same e and threads."""
    if positions is None:
        return
    if ref is not None:
        d = largest_distance(positions, ref)
        row["max_distance_m"], row["distance_per_spacing"] = d, d / case.spacing_m
    key = (row["tolerance_N"], row["threads"])
    if row["solver"] != FAST and key in fast_positions:
        row["distance_to_newton_m"] = largest_distance(positions, fast_positions[key])


def not_run(case, solver, tolerance, threads, killed: dict) -> dict:
    """A tighter e after an over-budget run: at least as long, so recorded as over budget too."""
    return dict(case_fields(case), solver=solver, tolerance_N=tolerance, threads=threads,
                status="over budget", seconds=killed["seconds"],
                note=f"not run: e={killed['tolerance_N']:g} was already over budget")


def run_solver(case, solver, threads, args, ref, fast_positions, out, record) -> None:
    """One solver at one thread count, loosest e first; record(row) takes each row."""
    killed = None
    for tolerance in args.tolerances:
        if killed:
            row = not_run(case, solver, tolerance, threads, killed)
        else:
            folder = out / "runs" / case.name / f"{solver}-t{threads}-e{tolerance:g}"
            row, positions = run_once(case, solver, tolerance, threads, folder, args.budget)
            row.update(case_fields(case))
            add_distances(row, positions, ref, fast_positions, case)
            if solver == FAST and positions is not None:
                fast_positions[(tolerance, threads)] = positions
            killed = row if row["status"] == "over budget" else None
        print(f"  {solver} e={tolerance:g} threads={threads}: {row['status']}, "
              f"{row.get('iterations', '-')} it, {row['seconds']} s", file=sys.stderr)
        record(row)


def run_case(case: Case, args, out: pathlib.Path, record) -> dict:
    """Every solver x threads x tolerance on one case; returns the reference's figures."""
    print(f"{case.name} ({case.overrides or 'as shipped'}):", file=sys.stderr)
    info, ref = reference(case, args, out)
    info.update(case=case.name, spacing_m=case.spacing_m)
    fast_positions = {}
    for solver in args.solvers:
        for threads in args.threads:
            run_solver(case, solver, threads, args, ref, fast_positions, out, record)
    return info


# --- bench.csv -------------------------------------------------------------------------------

def write_csv(rows: list, path: pathlib.Path) -> None:
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for r in rows:
            writer.writerow({k: ("" if isinstance(r.get(k), float) and math.isnan(r[k]) else r.get(k, ""))
                             for k in COLUMNS})


def read_csv(path: pathlib.Path) -> list:
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


# --- plots -----------------------------------------------------------------------------------

def pyplot():
    """matplotlib.pyplot on the Agg backend, or None when matplotlib is not installed."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError:
        return None


def curve_label(solver: str, threads: int, several: bool) -> str:
    return f"{solver}, {threads} thread{'s' if threads > 1 else ''}" if several else solver


def plot_curve(ax, points: list, label: str, floor: float) -> None:
    """One solver: time against error, filled where converged, x where stopped short. A run that
    landed on the reference (distance 0, off a log axis) is drawn at `floor`, marked '= ref'."""
    xs = [max(p["max_distance_m"], floor) for p in points]
    line, = ax.plot(xs, [p["seconds"] for p in points], "-", label=label)
    for x, p in zip(xs, points):
        marker = "o" if p["status"] == "converged" else "x"
        ax.plot(x, p["seconds"], marker, color=line.get_color())
        ax.annotate(f"{p['tolerance_N']:g}" + (" (= ref)" if p["max_distance_m"] == 0 else ""),
                    (x, p["seconds"]), fontsize=7, textcoords="offset points", xytext=(3, 3))


def plot_case(plt, rows: list, case: Case, out: pathlib.Path) -> bool:
    mine = [r for r in rows if r["case"] == case.name and r.get("max_distance_m", -1) >= 0]
    positive = [r["max_distance_m"] for r in mine if r["max_distance_m"] > 0]
    if not positive:
        return False
    fig, ax = plt.subplots(figsize=(7, 4.8))
    several = len({r["threads"] for r in mine}) > 1
    for solver, threads in sorted({(r["solver"], r["threads"]) for r in mine}):
        points = sorted((r for r in mine if (r["solver"], r["threads"]) == (solver, threads)),
                        key=lambda r: -r["tolerance_N"])
        plot_curve(ax, points, curve_label(solver, threads, several), min(positive) / 10)
    ax.axvline(1e-3 * case.spacing_m, color="grey", linestyle=":", label="1e-3 of the spacing")
    ax.set(xscale="log", yscale="log", xlabel="largest node distance from the reference (m)",
           ylabel="wall time (s)", title=f"{case.name}: time against error (labels: e in N; x: not converged)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(out / f"trade_{case.name}.{ext}", dpi=120)
    plt.close(fig)
    return True


def plot_all(rows: list, cases: list, out: pathlib.Path) -> str:
    plt = pyplot()
    if plt is None:
        return "matplotlib is not installed: no trade-curve plots (apt-get install python3-matplotlib)"
    drawn = [c.name for c in cases if plot_case(plt, rows, c, out)]
    return f"Trade curves: {', '.join(f'trade_{n}.png' for n in drawn) or 'none (no distances)'} (and .svg)"


# --- summary.md: the table -------------------------------------------------------------------

def number(r: dict, key: str, form: str) -> str:
    v = r.get(key, "")
    return "" if v == "" or (isinstance(v, float) and math.isnan(v)) else format(v, form)


def seconds_text(r: dict) -> str:
    return ("≥ " if r["status"] == "over budget" else "") + f"{r['seconds']:.3g}"


def table_row(r: dict) -> str:
    cells = [r["case"], r["solver"], f"{r['tolerance_N']:g}", str(r["threads"]), r["status"],
             str(r.get("iterations", "")), seconds_text(r), number(r, "residual_N", ".2e"),
             number(r, "peak_MiB", ".0f"), number(r, "max_distance_m", ".2e"),
             number(r, "distance_per_spacing", ".2e"), number(r, "distance_to_newton_m", ".2e")]
    return "| " + " | ".join(cells) + " |"


def runs_table(rows: list) -> list:
    return ["| case | solver | e (N) | threads | status | iterations | wall (s) | ‖V‖∞ (N) | peak MiB "
            "| from reference (m) | / spacing | from newton (m) |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|"] + [table_row(r) for r in rows]


def reference_table(infos: list) -> list:
    lines = ["| case | spacing (m) | status | iterations | wall (s) | ‖V‖∞ (N) | note |",
             "|---|---|---|---|---|---|---|"]
    for i in infos:
        lines.append(f"| {i['case']} | {i['spacing_m']:.3g} | {i['status']}{' (cached)' if i['cached'] else ''} "
                     f"| {i['iterations']} | {i['seconds']} | {number(i, 'residual_N', '.2e')} | {i['note']} |")
    return lines


# --- summary.md: the targets -----------------------------------------------------------------

def find(rows, case, solver, tolerance, threads=None) -> list:
    return [r for r in rows if r["case"] == case and r["solver"] == solver and
            math.isclose(r["tolerance_N"], tolerance) and threads in (None, r["threads"])]


def target_speedup(rows) -> str:
    name = "dome smooth N=201, e=1e-6: newton ≥ 100× faster than relax"
    fast, slow = find(rows, "dome-smooth-N201", FAST, 1e-6, 1), find(rows, "dome-smooth-N201", "relax", 1e-6, 1)
    if not (fast and slow) or fast[0]["status"] != "converged":
        return f"- {name}: **not measured**" + (f" (newton {fast[0]['status']})" if fast else "")
    fast, slow = fast[0], slow[0]
    ratio = slow["seconds"] / fast["seconds"]
    if slow["status"] == "converged":
        verdict = "met" if ratio >= 100 else "not met"
    elif slow["status"] == "over budget":
        verdict = "met" if ratio >= 100 else "not measured (relax over budget: raise --budget)"
    else:
        verdict = f"not measured (relax {slow['status']})"
    bound = "≥ " if slow["status"] == "over budget" else ""
    return (f"- {name}: relax {seconds_text(slow)} s, newton {fast['seconds']:.3g} s, "
            f"ratio {bound}{ratio:.0f}: **{verdict}**")


def target_million(rows) -> str:
    name = "dome smooth N=1001, e=1e-6, newton within 60 s and 4 GiB"
    runs = find(rows, "dome-smooth-N1001", FAST, 1e-6)
    if not runs:
        return f"- {name}: **not measured**"
    best = min(runs, key=lambda r: (r["status"] != "converged", r["seconds"]))
    ok = best["status"] == "converged" and best["seconds"] <= 60 and best.get("peak_MiB", math.inf) <= 4096
    return (f"- {name}: {best['status']} with {best['threads']} thread(s), {seconds_text(best)} s, "
            f"{number(best, 'peak_MiB', '.0f') or '?'} MiB: **{'met' if ok else 'not met'}**")


def thread_ratios(rows, solver) -> list:
    """(t1/t2, case, e) for each dome case with N >= 401 where both runs converged."""
    out = []
    for r2 in rows:
        if r2["solver"] != solver or r2["threads"] != 2 or r2["scene"] != "dome" or int(r2["N"]) < 401:
            continue
        r1 = find(rows, r2["case"], solver, r2["tolerance_N"], 1)
        if r1 and r1[0]["status"] == r2["status"] == "converged":
            out.append((r1[0]["seconds"] / r2["seconds"], r2["case"], r2["tolerance_N"]))
    return out


def target_threads(rows, solvers) -> list:
    lines = []
    for solver in solvers:
        name = f"dome N ≥ 401, {solver}: 2 threads ≥ 1.6× faster than 1"
        ratios = thread_ratios(rows, solver)
        if not ratios:
            lines.append(f"- {name}: **not measured**")
            continue
        worst = min(ratios)
        lines.append(f"- {name}: {len(ratios)} pairs, smallest {worst[0]:.2f}× ({worst[1]}, e={worst[2]:g}): "
                     f"**{'met' if worst[0] >= 1.6 else 'not met'}**")
    return lines


def target_harsh(rows, solvers) -> list:
    lines = []
    for solver in solvers:
        mine = [r for r in rows if r["start"] == "harsh" and r["solver"] == solver]
        counts = {s: sum(r["status"] == s for r in mine) for s in ("converged", "not converged", "failed",
                                                                  "over budget")}
        detail = ", ".join(f"{n} {s}" for s, n in counts.items() if n)
        if not mine or counts["converged"] == 0 and counts["over budget"] == len(mine):
            verdict = "not measured"
        elif counts["not converged"] or counts["failed"]:
            verdict = "not met"
        else:
            verdict = "met" if not counts["over budget"] else "met where measured (some runs over budget)"
        lines.append(f"- dome harsh start, {solver} converges: {detail or 'no runs'}: **{verdict}**")
    return lines


def target_agreement(rows) -> list:
    lines = []
    for scene in SHIPPED:
        name = f"{scene}: newton within 1e-3 of the spacing of relax at e <= {AGREEMENT_TOL_N:g} N"
        both = [r for r in rows if r["case"] == scene and r["solver"] == "relax" and r["status"] == "converged"
                and r["tolerance_N"] <= AGREEMENT_TOL_N
                and isinstance(r.get("distance_to_newton_m"), float) and not math.isnan(r["distance_to_newton_m"])]
        if not both:
            lines.append(f"- {name}: **not measured** (no relax run converged that tightly, beside newton's)")
            continue
        tight = min(both, key=lambda r: (r["tolerance_N"], r["threads"]))
        fraction = tight["distance_to_newton_m"] / tight["spacing_m"]
        lines.append(f"- {name}: at e={tight['tolerance_N']:g} (tightest both reached) "
                     f"{tight['distance_to_newton_m']:.2e} m = {fraction:.2e} of the spacing: "
                     f"**{'met' if fraction <= 1e-3 else 'not met'}**")
    return lines


def targets(rows, solvers) -> list:
    return (["## Targets", "", target_speedup(rows), target_million(rows)] + target_threads(rows, solvers)
            + target_harsh(rows, solvers) + target_agreement(rows))




def summary(rows, infos, args, plot_note) -> str:
    head = ["# Solver benchmark", "",
            f"`bench_solvers.py {' '.join(sys.argv[1:])}`, {datetime.date.today()}, {fabform_version()}, "
            f"{os.cpu_count()} cores; budget {args.budget:g} s a run (≥: killed at the budget, a lower bound). "
            f"Distances are the largest node distance from the reference; \"from newton\" is from newton's "
            f"run at the same e and threads. {plot_note}.", "",
            f"## References ({FAST} at e = {args.reference_tol:g} N)", ""]
    return "\n".join(head + reference_table(infos) + ["", "## Runs", ""] + runs_table(rows) + [""]
                     + targets(rows, args.solvers)) + "\n"


# --- smoke check -----------------------------------------------------------------------------

def smoke_problems(cases: list, args, csv_path: pathlib.Path) -> list:
    """What the test suite fails on, read back from bench.csv: a missing row, a run that did not
    converge, a residual above its e, a run not compared with the reference."""
    written = read_csv(csv_path)
    problems = []
    for case in cases:
        for solver in args.solvers:
            for threads in args.threads:
                for e in args.tolerances:
                    got = [r for r in written if r["case"] == case.name and r["solver"] == solver
                           and int(r["threads"]) == threads and math.isclose(float(r["tolerance_N"]), e)]
                    what = f"{case.name} {solver} e={e:g} threads={threads}"
                    if not got:
                        problems.append(f"{what}: no row in {csv_path.name}")
                    elif got[0]["status"] != "converged":
                        problems.append(f"{what}: {got[0]['status']} {got[0]['note']}".rstrip())
                    elif not float(got[0]["residual_N"]) <= e:
                        problems.append(f"{what}: residual {got[0]['residual_N']} N above e")
                    elif got[0]["max_distance_m"] == "":
                        problems.append(f"{what}: not compared with the reference")
    return problems


def main(argv: list) -> int:
    if "--scale" in argv:
        import bench_scale
        return bench_scale.main(argv)
    args = validate(parse_args(argv))
    out = pathlib.Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    cases, rows, csv_path = build_cases(args), [], out / "bench.csv"

    def record(row: dict) -> None:  # bench.csv is kept current: a long benchmark can be read as it goes
        rows.append(row)
        write_csv(rows, csv_path)

    infos = [run_case(case, args, out, record) for case in cases]
    write_csv(rows, csv_path)  # also when no run was made
    text = summary(rows, infos, args, plot_all(rows, cases, out))
    (out / "summary.md").write_text(text)
    print(text)
    if not args.smoke:
        return 0
    problems = smoke_problems(cases, args, csv_path)
    for p in problems:
        print(f"bench_solvers.py --smoke: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
