#!/usr/bin/python3
"""Speed against accuracy: every solver on the dome and the shipped scenes, measured in one run.

Why: users trade speed for accuracy, so the trade is measured, not assumed. For each case (the
dome of DESIGN.md at each N, smooth or harsh start, and each shipped scene) this runs
`build/fabform run` with every solver at every tolerance and records wall time, iterations,
final residual (recomputed from positions), peak memory (the child's maximum resident size) and
the largest node distance from a reference solution: newton at --reference-tol, or, where
newton does not reach it, the tightest converged run. A run past --budget seconds is killed and
recorded as "over budget" (its time is then a lower bound).

Writes into --out: bench.csv (one row a run), summary.md (the table and the issue's targets,
printed too) and, when matplotlib is installed, trade_CASE.png/.svg (time against error, one
line per solver).

Usage (after tools/setup.sh):
  /usr/bin/python3 tools/bench_solvers.py                          # the full benchmark (hours)
  /usr/bin/python3 tools/bench_solvers.py --sizes 41,101 --scenes dome --tolerances 1e-2,1e-4,1e-6
  /usr/bin/python3 tools/bench_solvers.py --smoke                  # seconds: the test suite's check
"""
import argparse
import csv
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import time
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
FABFORM = ROOT / "build" / "fabform"
SHIPPED = ("mold", "torso")
COLUMNS = ["case", "solver", "tolerance_N", "threads", "status", "iterations", "seconds",
           "residual_N", "peak_MiB", "max_distance_m", "distance_per_spacing"]


def fail(message: str) -> None:
    print(f"bench_solvers.py: {message}", file=sys.stderr)
    sys.exit(2)


def floats(text: str) -> list:
    try:
        return [float(v) for v in text.split(",") if v]
    except ValueError:
        fail(f"not a list of numbers: '{text}'")


def ints(text: str) -> list:
    try:
        return [int(v) for v in text.split(",") if v]
    except ValueError:
        fail(f"not a list of integers: '{text}'")


class Case:
    """A scene and the --set overrides that make it one benchmark case."""

    def __init__(self, name: str, scene: str, overrides: list, spacing_m: float):
        self.name, self.scene, self.overrides, self.spacing_m = name, scene, overrides, spacing_m


def scene_spacing(scene: pathlib.Path, divisions=None) -> float:
    fabric = tomllib.loads(scene.read_text())["fabric"]
    divisions = divisions or fabric["divisions"]
    return min(size / d for size, d in zip(fabric["size_m"], divisions))


def cases(args) -> list:
    out = []
    for scene in args.scenes:
        path = ROOT / "scenes" / f"{scene}.toml"
        if scene != "dome":
            out.append(Case(scene, str(path), [], scene_spacing(path)))
            continue
        for n in args.sizes:
            for start in args.starts:
                sets = [f"fabric.divisions=[{n - 1},{n - 1}]"]
                if start == "harsh":  # DESIGN.md: every interior node at z = 0.04 (seed 003's start)
                    sets.append("initial.shape=lift")
                out.append(Case(f"dome-{start}-N{n}", str(path), sets, scene_spacing(path, [n - 1, n - 1])))
    return out


def read_positions(obj: pathlib.Path) -> list:
    with obj.open() as f:
        return [tuple(map(float, line.split()[1:4])) for line in f if line.startswith("v ")]


def run_fabform(case: Case, solver: str, tolerance: float, threads: int, out: pathlib.Path,
                budget: float) -> dict:
    """One run; its figures, and its positions under 'x' when it wrote any."""
    if out.exists():
        shutil.rmtree(out)
    command = [str(FABFORM), "run", case.scene, "--out", str(out), "--solver", solver,
               "--tol", repr(tolerance), "--threads", str(threads), "--quiet"]
    for s in case.overrides:
        command += ["--set", s]
    started = time.monotonic()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    status, rusage, over = None, None, False
    while status is None:
        pid, raw, rusage = os.wait4(child.pid, os.WNOHANG)
        if pid:
            status = os.waitstatus_to_exitcode(raw)
        elif time.monotonic() - started > budget:
            child.kill()
            _, raw, rusage = os.wait4(child.pid, 0)
            status, over = os.waitstatus_to_exitcode(raw), True
        else:
            time.sleep(0.05)
    wall = time.monotonic() - started
    row = {"case": case.name, "solver": solver, "tolerance_N": tolerance, "threads": threads,
           "peak_MiB": round(rusage.ru_maxrss / 1024.0, 1), "seconds": round(wall, 3)}
    if over:
        return dict(row, status="over budget")
    if status not in (0, 3):
        err = child.stderr.read().decode(errors="replace").strip().splitlines()
        return dict(row, status=f"failed ({status}): {err[-1] if err else ''}")
    result = json.loads((out / "result.json").read_text())
    row.update(status="converged" if result["converged"] else result["termination"],
               iterations=result["iterations"], seconds=round(result["wall_seconds"], 3),
               residual_N=result["residual_recomputed_N"])
    row["x"] = read_positions(out / "fabric.obj")
    return row


def reference(case: Case, args, work: pathlib.Path) -> list:
    row = run_fabform(case, "newton", args.reference_tol, 1, work / "reference", args.reference_budget)
    if row["status"] != "converged":
        print(f"  {case.name}: newton reference at {args.reference_tol:g} N: {row['status']}", file=sys.stderr)
        return None
    return row["x"]


def largest_distance(a: list, b: list) -> float:
    return max(math.dist(p, q) for p, q in zip(a, b))


def run_case(case: Case, args, work: pathlib.Path) -> list:
    print(f"{case.name}:", file=sys.stderr)
    ref = reference(case, args, work)
    rows = []
    for solver in args.solvers:
        for threads in args.threads:
            for tolerance in args.tolerances:
                row = run_fabform(case, solver, tolerance, threads, work / "run", args.budget)
                print(f"  {solver} e={tolerance:g} threads={threads}: {row['status']}, "
                      f"{row.get('iterations', '-')} it, {row['seconds']} s", file=sys.stderr)
                rows.append(row)
                if row["status"] == "over budget":
                    break  # tighter tolerances take longer still
    converged = [r for r in rows if r["status"] == "converged"]
    if ref is None and converged:  # the tightest converged run stands in for the reference
        ref = min(converged, key=lambda r: r["tolerance_N"])["x"]
    for r in rows:
        x = r.pop("x", None)
        if ref is not None and x is not None and len(x) == len(ref):
            r["max_distance_m"] = largest_distance(x, ref)
            r["distance_per_spacing"] = r["max_distance_m"] / case.spacing_m
    return rows


def write_csv(rows: list, path: pathlib.Path) -> None:
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for r in rows:
            writer.writerow({k: r.get(k, "") for k in COLUMNS})


def plot(rows: list, out: pathlib.Path) -> str:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return "matplotlib is not installed: no trade-curve plots (apt-get install python3-matplotlib)"
    for case in sorted({r["case"] for r in rows}):
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for solver in sorted({r["solver"] for r in rows if r["case"] == case}):
            pts = [r for r in rows if r["case"] == case and r["solver"] == solver and r["threads"] == min(
                x["threads"] for x in rows) and r["status"] == "converged" and r.get("max_distance_m", 0) > 0]
            if not pts:
                continue
            ax.plot([p["max_distance_m"] for p in pts], [p["seconds"] for p in pts], "o-", label=solver)
            for p in pts:
                ax.annotate(f"{p['tolerance_N']:g}", (p["max_distance_m"], p["seconds"]), fontsize=7,
                            textcoords="offset points", xytext=(3, 3))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("largest node distance from the reference (m)")
        ax.set_ylabel("wall time (s)")
        ax.set_title(f"{case}: time against error (labels: e in N)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        for ext in ("png", "svg"):
            fig.savefig(out / f"trade_{case}.{ext}")
        plt.close(fig)
    return "trade curves: trade_CASE.png and .svg"


def find(rows, case, solver, tolerance, threads=1):
    for r in rows:
        if r["case"] == case and r["solver"] == solver and r["threads"] == threads and \
                math.isclose(r["tolerance_N"], tolerance):
            return r
    return None


def seconds_text(r) -> str:
    return (">" if r["status"] == "over budget" else "") + f"{r['seconds']:.3g}"


def targets(rows: list, args) -> list:
    lines = ["## Targets", ""]
    fast = find(rows, "dome-smooth-N201", "newton", 1e-6)
    slow = find(rows, "dome-smooth-N201", "relax", 1e-6)
    if fast and slow and fast["status"] == "converged":
        ratio = slow["seconds"] / fast["seconds"]
        bound = slow["status"] == "over budget"
        met = ratio >= 100
        lines.append(f"- dome smooth N=201, e=1e-6: relax {seconds_text(slow)} s, newton "
                     f"{fast['seconds']:.3g} s: newton {'≥ ' if bound else ''}{ratio:.0f}× faster "
                     f"(target 100×: {'met' if met else 'not met' if not bound else 'not shown: raise --budget'})")
    else:
        lines.append("- dome smooth N=201, e=1e-6, newton against relax: not measured")
    big = find(rows, "dome-smooth-N1001", "newton", 1e-6)
    if big:
        ok = big["status"] == "converged" and big["seconds"] <= 60 and big["peak_MiB"] <= 4096
        lines.append(f"- dome N=1001, e=1e-6, newton: {big['status']}, {seconds_text(big)} s, "
                     f"{big['peak_MiB']:.0f} MiB (target 60 s, 4096 MiB: {'met' if ok else 'not met'})")
    else:
        lines.append("- dome N=1001, e=1e-6: not measured")
    for r2 in [r for r in rows if r["threads"] == 2]:
        n = int(r2["case"].split("N")[-1]) if "-N" in r2["case"] else 0
        r1 = find(rows, r2["case"], r2["solver"], r2["tolerance_N"], 1)
        if n >= 401 and r1 and r1["status"] == r2["status"] == "converged":
            ratio = r1["seconds"] / r2["seconds"]
            lines.append(f"- {r2['case']} {r2['solver']} e={r2['tolerance_N']:g}: 2 threads "
                         f"{ratio:.2f}× faster than 1 (target 1.6×: {'met' if ratio >= 1.6 else 'not met'})")
    for case in sorted({r["case"] for r in rows if "harsh" in r["case"]}):
        for solver in args.solvers:
            mine = [r for r in rows if r["case"] == case and r["solver"] == solver]
            if mine:
                done = [r for r in mine if r["status"] == "converged"]
                lines.append(f"- {case} {solver}: converged at {len(done)} of {len(mine)} tolerances")
    for case in [c for c in SHIPPED if any(r["case"] == c for r in rows)]:
        both = [r for r in rows if r["case"] == case and r["solver"] == "relax" and r["status"] == "converged"
                and "distance_per_spacing" in r]
        if both:
            tight = min(both, key=lambda r: r["tolerance_N"])
            lines.append(f"- {case}: relax at e={tight['tolerance_N']:g} lies {tight['distance_per_spacing']:.2g} "
                         f"of the spacing from newton's reference (target 1e-3: "
                         f"{'met' if tight['distance_per_spacing'] <= 1e-3 else 'not met'})")
    return lines


def table_row(r: dict) -> str:
    def number(key, form):
        return format(r[key], form) if key in r else ""
    cells = [r["case"], r["solver"], f"{r['tolerance_N']:g}", str(r["threads"]), r["status"],
             str(r.get("iterations", "")), seconds_text(r), number("residual_N", ".2e"),
             number("peak_MiB", ".0f"), number("max_distance_m", ".2e"), number("distance_per_spacing", ".2e")]
    return "| " + " | ".join(cells) + " |"


def summary(rows: list, args, plot_note: str) -> str:
    lines = ["# Solver benchmark", "", f"`{' '.join(sys.argv)}` on {os.cpu_count()} cores; "
             f"reference: newton at {args.reference_tol:g} N. {plot_note}.", "",
             "| case | solver | e (N) | threads | status | iterations | wall (s) | ‖V‖∞ (N) | peak MiB "
             "| max distance (m) | / spacing |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    lines += [table_row(r) for r in rows]
    return "\n".join(lines + [""] + targets(rows, args)) + "\n"


def smoke_failures(rows: list, args) -> list:
    problems = []
    for solver in args.solvers:
        for tolerance in args.tolerances:
            r = find(rows, "dome-smooth-N21", solver, tolerance)
            if r is None:
                problems.append(f"no row for {solver} at {tolerance:g}")
            elif r["status"] != "converged":
                problems.append(f"{solver} at {tolerance:g}: {r['status']}")
            elif not r["residual_N"] <= tolerance:
                problems.append(f"{solver} at {tolerance:g}: residual {r['residual_N']:g} above e")
            elif "max_distance_m" not in r:
                problems.append(f"{solver} at {tolerance:g}: no distance from the reference")
    return problems


def parse(argv) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default=str(ROOT / "results" / "bench"))
    p.add_argument("--scenes", default="dome,mold,torso")
    p.add_argument("--sizes", default="41,101,201,401,1001", help="dome nodes a side")
    p.add_argument("--starts", default="smooth,harsh")
    p.add_argument("--solvers", default="", help="default: every solver `fabform solvers` lists")
    p.add_argument("--tolerances", default="1e-1,1e-2,1e-3,1e-4,1e-5,1e-6,1e-7,1e-8")
    p.add_argument("--threads", default="1")
    p.add_argument("--budget", type=float, default=600.0, help="seconds a run may take")
    p.add_argument("--reference-tol", type=float, default=1e-10)
    p.add_argument("--reference-budget", type=float, default=3600.0)
    p.add_argument("--smoke", action="store_true", help="dome N=21 smooth, 1e-2 and 1e-5, every solver")
    args = p.parse_args(argv)
    if args.smoke:
        args.scenes, args.sizes, args.starts, args.tolerances = "dome", "21", "smooth", "1e-2,1e-5"
        args.threads, args.budget = "1", 60.0
    if not FABFORM.exists():
        fail(f"{FABFORM} is missing: build first (tools/setup.sh)")
    known = subprocess.run([str(FABFORM), "solvers"], capture_output=True, text=True, check=True).stdout.split()
    args.solvers = args.solvers.split(",") if args.solvers else known
    args.scenes = args.scenes.split(",")
    args.starts = args.starts.split(",")
    for name, given, allowed in (("solver", args.solvers, known), ("scene", args.scenes, ("dome",) + SHIPPED),
                                 ("start", args.starts, ("smooth", "harsh"))):
        for g in given:
            if g not in allowed:
                fail(f"unknown {name} '{g}' (one of {', '.join(allowed)})")
    args.sizes, args.threads = ints(args.sizes), ints(args.threads)
    args.tolerances = floats(args.tolerances)
    if any(n < 2 for n in args.sizes) or any(t < 1 for t in args.threads) or any(
            not e > 0 for e in args.tolerances) or not args.budget > 0:
        fail("sizes must be ≥ 2, threads ≥ 1, tolerances and budget > 0")
    return args


def main(argv) -> int:
    args = parse(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    work = out / "runs"
    rows = []
    for case in cases(args):
        rows += run_case(case, args, work)
        write_csv(rows, out / "bench.csv")  # kept up to date: a long benchmark can be read as it goes
    note = plot(rows, out)
    text = summary(rows, args, note)
    (out / "summary.md").write_text(text)
    print(text)
    if args.smoke:
        problems = smoke_failures(rows, args)
        for p in problems:
            print(f"bench_solvers.py --smoke: {p}", file=sys.stderr)
        return 1 if problems else 0
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
