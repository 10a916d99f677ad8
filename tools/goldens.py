#!/usr/bin/python3
"""Golden regression tests: every shipped scene keeps its convergence history in
tests/goldens/SCENE.csv and, for every solver that reaches it, its answer in
tests/goldens/answers/ (final node positions, largest warp and weft strains, drape coefficient);
`check` re-runs a scene and compares, `bless` rewrites the goldens after an intended change and
says what changed, `spread` measures how far the answer moves across thread counts, builds and
stopping tolerance and sets the tolerances from that (tests/goldens/README.md).

The comparison:
  - the pace (the scene's own solver: its golden history; another solver: its iteration count):
    iterations to converge within ±10 % of the golden count (at least ±1); the residual curve
    within ±0.5 decades of the golden one, compared at the same fraction of the run (golden
    iteration i against new iteration round(i · n_new / n_golden));
  - the answer: the largest distance of a stored node from its golden position, the largest
    warp and weft strains, and the drape coefficient where the scene has one, each within the
    tolerance tests/goldens/tolerances.json gives the scene and solver (written by `spread`:
    4 × the largest spread measured, see README).
On a pace failure `check` writes DIR/overlay_SCENE.png (golden and new curves) and says where
they part. Exit status: 0 inside every band, 1 outside one, 2 bad input (one line naming the file).

Usage (after tools/setup.sh; the binary is --binary, else $FABFORM_BINARY, else build/fabform):
  /usr/bin/python3 tools/goldens.py check SCENE [--solver NAME] [--out DIR] [--set KEY=VALUE]...
  /usr/bin/python3 tools/goldens.py bless [SCENE ...] [--solver NAME]   # default: every scene, every solver it has
  /usr/bin/python3 tools/goldens.py spread SCENE [--solver NAME]... [--build NAME=BINARY]...
"""
import argparse
import gzip
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import plot_convergence as pc  # noqa: E402  (the tools share the history reader and the plot style)

ROOT = pathlib.Path(__file__).resolve().parent.parent
GOLDENS = ROOT / "tests" / "goldens"
ANSWERS = GOLDENS / "answers"
TOLERANCES = GOLDENS / "tolerances.json"
SPREAD_TABLE = GOLDENS / "spread.md"
# OpenBLAS picks its kernels by the CPU (the dome's newton took 27 to 45 iterations under
# different ones, all converged): the goldens pin those of any x86-64 with AVX2, so that a
# history depends on the code, not on which machine of the kind runs it.
PINNED_ENVIRONMENT = {**os.environ, "OPENBLAS_CORETYPE": "Haswell"}
ITERATION_TOLERANCE = 0.10
BAND_DECADES = 0.5
SOLVERS = ("relax", "newton", "dynamic")
# The answer's tolerance is this many times the largest spread `spread` measured (README).
SPREAD_FACTOR = 4.0
# Below these the stored numbers' own rounding (positions kept to 10 significant digits of
# metres, figures to 17) would decide: no tolerance is set tighter.
FLOORS = {"position_m": 1e-9, "strain": 1e-9, "drape": 1e-9}
# The geometry variant of `spread` scales the first body by 1 + this.
GEOMETRY_PERTURBATION = 1e-7
# Scenes of more nodes keep every k-th node's position (k = ceil(nodes / this)): the dome's
# 40401 nodes keep 1011, a wrong answer moves more than a few nodes.
MAX_STORED_NODES = 2000
QUANTITIES = (("position_m", "positions (largest distance)", "m"),
              ("warp_strain", "largest warp strain", ""),
              ("weft_strain", "largest weft strain", ""),
              ("drape", "drape coefficient", ""))


def binary_of(option: str | None) -> str:
    return option or os.environ.get("FABFORM_BINARY") or str(ROOT / "build" / "fabform")


def scene_path(scene: str) -> pathlib.Path:
    path = ROOT / "scenes" / f"{scene}.toml"
    if not path.is_file():
        raise pc.InputError(f"{path}: no such scene")
    return path


def own_solver(scene: str) -> str:
    """The solver the scene file names ([solver] name)."""
    section = None
    for line in scene_path(scene).read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("["):
            section = line.strip("[]").strip()
        elif section == "solver" and line.replace(" ", "").startswith("name="):
            return line.split("=", 1)[1].strip().strip('"')
    return "relax"


class Refused(Exception):
    """fabform refused the scene with this solver (exit 2): the solver does not reach it."""


def run_scene(scene: str, out: pathlib.Path, binary: str | None = None, solver: str | None = None,
              threads: int = 1, extra: tuple = (), environment: dict | None = None,
              timeout: float | None = None) -> pathlib.Path:
    """Runs the scene into out; returns out. A refusal (exit 2) raises Refused, other failures
    InputError; a run that stops at its cap (exit 3) is returned, result.json says so."""
    command = [binary_of(binary), "run", str(scene_path(scene)), "--out", str(out), "--quiet",
               "--threads", str(threads)]
    if solver:
        command += ["--solver", solver]
    command += list(extra)
    status = subprocess.run(command, stderr=subprocess.PIPE, text=True,
                            env=environment or PINNED_ENVIRONMENT, timeout=timeout)
    if status.returncode == 2:
        raise Refused(status.stderr.strip().splitlines()[-1] if status.stderr.strip() else "exit 2")
    if status.returncode not in (0, 3):
        raise pc.InputError(f"{scene_path(scene)}: fabform exited {status.returncode}: {status.stderr.strip()}")
    return out


def read_positions(vtk: pathlib.Path) -> np.ndarray:
    """The POINTS of a legacy ASCII VTK file (fabform's fabric.vtk), as an (n, 3) array."""
    if not vtk.is_file():
        raise pc.InputError(f"{vtk}: no such file")
    with vtk.open() as f:
        for number, line in enumerate(f, 1):
            if line.startswith("POINTS"):
                try:
                    n = int(line.split()[1])
                except (IndexError, ValueError):
                    raise pc.InputError(f"{vtk}:{number}: bad POINTS line")
                values = []
                while len(values) < 3 * n:
                    more = f.readline()
                    if not more:
                        raise pc.InputError(f"{vtk}: {n} points announced, file ends after {len(values) // 3}")
                    values.extend(float(v) for v in more.split())
                return np.array(values[:3 * n]).reshape(n, 3)
    raise pc.InputError(f"{vtk}: no POINTS")


def answer_of(run: pathlib.Path) -> dict:
    """What a run found: positions and the figures the goldens compare."""
    result = pc.read_result(run)
    figures = result.get("figures", {})
    try:
        answer = {
            "converged": bool(result["converged"]),
            "termination": result.get("termination"),
            "iterations": int(result["iterations"]),
            "residual_N": float(result["residual_N"]),
            "tolerance_N": float(result["tolerance_N"]),
            "solver": result.get("solver"),
            "warp_strain": float(figures["max_warp_strain"]["strain"]),
            "weft_strain": float(figures["max_weft_strain"]["strain"]),
            "drape": float(result["drape_coefficient"]) if "drape_coefficient" in result else None,
            "wall_seconds": float(result.get("wall_seconds", 0.0)),
        }
    except (KeyError, TypeError, ValueError) as error:
        raise pc.InputError(f"{run / 'result.json'}: missing or bad {error}")
    answer["positions"] = read_positions(run / "fabric.vtk")
    answer["nodes"] = len(answer["positions"])
    return answer


def stride_for(nodes: int) -> int:
    return max(1, math.ceil(nodes / MAX_STORED_NODES))


def answer_files(scene: str, solver: str) -> tuple:
    return ANSWERS / f"{scene}.{solver}.json", ANSWERS / f"{scene}.{solver}.xyz.csv.gz"


def write_answer(scene: str, solver: str, answer: dict) -> None:
    meta_path, xyz_path = answer_files(scene, solver)
    ANSWERS.mkdir(parents=True, exist_ok=True)
    stride = stride_for(answer["nodes"])
    meta = {"scene": scene, "solver": solver, "nodes": answer["nodes"], "stride": stride,
            "iterations": answer["iterations"], "residual_N": answer["residual_N"],
            "tolerance_N": answer["tolerance_N"], "warp_strain": answer["warp_strain"],
            "weft_strain": answer["weft_strain"], "drape": answer["drape"]}
    temporary = xyz_path.with_name(xyz_path.name + ".tmp")
    # mtime 0: the same positions give the same bytes, so a re-bless that changes nothing
    # changes no file.
    with open(temporary, "wb") as raw, gzip.GzipFile(fileobj=raw, mode="wb", mtime=0, filename="") as f:
        f.write(b"node,x_m,y_m,z_m\n")
        for i in range(0, answer["nodes"], stride):
            x, y, z = answer["positions"][i]
            f.write(f"{i},{x:.10g},{y:.10g},{z:.10g}\n".encode())
    temporary.replace(xyz_path)
    temporary = meta_path.with_name(meta_path.name + ".tmp")
    temporary.write_text(json.dumps(meta, indent=1) + "\n")
    temporary.replace(meta_path)


def read_answer(scene: str, solver: str) -> dict:
    meta_path, xyz_path = answer_files(scene, solver)
    if not meta_path.is_file():
        raise pc.InputError(f"{meta_path}: no such file (bless {scene} --solver {solver})")
    try:
        meta = json.loads(meta_path.read_text())
        with gzip.open(xyz_path, "rt") as f:
            rows = [line.split(",") for line in f.read().splitlines()[1:]]
        meta["node_index"] = np.array([int(r[0]) for r in rows])
        meta["positions"] = np.array([[float(v) for v in r[1:4]] for r in rows])
    except (OSError, ValueError, IndexError) as error:
        raise pc.InputError(f"{xyz_path}: {error}")
    return meta


def deviations(new: dict, golden: dict) -> dict:
    """How far new is from golden in each compared quantity (golden may be a stored answer,
    which holds some nodes, or a run's, which holds all)."""
    if new["nodes"] != golden["nodes"]:
        raise pc.InputError(f"{golden.get('scene', '?')}: {new['nodes']} nodes, golden {golden['nodes']}")
    index = golden.get("node_index", np.arange(golden["nodes"]))
    moved = np.linalg.norm(new["positions"][index] - golden["positions"], axis=1)
    out = {"position_m": float(moved.max()),
           "warp_strain": abs(new["warp_strain"] - golden["warp_strain"]),
           "weft_strain": abs(new["weft_strain"] - golden["weft_strain"])}
    if golden.get("drape") is not None:  # a drape coefficient lost is as wrong as one moved
        out["drape"] = abs(new["drape"] - golden["drape"]) if new.get("drape") is not None else math.inf
    return out


def read_tolerances() -> dict:
    if not TOLERANCES.is_file():
        return {"pairs": {}, "not_reached": {}}
    try:
        return json.loads(TOLERANCES.read_text())
    except ValueError as error:
        raise pc.InputError(f"{TOLERANCES}: {error}")


def write_tolerances(table: dict) -> None:
    temporary = TOLERANCES.with_name(TOLERANCES.name + ".tmp")
    temporary.write_text(json.dumps(table, indent=1, sort_keys=True) + "\n")
    temporary.replace(TOLERANCES)


def not_reached(table: dict, key: str, reason: str) -> None:
    """Records why a scene x solver pair has no golden (and drops any it had)."""
    table["not_reached"][key] = reason
    table["pairs"].pop(key, None)
    print(f"{key}: {reason}")


def pair_key(scene: str, solver: str) -> str:
    return f"{scene}.{solver}"


def pair_arguments(pair: dict) -> tuple:
    """The command-line arguments a pair runs with beyond the solver (an iteration cap of its
    own where the scene's is set for another solver)."""
    return tuple(pair.get("arguments", []))


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


def pace_problems(golden_iterations: int, new_iterations: int, result: dict) -> list:
    allowed = max(1, round(ITERATION_TOLERANCE * golden_iterations))
    problems = []
    if not result["converged"]:
        problems.append(f"did not converge ({result['termination']}) after {new_iterations} iterations")
    if abs(new_iterations - golden_iterations) > allowed:
        problems.append(f"converged in {new_iterations} iterations, golden {golden_iterations} (allowed ±{allowed})")
    return problems


def answer_report(scene: str, solver: str, new: dict, tolerances: dict) -> tuple:
    """(lines, failed): each compared quantity with its deviation and tolerance."""
    golden = read_answer(scene, solver)
    found = deviations(new, golden)
    lines, failed = [], False
    for key, label, unit in QUANTITIES:
        if key not in found:
            continue
        if key not in tolerances:
            raise pc.InputError(f"{TOLERANCES}: {pair_key(scene, solver)} has no tolerance for {key}")
        ok = found[key] <= tolerances[key]
        failed |= not ok
        lines.append(f"{label} {found[key]:.3g}{' ' + unit if unit else ''} from golden "
                     f"(tolerance {tolerances[key]:.3g}){'' if ok else ' OUTSIDE'}")
    return lines, failed, found


def check(scene: str, solver: str | None, out: pathlib.Path, binary: str | None = None,
          overrides: tuple = ()) -> dict:
    """Runs the scene (with solver, default the scene's own) and compares pace and answer.
    Returns {"pace_problems": [...], "answer_lines": [...], "answer_failed": bool,
    "deviations": {...}, "picture": path or None}."""
    solver = solver or own_solver(scene)
    own = solver == own_solver(scene)
    table = read_tolerances()
    pair = table["pairs"].get(pair_key(scene, solver))
    if pair is None:
        raise pc.InputError(f"{TOLERANCES}: no tolerances for {pair_key(scene, solver)}"
                            f"{' (' + table['not_reached'][pair_key(scene, solver)] + ')' if pair_key(scene, solver) in table['not_reached'] else ''}")
    extra = pair_arguments(pair) + tuple(a for o in overrides for a in ("--set", o))
    with tempfile.TemporaryDirectory() as work:
        run = run_scene(scene, pathlib.Path(work) / scene, binary, solver if not own else None, 1, extra)
        result = pc.read_result(run)
        new_history = pc.read_history(run / "convergence.csv")
        new = answer_of(run)
    report = {"picture": None}
    if own:
        golden = pc.read_history(GOLDENS / f"{scene}.csv")
        problems = pace_problems(golden[0][-1], new_history[0][-1], result)
        parting = first_parting(golden, new_history)
        if parting:
            problems.append(f"curves part at golden iteration {parting[0]} / new {parting[1]}: "
                            f"{parting[2]:.2f} decades apart (band {BAND_DECADES})")
        if problems:
            report["picture"] = overlay(scene, golden, new_history, float(result["tolerance_N"]), out)
    else:
        problems = pace_problems(read_answer(scene, solver)["iterations"], new["iterations"], result)
    report["pace_problems"] = problems
    report["iterations"] = new["iterations"]
    report["history"] = new_history
    lines, failed, found = answer_report(scene, solver, new, pair["tolerance"])
    report.update(answer_lines=lines, answer_failed=failed, deviations=found)
    return report


def compare(scene: str, solver: str | None, out: pathlib.Path, binary: str | None, overrides: tuple) -> int:
    report = check(scene, solver, out, binary, overrides)
    name = f"{scene} ({solver or own_solver(scene)})"
    for p in report["pace_problems"]:
        print(f"{name}: {p}")
    if not report["pace_problems"]:
        print(f"{name}: pace inside the band ({report['iterations']} iterations)")
    if report["picture"]:
        print(f"{name}: overlay in {report['picture']}")
    for line in report["answer_lines"]:
        print(f"{name}: {line}")
    return 1 if report["pace_problems"] or report["answer_failed"] else 0


def write_golden(scene: str, history: tuple) -> None:
    GOLDENS.mkdir(parents=True, exist_ok=True)
    path = GOLDENS / f"{scene}.csv"
    temporary = path.with_name(path.name + ".tmp")
    with temporary.open("w") as f:
        f.write("iteration,residual_N\n")
        for it, res in zip(*history):
            f.write(f"{it},{res:.10g}\n")
    temporary.replace(path)


def solvers_of(scene: str, table: dict) -> list:
    """The scene's own solver first, then the others that reach it (tolerances.json)."""
    own = own_solver(scene)
    return [own] + [s for s in SOLVERS if s != own and pair_key(scene, s) in table["pairs"]]


def bless_one(scene: str, solver: str, binary: str | None, table: dict) -> None:
    own = solver == own_solver(scene)
    pair = table["pairs"].get(pair_key(scene, solver), {})
    meta_path, _ = answer_files(scene, solver)
    old_answer = read_answer(scene, solver) if meta_path.is_file() else None
    with tempfile.TemporaryDirectory() as work:
        run = run_scene(scene, pathlib.Path(work) / scene, binary, None if own else solver, 1,
                        pair_arguments(pair))
        new_history = pc.read_history(run / "convergence.csv")
        new = answer_of(run)
    name = f"{scene} ({solver})"
    if not new["converged"]:
        print(f"{name}: did not converge ({new['termination']}); nothing blessed")
        return
    if own:
        path = GOLDENS / f"{scene}.csv"
        old = pc.read_history(path) if path.is_file() else None
        write_golden(scene, new_history)
        if old is None:
            print(f"{name}: new golden history, {new_history[0][-1]} iterations, final {new_history[1][-1]:.3g} N")
        else:
            parting = first_parting(old, new_history)
            change = "curve inside the old band" if not parting else \
                f"curve leaves the old band at iteration {parting[0]} ({parting[2]:.2f} decades)"
            print(f"{name}: {old[0][-1]} -> {new_history[0][-1]} iterations, final {old[1][-1]:.3g} -> "
                  f"{new_history[1][-1]:.3g} N; {change}")
    if old_answer is not None and old_answer["nodes"] == new["nodes"]:
        moved = deviations(new, old_answer)
        print(f"{name}: answer moved " + ", ".join(f"{k} {v:.3g}" for k, v in moved.items()))
    write_answer(scene, solver, new)
    print(f"{name}: answer blessed ({new['nodes']} nodes, {new['iterations']} iterations)")


def bless(scenes: list, solver: str | None, binary: str | None) -> int:
    table = read_tolerances()
    for scene in scenes:
        for s in ([solver] if solver else solvers_of(scene, table)):
            bless_one(scene, s, binary, table)
    return 0


def spread(scene: str, solvers: list, builds: list, binary: str | None, max_iterations: int | None,
           variants: tuple = ("threads", "builds", "geometry", "stop"), timeout: float | None = None,
           floor_solver: str | None = None) -> int:
    """Measures, for each solver, how far the answer moves (against the same binary's one-thread
    run at the scene's tolerance e): with 2 threads, with each other build, and stopped at e/10
    (the floor the stopping tolerance sets); and how far it lies from the other solvers'
    stored answers. Sets the tolerance to SPREAD_FACTOR times the largest of the first three
    (never under FLOORS) and rewrites tolerances.json and spread.md. A solver that is refused or
    does not converge is recorded as not reaching the scene. Only the variants named are run;
    what they measure replaces the same variants' earlier measurements, the others are kept."""
    table = read_tolerances()
    for solver in solvers or SOLVERS:
        key = pair_key(scene, solver)
        own = solver == own_solver(scene)
        arguments = ["--max-iter", str(max_iterations)] if max_iterations else []
        with tempfile.TemporaryDirectory() as work:
            work = pathlib.Path(work)
            started = time.monotonic()
            try:
                base_run = run_scene(scene, work / "base", binary, None if own else solver, 1, arguments,
                                     timeout=timeout)
            except subprocess.TimeoutExpired:
                not_reached(table, key, f"does not converge within {timeout:g} s on one thread"
                                        f"{' (--max-iter ' + str(max_iterations) + ')' if max_iterations else ''}")
                continue
            except Refused as refusal:
                not_reached(table, key, f"refused: {refusal}")
                continue
            seconds = time.monotonic() - started
            base = answer_of(base_run)
            if not base["converged"]:
                not_reached(table, key, f"does not converge: {base['termination']} after {base['iterations']} iterations "
                                        f"({seconds:.0f} s), ||V||inf = {base['residual_N']:.3g} N > e = {base['tolerance_N']:.3g} N")
                continue
            measured = dict(table["pairs"].get(key, {}).get("measured", {}))
            runs = [("threads 2", binary, 2, [])] if "threads" in variants else []
            runs += [(f"build {name}", path, 1, []) for name, path in builds] if "builds" in variants else []
            # The first body scaled by 1 + 1e-7, about float's rounding: what a CPU's own ray
            # kernels (Embree's are picked by the CPU) or a mesh read in float instead of double
            # (commit 3a993c4) does to the geometry; no shipped scene scales its first body.
            if "geometry" in variants and pc.read_result(base_run).get("bodies"):
                runs += [("geometry 1e-7", binary, 1, ["--set", f"body.0.scale={1 + GEOMETRY_PERTURBATION!r}"])]
            # Stopped a decade below where this run stopped (below e/10 when newton overshot e):
            # the distance d it moves is how far this run lies from the rest; a run that stops
            # anywhere under e (another path, a changed solver) may lie d · e / residual away,
            # the floor the stopping tolerance sets.
            tighter = min(base["tolerance_N"], base["residual_N"]) / 10
            runs += [("stop e/10", binary, 1, ["--tol", f"{tighter:.6g}"])] if "stop" in variants else []
            # Where the solver creeps below where it stopped (newton on the Cusick disc), the
            # other side: stopped at 10 e, the distance to this run scaled by e / that run's
            # residual.
            runs += [("stop 10e", binary, 1, ["--tol", f"{10 * base['tolerance_N']:.6g}"])] if "loose" in variants else []
            for label, path, threads, more in runs:
                try:  # a variant may creep (newton on the mold below e/10): it may take 10 × as long
                    run = run_scene(scene, work / label.replace(" ", "_").replace("/", ""), path,
                                    None if own else solver, threads, arguments + more,
                                    timeout=max(60.0, 10 * seconds))
                except subprocess.TimeoutExpired:
                    print(f"{key}: {label}: not done within {max(60.0, 10 * seconds):.0f} s; left out")
                    measured.pop(label, None)
                    continue
                answer = answer_of(run)
                if not answer["converged"]:
                    print(f"{key}: {label}: did not converge ({answer['termination']}); left out")
                    measured.pop(label, None)
                    continue
                measured[label] = deviations(answer, base)
                if label.startswith("stop"):
                    to_e = base["tolerance_N"] / max(base["residual_N"] if label == "stop e/10"
                                                     else answer["residual_N"], 1e-300)
                    measured[label] = {q: v * to_e for q, v in measured[label].items()}
                    measured[label]["scaled_by"] = to_e
                print(f"{key}: {label}: " + ", ".join(f"{k} {v:.3g}" for k, v in measured[label].items()))
        if floor_solver:
            # The solver creeps below e (the stop variant cannot be measured): the distance to
            # another solver's rest, also stopped at e, stands for the stopping floor.
            measured["stop e/10"] = dict(deviations(base, read_answer(scene, floor_solver)), from_solver=floor_solver)
            print(f"{key}: stopping floor from {floor_solver}'s golden: " +
                  ", ".join(f"{k} {v:.3g}" for k, v in measured["stop e/10"].items() if k != "from_solver"))
        tolerance = {}
        for q, _, _ in QUANTITIES:
            values = [m[q] for m in measured.values() if q in m]
            if values:
                tolerance[q] = max(SPREAD_FACTOR * max(values), FLOORS.get(q, FLOORS["strain"]))
        across = {}
        for other in SOLVERS:
            if other != solver and answer_files(scene, other)[0].is_file():
                across[other] = deviations(base, read_answer(scene, other))
                print(f"{key}: against {other}'s golden: " +
                      ", ".join(f"{k} {v:.3g}" for k, v in across[other].items()))
        table["not_reached"].pop(key, None)
        table["pairs"][key] = {"arguments": arguments, "iterations": base["iterations"],
                               "seconds": round(seconds, 1), "measured": measured,
                               "solvers": across, "tolerance": tolerance}
        if not answer_files(scene, solver)[0].is_file():
            write_answer(scene, solver, base)
            print(f"{key}: answer blessed (none stored yet)")
        else:
            drift = deviations(base, read_answer(scene, solver))
            print(f"{key}: stored answer is " + ", ".join(f"{k} {v:.3g}" for k, v in drift.items()) + " away")
        print(f"{key}: tolerance " + ", ".join(f"{k} {v:.3g}" for k, v in tolerance.items()))
    write_tolerances(table)
    write_spread_table(table)
    return 0


def write_spread_table(table: dict) -> None:
    lines = ["# Measured spread of the goldens' answers (written by `tools/goldens.py spread`)", "",
             "Each cell: how far the answer moved from the one-thread run of the same binary at the "
             "scene's tolerance e. `threads 2`: two threads; `builds`: other builds; `stop e/10`: "
             "the run stopped a decade below where it stopped (e/10, or its residual/10 when it "
             "overshot e), the distance scaled by e / its residual: how far a run stopped anywhere "
             "under e may lie, the stopping tolerance's floor; where the solver creeps below its "
             "stop, marked `10e` (stopped at 10 e) or `n-1` (stopped one iteration sooner), scaled by "
             "e / that run's residual, or `from S` "
             "(the distance to solver S's golden). "
             f"Tolerance = {SPREAD_FACTOR:g} × the largest of these (floor "
             f"{FLOORS['position_m']:g}). `solvers`: the largest distance from another solver's golden "
             "(not used for the tolerance: each solver has its own golden). Positions in metres.", ""]
    for q, label, _ in QUANTITIES:
        rows = [(k, p) for k, p in sorted(table["pairs"].items()) if q in p["tolerance"]]
        if not rows:
            continue
        lines += [f"## {label}", "", "| scene.solver | iterations | s | threads 2 | builds | stop e/10 | tolerance | other solvers |",
                  "|---|---|---|---|---|---|---|---|"]
        for k, p in rows:
            m = p["measured"]
            builds = [f"{v[q]:.2g}" for n, v in m.items() if n.startswith("build") and q in v]
            others = [f"{n} {v[q]:.2g}" for n, v in p["solvers"].items() if q in v]
            cell = lambda name: f"{m[name][q]:.2g}" if name in m and q in m[name] else "–"  # noqa: E731
            other_stops = [n for n in m if n.startswith("stop") and n != "stop e/10" and q in m[n]]
            if other_stops:
                stop = ", ".join(f"{m[n][q]:.2g} ({n[5:]})" for n in other_stops)
            elif "stop e/10" in m and "from_solver" in m["stop e/10"]:
                stop = f"{cell('stop e/10')} (from {m['stop e/10']['from_solver']})"
            else:
                stop = cell("stop e/10")
            lines.append(f"| {k} | {p['iterations']} | {p['seconds']} | {cell('threads 2')} | "
                         f"{', '.join(builds) or '–'} | {stop} | {p['tolerance'][q]:.2g} | "
                         f"{', '.join(others) or '–'} |")
        lines.append("")
    lines += ["## Not reached", "", "| scene.solver | why |", "|---|---|"]
    lines += [f"| {k} | {v} |" for k, v in sorted(table["not_reached"].items())]
    SPREAD_TABLE.write_text("\n".join(lines) + "\n")


def shipped() -> list:
    return sorted(p.stem for p in (ROOT / "scenes").glob("*.toml"))


def main(argv) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    check_parser = sub.add_parser("check", help="re-run a scene and compare with its goldens")
    check_parser.add_argument("scene")
    check_parser.add_argument("--solver", choices=SOLVERS, help="default: the scene's own")
    check_parser.add_argument("--out", default=str(ROOT / "results" / "goldens"), help="where overlays go")
    check_parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                              help="passed to fabform (a deliberately changed model should fail)")
    again = sub.add_parser("bless", help="re-run scenes and rewrite their goldens")
    again.add_argument("scenes", nargs="*")
    again.add_argument("--solver", choices=SOLVERS, help="default: every solver tolerances.json lists")
    measure = sub.add_parser("spread", help="measure the answers' spread and set the tolerances")
    measure.add_argument("scene")
    measure.add_argument("--solver", action="append", choices=SOLVERS, help="default: all three")
    measure.add_argument("--build", action="append", default=[], metavar="NAME=BINARY",
                         help="another build's fabform to compare with (repeatable)")
    measure.add_argument("--max-iter", type=int, help="an iteration cap of the pair's own")
    measure.add_argument("--timeout", type=float, help="seconds the first run may take before the "
                         "solver is recorded as not reaching the scene")
    measure.add_argument("--floor-from-solver", choices=SOLVERS,
                         help="where the solver creeps below e: take the distance to this solver's "
                         "golden as the stopping floor")
    measure.add_argument("--variants", default="threads,builds,geometry,stop",
                         help="which to run, of threads,builds,geometry,stop,loose "
                         "(default threads,builds,geometry,stop)")
    for p in (check_parser, again, measure):
        p.add_argument("--binary", help="fabform to run (default $FABFORM_BINARY, else build/fabform)")
    args = parser.parse_args(argv)
    try:
        if args.command == "check":
            return compare(args.scene, args.solver, pathlib.Path(args.out), args.binary, tuple(args.set))
        if args.command == "spread":
            builds = [tuple(b.split("=", 1)) for b in args.build]
            return spread(args.scene, args.solver, builds, args.binary, args.max_iter,
                          tuple(args.variants.split(",")), args.timeout, args.floor_from_solver)
        return bless(args.scenes or shipped(), args.solver, args.binary)
    except (pc.InputError, Refused) as error:
        print(f"goldens.py: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
