#!/usr/bin/python3
"""Seed 000's Figure 9, measured: drape coefficient and time of the three meshes of a circle.

Why: seed 000 drapes a circle of fabric over a pin with a quadrangular, a triangular and an arc
mesh at comparable node counts and compares their drape coefficients (DC) and times. This tool
runs the same comparison on fabform's `pin` scene, and the same meshes refined, so that anyone
can see which mesh gives which DC, at what cost, and whether the DC settles under refinement.

What it does: for each mesh and each refinement level it writes a copy of the scene (default
scenes/pin.toml) with the [fabric] mesh keys replaced, runs `build/fabform run` on it and reads
result.json. Level 1 is by default seed 000's comparison: divisions 24 for the lattices (437 nodes
on the 30 cm circle) against 15 rings on 32 spokes for the arc mesh (481 nodes); level L
multiplies divisions, rings and spokes by L. The triangular mesh's diagonal springs follow the fabric's shear table
(materials/FABRIC_shear.csv next to its warp table), added as a [shear] section. The jittered mesh (not seed
000's) is the lattice with its inner nodes moved at random by up to 0.2 of the spacing, drawn from [initial]
seed: a mesh with no symmetry of its own, run only when --meshes names it.

With --specimens N every mesh and level is run N times, as a tester tests several specimens of a
fabric, with --set initial.seed=1 … N (the scene needs a start imperfection or the jittered mesh for
them to differ), --jobs at once; the tables then give each mesh and level's mean drape coefficient
and mean fold count with their sample standard deviations, and how far apart the mean fold counts
of the meshes and levels lie (issue 22's target: at most 1).

Writes into --out (default results/drape_meshes): drape_meshes.csv (one row a run), table.md
(the Figure 9 table and the refinement table, or with --specimens the specimens' table; printed too) and runs/ (each run's result.json and
stderr, as NAME.stderr.txt). Exit status 1 if a run fails or does not converge.

Usage (after tools/setup.sh, from anywhere):
  /usr/bin/python3 tools/drape_meshes.py                 # levels 1, 2, 4: about 15 minutes
  /usr/bin/python3 tools/drape_meshes.py --levels 1      # Figure 9 alone: seconds
  /usr/bin/python3 tools/drape_meshes.py --smoke         # the test suite's check: tiny meshes
  /usr/bin/python3 tools/drape_meshes.py --scene scenes/cusick.toml --divisions 40 --rings 20 --spokes 64 --levels 1,2,3
  /usr/bin/python3 tools/drape_meshes.py --rigidity 8.06e-5 --levels 1,2   # the pin with hinges
  /usr/bin/python3 tools/drape_meshes.py --scene scenes/cusick.toml --divisions 40 --rings 20 --spokes 64 \
      --set fabric.compression=buckling --set initial.perturbation_m=1e-4   # folds from the fabric
  /usr/bin/python3 tools/drape_meshes.py --scene scenes/cusick.toml --divisions 40 --rings 20 --spokes 64 \
      --levels 1,2 --meshes quadrangular,arc,jittered --set initial.seed=2   # and from no mesh's symmetry
  /usr/bin/python3 tools/drape_meshes.py --scene scenes/cusick.toml --divisions 40 --rings 20 --spokes 64 \
      --levels 1,2 --meshes quadrangular,arc,jittered --specimens 16 --jobs 2   # means over 16 specimens
Standard library only.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import pathlib
import re
import statistics
import subprocess
import sys
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
FABFORM = ROOT / "build" / "fabform"
MESHES = ("quadrangular", "triangular", "arc", "jittered")
LEVEL_ONE = {"divisions": 24, "rings": 15, "spokes": 32}  # seed 000: similar numbers of nodes
SMOKE = {"divisions": 8, "rings": 4, "spokes": 12}
MESH_KEYS = re.compile(r"^\s*(mesh|divisions|rings|spokes)\s*=")
BENDING_KEYS = re.compile(r"^\s*(stiffness_N_m|rigidity_Nm)\s*=")
PATH_KEY = re.compile(r'^(\s*(?:warp|weft|mesh|material)\s*=\s*)"([^"]+)"')  # relative to the scene
COLUMNS = ["mesh", "level", "specimen", "nodes", "springs", "solver", "iterations", "residual_N", "converged",
           "drape_coefficient", "folds", "solve_seconds"]


def mesh_lines(mesh, level, base):
    if mesh == "arc":
        return ['mesh = "arc"', "rings = %d" % (base["rings"] * level), "spokes = %d" % (base["spokes"] * level)]
    return ['mesh = "%s"' % mesh, "divisions = %d" % (base["divisions"] * level)]


def shear_table(scene_text, scene_dir):
    """The shear table beside the scene's warp table: FABRIC_warp.csv -> FABRIC_shear.csv."""
    warp = re.search(r'^\s*warp\s*=\s*"([^"]+)"', scene_text, re.M)
    if not warp or not warp.group(1).endswith("_warp.csv"):
        sys.exit("drape_meshes: the scene's warp table is not named FABRIC_warp.csv")
    return (scene_dir / warp.group(1)).resolve().with_name(warp.group(1).split("/")[-1][:-9] + "_shear.csv")


def variant(scene_text, scene_dir, mesh, level, base, rigidity=None):
    """The scene with the [fabric] mesh keys replaced, its [bending] made hinges of `rigidity`
    (N·m) when given, and its relative paths made absolute."""
    out, section = [], ""
    for line in scene_text.splitlines():
        header = re.match(r"^\s*\[+\s*([A-Za-z_]+)", line)
        if header:
            section = header.group(1)
        if section == "fabric" and MESH_KEYS.match(line):
            continue
        if rigidity is not None and section == "bending" and BENDING_KEYS.match(line):
            line = "rigidity_Nm = %r" % rigidity
        line = PATH_KEY.sub(lambda m: '%s"%s"' % (m.group(1), (scene_dir / m.group(2)).resolve()), line)
        out.append(line)
        if section == "fabric" and re.match(r"^\s*diameter_m\s*=", line):
            out.extend(mesh_lines(mesh, level, base))
    if mesh == "triangular" and not re.search(r"^\s*\[shear\]", scene_text, re.M):
        out += ["", "[shear]", 'material = "%s"' % shear_table(scene_text, scene_dir)]
    return "\n".join(out) + "\n"


def run(fabform, scene_path, out_dir, extra):
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    with open(stderr_of(out_dir), "w") as err:
        status = subprocess.run([fabform, "run", str(scene_path), "--out", str(out_dir), "--quiet"] + extra,
                                stderr=err, stdout=subprocess.DEVNULL).returncode
    result = out_dir / "result.json"
    return status, json.loads(result.read_text()) if result.exists() else None


def stderr_of(out_dir):
    return out_dir.with_name(out_dir.name + ".stderr.txt")  # fabform wants its folder to itself


def row_of(mesh, level, specimen, result):
    """The run's row, or None when it has no drape figures (a state with no shadow)."""
    if not result.get("drape"):
        return None
    springs = result["fabric"]["springs"]
    return {"mesh": mesh, "level": level, "specimen": specimen, "nodes": result["fabric"]["nodes"], "springs": sum(springs.values()),
            "solver": result["solver"],
            "iterations": result["iterations"], "residual_N": "%.3g" % result["residual_N"],
            "converged": result["converged"], "drape_coefficient": "%.4f" % result["drape_coefficient"],
            "folds": result["drape"]["folds"], "solve_seconds": "%.2f" % result["solve_seconds"]}


def tables(rows, levels, meshes, scene_name):
    """The Figure 9 table (level 1) and the DC of each mesh at every level."""
    lines = ["Figure 9 (seed 000), measured: %s, level %d" % (scene_name, levels[0]), "",
             "| mesh | nodes | DC (%) | folds | iterations | time (s) |", "|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        if r["level"] == levels[0]:
            lines.append("| %s | %d | %.2f | %d | %d | %s |" % (r["mesh"], r["nodes"], 100 * float(r["drape_coefficient"]),
                                                          r["folds"], r["iterations"], r["solve_seconds"]))
    lines += ["", "DC (%) under refinement (nodes in brackets); last column: the change between the two finest", "",
              "| mesh | " + " | ".join("level %d" % L for L in levels) + " | finest change (points) |",
              "|---|" + "---:|" * (len(levels) + 1)]
    for mesh in meshes:
        by_level = {r["level"]: r for r in rows if r["mesh"] == mesh}
        cells = ["%.2f (%d)" % (100 * float(by_level[L]["drape_coefficient"]), by_level[L]["nodes"]) if L in by_level
                 else "-" for L in levels]
        change = "-"
        if len(levels) > 1 and levels[-1] in by_level and levels[-2] in by_level:
            change = "%.2f" % (100 * abs(float(by_level[levels[-1]]["drape_coefficient"])
                                         - float(by_level[levels[-2]]["drape_coefficient"])))
        lines.append("| %s | %s | %s |" % (mesh, " | ".join(cells), change))
    lines += ["", "Folds under refinement; last column: the largest difference between any two runs", "",
              "| mesh | " + " | ".join("level %d" % L for L in levels) + " | spread |",
              "|---|" + "---:|" * (len(levels) + 1)]
    for mesh in meshes:
        by_level = {r["level"]: r for r in rows if r["mesh"] == mesh}
        cells = ["%d" % by_level[L]["folds"] if L in by_level else "-" for L in levels]
        folds = [r["folds"] for r in by_level.values()]
        lines.append("| %s | %s | %s |" % (mesh, " | ".join(cells), max(folds) - min(folds) if folds else "-"))
    every = [r["folds"] for r in rows]
    if every:
        lines += ["", "Folds over every run: %d to %d" % (min(every), max(every))]
    return "\n".join(lines) + "\n"


def specimen_tables(rows, levels, meshes, specimens):
    """Each mesh and level's mean DC and mean folds over its specimens (sample standard deviations),
    and the largest difference between two mean fold counts."""
    def spread(values):
        return "%.2f" % statistics.stdev(values) if len(values) > 1 else "-"
    lines = ["Over %d specimens (initial.seed 1 to %d): mean DC (%%) ± sd, mean folds ± sd [least-most]" % (specimens, specimens),
             "", "| mesh | " + " | ".join("level %d" % L for L in levels) + " |", "|---|" + "---:|" * len(levels)]
    means = []
    for mesh in meshes:
        cells = []
        for level in levels:
            runs = [r for r in rows if r["mesh"] == mesh and r["level"] == level and r["converged"]]
            if not runs:
                cells.append("-")
                continue
            dc = [100 * float(r["drape_coefficient"]) for r in runs]
            folds = [r["folds"] for r in runs]
            means.append(statistics.mean(folds))
            cells.append("%.2f ± %s, %.2f ± %s [%d-%d] (%d of %d)" % (statistics.mean(dc), spread(dc), means[-1], spread(folds),
                                                                    min(folds), max(folds), len(runs), specimens))
        lines.append("| %s | %s |" % (mesh, " | ".join(cells)))
    if means:
        lines += ["", "Mean fold counts: %.2f to %.2f, %.2f apart (target: at most 1)" % (min(means), max(means), max(means) - min(means))]
    return "\n".join(lines) + "\n"


def perturbed(scene_text, settings):
    """Whether the runs start from a seeded imperfection: the scene's or a --set's perturbation_m > 0."""
    amplitude = tomllib.loads(scene_text).get("initial", {}).get("perturbation_m", 0.0)
    for setting in settings:
        key, _, value = setting.partition("=")
        if key == "initial.perturbation_m":
            amplitude = float(value)
    return amplitude > 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "pin.toml"))
    parser.add_argument("--levels", default="1,2,4", help="refinement levels, comma-separated")
    parser.add_argument("--divisions", type=int, default=LEVEL_ONE["divisions"], help="lattice divisions at level 1")
    parser.add_argument("--rings", type=int, default=LEVEL_ONE["rings"], help="arc mesh rings at level 1")
    parser.add_argument("--spokes", type=int, default=LEVEL_ONE["spokes"], help="arc mesh spokes at level 1")
    parser.add_argument("--meshes", default=",".join(MESHES[:3]), help="which meshes, comma-separated (%s)" % ", ".join(MESHES))
    parser.add_argument("--solver", default=None, help="override the scene's solver")
    parser.add_argument("--rigidity", type=float, default=None,
                        help="bend with hinges of this flexural rigidity (N·m) in place of the scene's [bending]")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="passed to every run as fabform's --set (repeatable)")
    parser.add_argument("--out", default=str(ROOT / "results" / "drape_meshes"))
    parser.add_argument("--fabform", default=str(FABFORM), help="the fabform binary to run")
    parser.add_argument("--smoke", action="store_true", help="tiny meshes, levels 1 and 2")
    parser.add_argument("--specimens", type=int, default=0,
                        help="run every mesh and level with initial.seed 1 ... N and give the means")
    parser.add_argument("--jobs", type=int, default=1, help="runs at once, each with cores / jobs threads")
    args = parser.parse_args(argv)
    base = SMOKE if args.smoke else {"divisions": args.divisions, "rings": args.rings, "spokes": args.spokes}
    levels = [1, 2] if args.smoke else [int(v) for v in args.levels.split(",")]
    scene_path = pathlib.Path(args.scene).resolve()
    scene_text = scene_path.read_text()
    out = pathlib.Path(args.out)
    (out / "scenes").mkdir(parents=True, exist_ok=True)
    extra = ["--solver", args.solver] if args.solver else []
    for setting in args.set:
        extra += ["--set", setting]
    if args.rigidity is not None and not (args.rigidity > 0 and re.search(r"^\s*\[bending\]", scene_text, re.M)):
        sys.exit("drape_meshes: --rigidity needs a positive value and a scene with a [bending] table")
    meshes = args.meshes.split(",")
    for mesh in meshes:
        if mesh not in MESHES:
            sys.exit("drape_meshes: --meshes: no mesh named '%s' (%s)" % (mesh, ", ".join(MESHES)))
    if args.specimens < 0 or args.jobs < 1:
        sys.exit("drape_meshes: --specimens must be 0 or more and --jobs 1 or more")
    if args.specimens and any(setting.startswith("initial.seed=") for setting in args.set):
        sys.exit("drape_meshes: --specimens sets initial.seed itself (1 to N); drop --set initial.seed")
    if args.specimens > 1 and any(m != "jittered" for m in meshes) and not perturbed(scene_text, args.set):
        sys.exit("drape_meshes: --specimens: every specimen of a mesh but the jittered one would be the same run "
                 "(no initial.perturbation_m)")
    if args.jobs > 1:
        extra += ["--threads", str(max(1, (os.cpu_count() or 1) // args.jobs))]
    jobs = []
    for level in levels:
        for mesh in meshes:
            name = "%s_%d" % (mesh, level)
            path = out / "scenes" / (name + ".toml")
            path.write_text(variant(scene_text, scene_path.parent, mesh, level, base, args.rigidity))
            for specimen in range(1, args.specimens + 1) if args.specimens else [0]:
                run_name = "%s_s%d" % (name, specimen) if specimen else name
                seed = ["--set", "initial.seed=%d" % specimen] if specimen else []
                jobs.append((mesh, level, specimen, run_name, path, extra + seed))
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run, args.fabform, j[4], out / "runs" / j[3], j[5]) for j in jobs]
        for done, future in enumerate(concurrent.futures.as_completed(futures), start=1):
            future.result()
            print("drape_meshes: %d of %d runs done" % (done, len(jobs)), file=sys.stderr)
    rows, failed = [], []
    for (mesh, level, specimen, name, _, _), future in zip(jobs, futures):
        status, result = future.result()
        if result is None or status not in (0, 3):
            failed.append("%s: exit %d, see %s" % (name, status, stderr_of(out / "runs" / name)))
            continue
        row = row_of(mesh, level, specimen, result)
        if row is None:
            failed.append("%s: no drape figures (%s)" % (name, result["message"]))
            continue
        rows.append(row)
        if not result["converged"]:
            failed.append("%s: %s" % (name, result["message"]))
        print("%-14s level %d: %5d nodes, DC %.2f %%, %s s" % (name, level, row["nodes"],
              100 * float(row["drape_coefficient"]), row["solve_seconds"]), file=sys.stderr)
    with open(out / "drape_meshes.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    text = (specimen_tables(rows, levels, meshes, args.specimens) if args.specimens
            else tables(rows, levels, meshes, scene_path.name))
    (out / "table.md").write_text(text)
    print(text)
    for line in failed:
        print("drape_meshes: " + line, file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
