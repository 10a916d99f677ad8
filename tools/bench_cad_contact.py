#!/usr/bin/python3
"""How robust forming over a user's faceted CAD part is, per contact variant: one sweep.

Why: with a real CAD part as the tool, node-only contact lets springs cut through its sharp
edges (result.json's figures.deepest_spring_cut_m) and wrapping the edges (`wrap_edges_deg =
30`) makes newton stall. The issue's target is a contact variant that forms every case cleanly:
the "springs" variant (`spring_contact = true` on the body: springs kept out of the body along
their length by a penalty on their points' depth) clean in 100 % of the cases, in at most 3 × the
solver time of node-only contact on the same case (the median of the ratios, over the cases where
node-only contact converged). Timings on a shared machine drift, so each case's variants run next to
each other and the ratio is taken case by case.

What it does: for each part (trimesh's featuretype, inches; octagonal_pocket, metres;
plate_holes, mm: molds/README.md) × mode × resolution × orientation × friction μ on the part ×
contact variant, it writes a scene into OUT/scenes/ and runs `build/fabform run SCENE --out
OUT/runs/CASE --quiet`, --jobs at a time. The blank is the swim knit
(materials/white-swim-solid_*.csv), the part's placed x and y size + 6 cm (3 cm round it),
cells about square with the given divisions along its longer side, at z = 0, the part centred
under it (its placed bounding box, read from the STL here, rotations as fabform applies them).
- punch: the part's top 2 mm under the blank, pushed up 20 mm (the 12.7 mm plate 12 mm, so the
  blank stays above its lower face) in 10 load steps; a blank holder grips a 15 mm frame
  ([clamp] force_N 40, friction 0.3).
- die: vacuum forming over the part standing on the machine's table (a 5 mm slab under the
  blank, its top at the part's lowest point, written beside the scene as OUT/scenes/table_*.obj):
  the blank's perimeter held in x, y and z 1 mm above the table, its inside lifted 5 mm clear of
  the part, and a vacuum of 3000 Pa ([pressure]) pulls it onto the part and the table round it.
Resolutions 40 and 60 divisions; orientations as is, turned 90° about z, tilted 10° about x;
μ 0 and 0.3; variants nodes (no key), wrap (`wrap_edges_deg = 30`), edges (`edge_contact_deg =
2`) and springs (`spring_contact = true`). newton, tolerance_N 1e-5, max_iterations 300 (a step).
A case is clean when result.json says converged at every load step, its residual is at most
1e-5 N and figures.deepest_spring_cut_m at most 1e-4 m. It prints a table of the cases and per
variant the fraction clean, the median iterations and the median over cases of the time ratio
to the nodes run of the same case (where that one converged), and writes them into
OUT/summary.json. A case whose load steps fabform had to cut (halve, `[solver] max_step_cuts`)
says how many cuts beside its termination.

Usage (after tools/setup.sh):
  /usr/bin/python3 tools/bench_cad_contact.py                        # the whole sweep: 72 cases a variant
  /usr/bin/python3 tools/bench_cad_contact.py --quick --variants nodes,wrap --jobs 2
  /usr/bin/python3 tools/bench_cad_contact.py --quick --variants nodes,springs --jobs 2
--quick runs one resolution (40) and the part as is only; --modes punch (or die) one mode.
--target names the variant the target is about (default springs; it needs nodes among --variants
for the ratio). A case still running after --timeout seconds is stopped (SIGTERM: fabform writes
what it has, "interrupted") and is not clean. Writes into --out (default
results/bench_cad_contact). Exit status 0 when the target is met, 1 when not, 2 on bad input or
a case fabform refused or failed to run (its message is in the table). Standard library only.
FABFORM_BINARY names the fabform to run (default build/fabform).
"""
import argparse
import concurrent.futures
import json
import math
import os
import pathlib
import statistics
import struct
import subprocess
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import generated_mesh  # noqa: E402  (OBJ text)

ROOT = pathlib.Path(__file__).resolve().parent.parent
FABFORM = pathlib.Path(os.environ.get("FABFORM_BINARY", ROOT / "build" / "fabform"))
UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254}
# name: (mesh, its units, punch travel in m). The plate is 12.7 mm thick: 12 mm keeps the
# blank's plane above its lower face.
PARTS = {
    "featuretype": ("molds/trimesh_featuretype.STL", "in", 0.020),
    "octagonal_pocket": ("molds/trimesh_octagonal_pocket.stl", "m", 0.020),
    "plate_holes": ("molds/trimesh_plate_holes.STL", "mm", 0.012),
}
MODES = ("punch", "die")
RESOLUTIONS = (40, 60)
ORIENTATIONS = {"asis": (0.0, 0.0, 0.0), "turned": (0.0, 0.0, 90.0), "tilted": (10.0, 0.0, 0.0)}
FRICTIONS = (0.0, 0.3)
VARIANTS = ("nodes", "wrap", "edges", "springs")
MARGIN_M = 0.03          # blank beyond the part's placed footprint, each side
GAP_M = 0.002            # the punch's top under the blank at the start
STEPS = 10
CLEARANCE_M = 0.005      # the die's lifted blank above the part's top
TABLE_GAP_M = 0.001      # the die's table under the blank's held perimeter
TABLE_THICKNESS_M = 0.005
VACUUM_PA = 3000.0
TOLERANCE_N = 1e-5
MAX_ITERATIONS = 300
MAX_CUT_M = 1e-4
TARGET_RATIO = 3.0
MATERIALS = ("materials/white-swim-solid_warp.csv", "materials/white-swim-solid_weft.csv")


def read_stl(path: pathlib.Path) -> list:
    """The vertices of an STL, binary (84 + 50 n bytes) or ASCII, in the file's units."""
    data = path.read_bytes()
    if len(data) >= 84:
        n = struct.unpack_from("<I", data, 80)[0]
        if len(data) >= 84 + 50 * n and n > 0:   # a binary STL may start "solid" too
            points = []
            for k in range(n):
                f = struct.unpack_from("<12f", data, 84 + 50 * k)
                points += [f[3:6], f[6:9], f[9:12]]
            return points
    points = [tuple(float(x) for x in line.split()[1:4])
              for line in data.decode("ascii", "replace").splitlines() if line.strip().startswith("vertex")]
    if not points:
        raise ValueError(f"{path}: no triangles read")
    return points


def rotate(points: list, degrees: tuple) -> list:
    """Rotation about x, then y, then z (right-handed, about the file's origin), as fabform
    places a body (checked against its bodies.obj)."""
    ax, ay, az = (math.radians(d) for d in degrees)
    cx, sx, cy, sy, cz, sz = math.cos(ax), math.sin(ax), math.cos(ay), math.sin(ay), math.cos(az), math.sin(az)
    out = []
    for x, y, z in points:
        y, z = y * cx - z * sx, y * sx + z * cx
        x, z = x * cy + z * sy, -x * sy + z * cy
        x, y = x * cz - y * sz, x * sz + y * cz
        out.append((x, y, z))
    return out


def bounding_box(points: list) -> tuple:
    return tuple(min(p[i] for p in points) for i in range(3)), tuple(max(p[i] for p in points) for i in range(3))


def ceil_mm(x: float) -> float:
    return math.ceil(x * 1000.0 - 1e-9) / 1000.0


def scene_text(case: dict, contact_line: str) -> str:
    """A case's scene: blank, part (with its variant's contact line, if any), and the mode's holder
    or vacuum."""
    mesh, units, travel = PARTS[case["part"]]
    lo, hi = case["bbox"]
    width, height = ceil_mm(hi[0] - lo[0] + 2 * MARGIN_M), ceil_mm(hi[1] - lo[1] + 2 * MARGIN_M)
    spacing = max(width, height) / case["res"]
    divisions = [max(4, round(width / spacing)), max(4, round(height / spacing))]
    centre = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
    if case["mode"] == "punch":
        translation = [-centre[0], -centre[1], -GAP_M - hi[2]]
        top = -GAP_M
    else:   # standing on the table, its top TABLE_GAP_M under the perimeter (z = 0)
        translation = [-centre[0], -centre[1], -TABLE_GAP_M - lo[2]]
        top = hi[2] - lo[2] - TABLE_GAP_M
    lines = [
        f"# tools/bench_cad_contact.py: {case['name']}",
        f"# {case['part']} ({units}) as {case['mode']}, {case['res']} divisions, {case['orientation']} "
        f"{list(ORIENTATIONS[case['orientation']])} deg, mu {case['mu']:g}, contact {case['variant']}",
        "", "[scene]", f'name = "{case["name"]}"', "", "[fabric]",
        f"size_m = [{width:.3f}, {height:.3f}]", f"divisions = [{divisions[0]}, {divisions[1]}]",
        f"origin_m = [{-width / 2:.4f}, {-height / 2:.4f}, 0.0]",
        f'warp = "{ROOT / MATERIALS[0]}"', f'weft = "{ROOT / MATERIALS[1]}"', "",
        "[[body]]", 'name = "part"', f'mesh = "{ROOT / mesh}"', f'units = "{units}"',
        f"rotation_deg = [{', '.join(f'{d:g}' for d in ORIENTATIONS[case['orientation']])}]",
        f"translation_m = [{', '.join(f'{round(t, 9) + 0.0:.9g}' for t in translation)}]",
        f"friction = {case['mu']:g}",
    ]
    if contact_line:
        lines.append(contact_line)
    if case["mode"] == "punch":
        lines += ["", "[body.path]", f"translation_m = [0.0, 0.0, {travel:g}]", f"steps = {STEPS}",
                  "", "[clamp]", "width_m = 0.015", "force_N = 40.0", "friction = 0.3"]
    else:
        table = case["scene"].with_name(f"table_{case['name']}.obj")
        table.write_text(table_obj(width + 2 * MARGIN_M, height + 2 * MARGIN_M, -TABLE_GAP_M))
        lines += ["", "[[body]]", 'name = "table"', f'mesh = "{table}"', 'units = "m"', f"friction = {case['mu']:g}",
                  "", "[[constraint]]", 'nodes = "perimeter"', 'axes = "xyz"',
                  "", "[pressure]", f"pressure_Pa = {VACUUM_PA:g}",
                  "", "[initial]", 'shape = "lift"', f"height_m = {top + CLEARANCE_M:.4f}"]
    lines += ["", "[solver]", 'name = "newton"', f"tolerance_N = {TOLERANCE_N:g}",
              f"max_iterations = {MAX_ITERATIONS}", ""]
    return "\n".join(lines)


def table_obj(width: float, height: float, top: float) -> str:
    """The vacuum table: a slab TABLE_THICKNESS_M thick, centred on the z axis, its top at `top`."""
    xs, ys, zs = (-width / 2, width / 2), (-height / 2, height / 2), (top - TABLE_THICKNESS_M, top)
    vertices = [(x, y, z) for z in zs for y in ys for x in xs]   # 1..4 bottom, 5..8 top
    faces = [(1, 3, 4), (1, 4, 2), (5, 6, 8), (5, 8, 7), (1, 2, 6), (1, 6, 5),
             (2, 4, 8), (2, 8, 6), (4, 3, 7), (4, 7, 8), (3, 1, 5), (3, 5, 7)]
    return generated_mesh.obj_text("vacuum table (tools/bench_cad_contact.py)", vertices, faces)


RUNNING = set()
RUNNING_LOCK = threading.Lock()


def run_case(case: dict, out: pathlib.Path, timeout: float) -> dict:
    """Runs one case; returns what the tables need."""
    folder = out / "runs" / case["name"]
    command = [str(FABFORM), "run", str(case["scene"]), "--out", str(folder), "--quiet"]
    for _ in range(60):              # a rebuild may briefly remove the binary: wait up to 5 minutes
        if FABFORM.exists():
            break
        time.sleep(5)
    start = time.monotonic()
    try:
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    except OSError as e:
        return dict(case, scene=str(case["scene"]), bbox=None, status=None, wall=0.0, clean=False, ran=False,
                    termination="could not start", message=str(e))
    with RUNNING_LOCK:
        RUNNING.add(process)
    timed_out = False
    try:
        _, stderr = process.communicate(timeout=timeout if timeout > 0 else None)
    except subprocess.TimeoutExpired:
        timed_out = True
        process.terminate()          # fabform stops at the end of its iteration and writes
        _, stderr = process.communicate()
    finally:
        with RUNNING_LOCK:
            RUNNING.discard(process)
    row = dict(case, scene=str(case["scene"]), bbox=None, status=process.returncode,
               wall=time.monotonic() - start, clean=False, ran=True)
    result_file = folder / "result.json"
    if timed_out and not result_file.exists():
        row.update(termination="timeout", message=f"stopped after {timeout:g} s, nothing written")
        return row
    if process.returncode not in (0, 3, 4) and not timed_out or not result_file.exists():
        lines = [x for x in stderr.strip().splitlines() if x.strip()]
        row.update(ran=False, termination="refused" if process.returncode == 2 else f"exit {process.returncode}",
                   message=lines[-1] if lines else "")
        return row
    result = json.loads(result_file.read_text())
    steps = result.get("steps")
    every_step = result.get("converged") is True and (
        steps is None or (len(steps) == result.get("load_steps", -1) and all(s.get("converged") for s in steps)))
    residual = result.get("residual_N")
    cut = (result.get("figures") or {}).get("deepest_spring_cut_m")
    row.update(termination="timeout" if timed_out else result.get("termination"),
               message=result.get("message", ""), converged=every_step,
               iterations=result.get("iterations"), solve_seconds=result.get("solve_seconds"),
               residual_N=residual, deepest_cut_m=cut,
               steps_done=len(steps) if steps is not None else None,
               cuts=sum(s.get("cuts", 0) for s in steps) if steps is not None else None)
    row["clean"] = bool(every_step and not timed_out and residual is not None and residual <= TOLERANCE_N
                        and cut is not None and cut <= MAX_CUT_M)
    return row


def cells(row: dict) -> str:
    def num(x, fmt):
        return "–" if x is None else format(x, fmt)
    cut = row.get("deepest_cut_m")
    termination = row["termination"] if row["ran"] else f"{row['termination']}: {row['message']}"
    if row.get("cuts"):
        termination += f" ({row['cuts']} step cuts)"   # load steps fabform halved to get through
    return (f"| {row['part']} | {row['mode']} | {row['res']} | {row['orientation']} | {row['mu']:g} | "
            f"{row['variant']} | {'yes' if row['clean'] else 'no'} | {termination} | "
            f"{num(row.get('iterations'), 'd')} | {num(row.get('solve_seconds'), '.2f')} | "
            f"{'–' if cut is None else format(1000 * cut, '.3f')} |")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--variants", default="nodes,wrap,edges,springs",
                        help="contact variants (default nodes,wrap,edges,springs)")
    parser.add_argument("--parts", default=",".join(PARTS), help=f"parts (default {','.join(PARTS)})")
    parser.add_argument("--modes", default=",".join(MODES), help="punch, die or both (default)")
    parser.add_argument("--quick", action="store_true", help="one resolution (40), the part as is only")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "results" / "bench_cad_contact")
    parser.add_argument("--jobs", type=int, default=2, help="cases run at once (default 2)")
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds a case may run (0: no limit)")
    parser.add_argument("--wrap-deg", type=float, default=30.0, help="wrap_edges_deg of the wrap variant (30)")
    parser.add_argument("--edge-deg", type=float, default=2.0, help="edge_contact_deg of the edges variant (2)")
    parser.add_argument("--target", default="springs", help="the variant the target is about (default springs)")
    args = parser.parse_args()

    def listed(text, known, what):
        items = [x.strip() for x in text.split(",") if x.strip()]
        bad = [x for x in items if x not in known]
        if bad or not items or len(set(items)) != len(items):
            raise ValueError(f"--{what}: {text!r}: one or more of {', '.join(known)}, comma-separated, each once")
        return items
    try:
        variants = listed(args.variants, VARIANTS, "variants")
        parts = listed(args.parts, PARTS, "parts")
        modes = listed(args.modes, MODES, "modes")
        if args.target not in VARIANTS:
            raise ValueError(f"--target: {args.target!r}: one of {', '.join(VARIANTS)}")
        if args.jobs < 1 or args.timeout < 0 or not 0 <= args.wrap_deg < 180 or not 0 < args.edge_deg < 180:
            raise ValueError("--jobs must be at least 1, --timeout 0 or more, --wrap-deg in [0, 180), --edge-deg in (0, 180)")
        if not FABFORM.exists():
            raise ValueError(f"{FABFORM} not found: build it first (tools/setup.sh)")
        points = {p: read_stl(ROOT / PARTS[p][0]) for p in parts}
    except (ValueError, OSError) as e:
        print(f"bench_cad_contact.py: {e}", file=sys.stderr)
        return 2
    resolutions = RESOLUTIONS[:1] if args.quick else RESOLUTIONS
    orientations = ["asis"] if args.quick else list(ORIENTATIONS)
    contact_line = {"nodes": "", "wrap": f"wrap_edges_deg = {args.wrap_deg:g}",
                    "edges": f"edge_contact_deg = {args.edge_deg:g}", "springs": "spring_contact = true"}

    (args.out / "scenes").mkdir(parents=True, exist_ok=True)
    cases = []
    for part in parts:
        scale = UNITS[PARTS[part][1]]
        for orientation in orientations:
            placed = rotate([(x * scale, y * scale, z * scale) for x, y, z in points[part]], ORIENTATIONS[orientation])
            bbox = bounding_box(placed)
            for mode in modes:
                for res in resolutions:
                    for mu in FRICTIONS:
                        for variant in variants:   # a case's variants one after another: fair ratios
                            name = f"{part}_{mode}_n{res}_{orientation}_mu{mu:g}_{variant}"
                            case = dict(name=name, part=part, mode=mode, res=res, orientation=orientation,
                                        mu=mu, variant=variant, bbox=bbox)
                            case["scene"] = args.out / "scenes" / f"{name}.toml"
                            case["scene"].write_text(scene_text(case, contact_line[variant]))
                            cases.append(case)
    print(f"bench_cad_contact.py: {len(cases)} cases, {args.jobs} at a time, into {args.out}", file=sys.stderr)

    rows = [None] * len(cases)
    started = time.monotonic()
    binary = FABFORM.stat().st_mtime
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs)
    try:
        futures = {pool.submit(run_case, case, args.out, args.timeout): k for k, case in enumerate(cases)}
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            row = future.result()
            rows[futures[future]] = row
            print(f"  [{done}/{len(cases)}] {row['name']}: {'clean' if row['clean'] else 'not clean'} "
                  f"({row['termination']}, {row['wall']:.1f} s)", file=sys.stderr)
    except KeyboardInterrupt:
        pool.shutdown(wait=False, cancel_futures=True)
        with RUNNING_LOCK:
            for process in RUNNING:
                process.terminate()
        print("bench_cad_contact.py: interrupted", file=sys.stderr)
        return 130
    pool.shutdown()
    elapsed = time.monotonic() - started

    print(f"| part | mode | res | orientation | μ | variant | clean | termination | iterations | "
          f"solve s | deepest cut mm |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        print(cells(row))

    nodes = {(r["part"], r["mode"], r["res"], r["orientation"], r["mu"]): r
             for r in rows if r["variant"] == "nodes" and r["ran"]}
    summary = {}
    print()
    print("| variant | cases | clean | median iterations | median time ratio to nodes (pairs) |")
    print("|---|---|---|---|---|")
    for variant in variants:
        mine = [r for r in rows if r["variant"] == variant]
        clean = sum(r["clean"] for r in mine)
        iterations = [r["iterations"] for r in mine if r.get("iterations") is not None]
        ratios = []
        for r in mine:
            reference = nodes.get((r["part"], r["mode"], r["res"], r["orientation"], r["mu"]))
            if (r["ran"] and reference and reference.get("converged") and reference["solve_seconds"]
                    and r.get("solve_seconds") is not None):
                ratios.append(r["solve_seconds"] / reference["solve_seconds"])
        ratio = statistics.median(ratios) if ratios else None
        summary[variant] = dict(cases=len(mine), clean=clean, fraction_clean=clean / len(mine),
                                median_iterations=statistics.median(iterations) if iterations else None,
                                median_time_ratio=ratio, ratio_pairs=len(ratios))
        print(f"| {variant} | {len(mine)} | {clean}/{len(mine)} ({100 * clean / len(mine):.0f} %) | "
              f"{'–' if not iterations else format(statistics.median(iterations), 'g')} | "
              f"{'–' if ratio is None else format(ratio, '.2f')} ({len(ratios)}) |")
    walls = [r["wall"] for r in rows]
    print(f"\n{len(rows)} cases in {elapsed:.0f} s with --jobs {args.jobs}; a case took {statistics.median(walls):.1f} s "
          f"(median wall, {min(walls):.1f} to {max(walls):.1f} s)")

    if not FABFORM.exists() or FABFORM.stat().st_mtime != binary:
        print(f"warning: {FABFORM} changed during the sweep: the cases may have run on two builds", file=sys.stderr)
    failed = [r for r in rows if not r["ran"]]
    target = summary.get(args.target)
    if target is None:
        verdict, met = f"not measured ({args.target} not among --variants)", False
    elif target["median_time_ratio"] is None:
        verdict = (f"{target['clean']}/{target['cases']} clean, no time ratio "
                   f"({'nodes not among --variants' if 'nodes' not in variants else 'no case where nodes converged'}): NOT met")
        met = False
    else:
        met = target["clean"] == target["cases"] and target["median_time_ratio"] <= TARGET_RATIO
        verdict = (f"{target['clean']}/{target['cases']} clean, median time ratio {target['median_time_ratio']:.2f}: "
                   f"{'met' if met else 'NOT met'}")
    print(f"target: {args.target} 100 % clean and median time ratio to nodes <= {TARGET_RATIO:g}: {verdict}")
    (args.out / "summary.json").write_text(json.dumps(
        dict(cases=[{k: (str(v) if isinstance(v, pathlib.Path) else v) for k, v in r.items() if k != "bbox"} for r in rows],
             variants=summary, target=args.target, target_met=met, seconds=elapsed, jobs=args.jobs), indent=1) + "\n")
    if failed:
        print(f"bench_cad_contact.py: {len(failed)} case(s) refused or failed to run, first: {failed[0]['name']}: "
              f"{failed[0]['message']}", file=sys.stderr)
        return 2
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
