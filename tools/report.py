#!/usr/bin/python3
"""The report of a run, for engineers: RUN_DIR/report.html with the summary, the strain maps
(the formed fabric over the bodies, coloured by warp and by weft strain, with a colour bar),
the forming maps (shear angle, thickness ratio and wrinkle risk per cell, the draw-in round the
blank's edge, the contact pressure on the bodies in Pa and mmHg), the area-weighted strain histogram, the convergence plot, for a run in load steps each step's
figures (a table, and strain and draw-in against the tool's travel), what was modelled, the
warnings and the inputs with their SHA-256. It opens in a browser from the folder, without a
server.

Why: an engineer judges a fit by looking at it. The pictures are rendered headless with
matplotlib (Agg), the fabric from fabric.obj and fabric.vtk, the bodies from bodies.obj.
A run that did not converge says so at the top of the report and in its plot's title.

Usage: /usr/bin/python3 tools/report.py RUN_DIR
Writes into RUN_DIR: report.html, strain_warp.png, strain_weft.png, shear_angle.png,
thickness_ratio.png, wrinkle_risk.png, draw_in.png, contact_pressure.png (with bodies),
strain_histogram.png, convergence.png and convergence.svg (and steps.png for a run in load steps), each under a
temporary name first, then renamed.
Exits 2 with one line naming the file when an input is missing or malformed.
"""
import html
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import numpy as np  # noqa: E402
import plot_convergence as pc  # noqa: E402  (shared reader, plot and InputError)
import raster  # noqa: E402
import view3d  # noqa: E402
import vtk_files  # noqa: E402

VIEW = {"elevation_deg": 35, "azimuth_deg": -60}


def read_obj(path: pathlib.Path) -> tuple:
    """(vertices, faces) of an OBJ fabform wrote; faces as 0-based index lists."""
    if not path.is_file():
        raise pc.InputError(f"{path}: no such file")
    vertices, faces = [], []
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        words = line.split()
        try:
            if words and words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words and words[0] == "f":
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
        except ValueError:
            raise pc.InputError(f"{path}:{number}: not a number")
    if any(i < 0 or i >= len(vertices) for face in faces for i in face):
        raise pc.InputError(f"{path}: a face refers to a vertex it does not have")
    return vertices, faces


def save_figure(fig, path: pathlib.Path) -> pathlib.Path:
    temporary = path.with_name(path.name + ".tmp")
    fig.savefig(temporary, format=path.suffix[1:], dpi=110)
    temporary.replace(path)
    return path


def triangles_near(vertices, faces, box) -> np.ndarray:
    """The body triangles near the fabric (within its box grown by half its size), (n, 3, 3)."""
    if not faces:
        return np.zeros((0, 3, 3))
    corners = np.asarray(vertices)[np.asarray([f[:3] for f in faces])]
    lo, hi = box
    grow = 0.5 * (hi - lo)
    near = np.all((corners.max(axis=1) >= lo - grow) & (corners.min(axis=1) <= hi + grow), axis=1)
    return corners[near]


def colour_bar(fig, ax, norm, cmap, label: str):
    from matplotlib import cm
    bar = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.7)
    bar.set_label(label)
    return bar


def finite_norm(values: np.ndarray):
    from matplotlib import colors
    finite = values[np.isfinite(values)]
    lo, hi = (finite.min(), finite.max()) if finite.size else (0.0, 1.0)
    return colors.Normalize(vmin=lo, vmax=max(hi, lo + 1e-9))


def fabric_map(run: pathlib.Path, fabric, values, bodies, name: str, label: str, title: str,
               per_cell: bool = False, cmap_name: str = "viridis") -> pathlib.Path:
    """The formed fabric over the bodies, coloured by a field per node (interpolated) or per cell,
    z-buffered (tools/raster.py)."""
    plt = pc.pyplot()
    vertices, quads = np.asarray(fabric[0]), np.asarray(fabric[1])
    values = np.asarray(values, dtype=float)
    split = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])  # each cell as two triangles
    cloth = vertices[split]
    box = (vertices.min(axis=0), vertices.max(axis=0))
    body = triangles_near(*bodies, box) if bodies else np.zeros((0, 3, 3))
    every = np.concatenate([cloth, body])
    view = raster.camera(**VIEW)
    frame = raster.Frame(every.reshape(-1, 3), view, width=900)
    # A cell resting on a body is a chord under its facets: within half a cell of the body's
    # surface the fabric is drawn over it.
    cell = np.linalg.norm(cloth[:, 0] - cloth[:, 2], axis=1).max()
    nearer_by = np.concatenate([np.full(len(cloth), 0.5 * cell), np.zeros(len(body))])
    owner, weights = raster.rasterise(frame, every, nearer_by)
    light = view[2] + 0.5 * view[1] - 0.3 * view[0]
    shading = raster.lambert(every, light / np.linalg.norm(light))
    norm = finite_norm(values)
    cmap = plt.get_cmap(cmap_name)
    image = np.ones(owner.shape + (3,))
    on_cloth = (owner >= 0) & (owner < len(cloth))
    t = owner[on_cloth]
    value = values[t % len(quads)] if per_cell else np.sum(weights[on_cloth] * values[split[t]], axis=1)
    image[on_cloth] = cmap(norm(value))[:, :3] * shading[t, None]
    on_body = owner >= len(cloth)
    image[on_body] = 0.85 * shading[owner[on_body], None]
    fig, ax = plt.subplots(figsize=(7.6, 7.6 * frame.height / frame.width + 0.6))
    ax.imshow(image, interpolation="antialiased")
    ax.set_axis_off()
    colour_bar(fig, ax, norm, cmap, label)
    ax.set_title(f"{title} (grey: the bodies)", fontsize=10)
    fig.tight_layout()
    path = save_figure(fig, run / f"{name}.png")
    plt.close(fig)
    return path


def strain_map(run: pathlib.Path, fabric, strains, bodies, direction: str) -> pathlib.Path:
    return fabric_map(run, fabric, strains, bodies, f"strain_{direction}", f"{direction} strain",
                      f"{direction} strain of the formed fabric")


MMHG_PA = 133.322387415  # 1 mmHg in Pa (contact_pressure.hpp)


def pressure_map(run: pathlib.Path, fabric, bodies, pressure) -> pathlib.Path:
    """The bodies under the fabric, seen from the report's view without the fabric, coloured by
    the contact pressure on each vertex (bodies.vtk), in Pa and mmHg."""
    plt = pc.pyplot()
    vertices, faces = np.asarray(bodies[0]), np.asarray([f[:3] for f in bodies[1]])
    values = np.asarray(pressure, dtype=float)
    cloth = np.asarray(fabric[0])
    lo, hi = cloth.min(axis=0), cloth.max(axis=0)
    grow = 0.5 * (hi - lo)
    corners = vertices[faces]
    near = np.all((corners.max(axis=1) >= lo - grow) & (corners.min(axis=1) <= hi + grow), axis=1)
    faces, corners = faces[near], corners[near]
    view = raster.camera(**VIEW)
    frame = raster.Frame(corners.reshape(-1, 3), view, width=900)
    owner, weights = raster.rasterise(frame, corners)
    light = view[2] + 0.5 * view[1] - 0.3 * view[0]
    shading = raster.lambert(corners, light / np.linalg.norm(light))
    norm = finite_norm(values[np.unique(faces)] if faces.size else values)
    cmap = plt.get_cmap("inferno")
    image = np.ones(owner.shape + (3,))
    seen = owner >= 0
    t = owner[seen]
    image[seen] = cmap(norm(np.sum(weights[seen] * values[faces[t]], axis=1)))[:, :3] * (0.4 + 0.6 * shading[t, None])
    fig, ax = plt.subplots(figsize=(7.6, 7.6 * frame.height / frame.width + 0.6))
    ax.imshow(image, interpolation="antialiased")
    ax.set_axis_off()
    bar = colour_bar(fig, ax, norm, cmap, "contact pressure (Pa)")
    mmhg = bar.ax.secondary_yaxis("left", functions=(lambda p: p / MMHG_PA, lambda m: m * MMHG_PA))
    mmhg.set_ylabel("mmHg")
    ax.set_title("contact pressure of the fabric on the bodies (fabric hidden)", fontsize=10)
    fig.tight_layout()
    path = save_figure(fig, run / "contact_pressure.png")
    plt.close(fig)
    return path


def edge_nodes(faces) -> list:
    """The nodes on the fabric's edge: on a side only one face has."""
    count = {}
    for f in faces:
        for a, b in zip(f, f[1:] + f[:1]):
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    return sorted({i for key, n in count.items() if n == 1 for i in key})


def draw_in_map(run: pathlib.Path, fabric, blank, draw_in) -> pathlib.Path:
    """Seen from above: the flat blank's outline, its edge nodes coloured by how far they drew
    in (mm), and the formed fabric's outline."""
    plt = pc.pyplot()
    flat, formed = np.asarray(blank[0]), np.asarray(fabric[0])
    edge = edge_nodes(fabric[1])
    values = 1000.0 * np.asarray(draw_in, dtype=float)[edge]
    norm = finite_norm(values)
    cmap = plt.get_cmap("coolwarm")
    fig, ax = plt.subplots(figsize=(7.0, 6.2))
    ax.scatter(1000.0 * formed[edge, 0], 1000.0 * formed[edge, 1], s=4, c="0.6", label="formed edge (top view)")
    ax.scatter(1000.0 * flat[edge, 0], 1000.0 * flat[edge, 1], s=18, c=values, cmap=cmap, norm=norm,
               label="flat blank's edge")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.legend(loc="upper right", fontsize=8)
    colour_bar(fig, ax, norm, cmap, "draw-in (mm, inwards)")
    ax.set_title("draw-in round the blank's edge", fontsize=10)
    fig.tight_layout()
    path = save_figure(fig, run / "draw_in.png")
    plt.close(fig)
    return path


def histogram_picture(run: pathlib.Path, histogram: dict) -> pathlib.Path:
    plt = pc.pyplot()
    edges = histogram["strain_edges"]
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    width = (edges[1] - edges[0]) * 100 if len(edges) > 1 else 1.0
    left = [e * 100 for e in edges[:-1]]
    ax.bar([x + 0.25 * width for x in left], [a * 1e4 for a in histogram["warp_area_m2"]],
           width=0.45 * width, align="edge", label="warp")
    ax.bar([x + 0.5 * width for x in left], [a * 1e4 for a in histogram["weft_area_m2"]],
           width=0.45 * width, align="edge", label="weft")
    ax.set_xlabel("strain (%)")
    ax.set_ylabel("fabric area (cm²)")
    ax.set_title("area-weighted strain histogram", fontsize=10)
    ax.legend()
    ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    path = save_figure(fig, run / "strain_histogram.png")
    plt.close(fig)
    return path


def travel_mm(step: dict) -> float:
    """How far the first travelling body has moved after a step (mm)."""
    travel = step.get("travel") or [{"translation_m": [0.0, 0.0, 0.0]}]
    return 1000.0 * math.sqrt(sum(c * c for c in travel[0]["translation_m"]))


def steps_picture(run: pathlib.Path, steps: list) -> pathlib.Path:
    """The largest strains and the draw-in against the tool's travel, step by step."""
    plt = pc.pyplot()
    fig, strain_axis = plt.subplots(figsize=(6.4, 4.0))
    travel = [travel_mm(s) for s in steps]
    for key, label, style in (("max_warp_strain", "largest warp strain", "o-"),
                              ("max_weft_strain", "largest weft strain", "s-")):
        strain_axis.plot(travel, [100.0 * (s[key] or 0.0) for s in steps], style, label=label)
    strain_axis.set_xlabel("tool travel (mm)")
    strain_axis.set_ylabel("strain (%)")
    draw_axis = strain_axis.twinx()
    draw_axis.plot(travel, [1000.0 * (s["draw_in_max_m"] or 0.0) for s in steps], "k^--", label="largest draw-in")
    draw_axis.set_ylabel("draw-in (mm)")
    lines = strain_axis.get_legend_handles_labels()
    more = draw_axis.get_legend_handles_labels()
    strain_axis.legend(lines[0] + more[0], lines[1] + more[1], loc="upper left")
    strain_axis.set_title("load steps: strain and draw-in as the tool travels")
    fig.tight_layout()
    path = save_figure(fig, run / "steps.png")
    plt.close(fig)
    return path


def steps_table(steps: list) -> str:
    e = html.escape
    head = ("step", "travel (mm)", "iterations", "‖V‖∞ (N)", "contact nodes", "largest warp strain (%)",
            "largest weft strain (%)", "largest draw-in (mm)", "file")
    rows = "".join(
        "<tr>" + "".join(f"<td>{e(str(v))}</td>" for v in (
            s["step"], number(travel_mm(s), 4), s["iterations"], number(s["residual_N"], 3), s["contact_nodes"],
            number(100.0 * s["max_warp_strain"], 3) if s["max_warp_strain"] is not None else "—",
            number(100.0 * s["max_weft_strain"], 3) if s["max_weft_strain"] is not None else "—",
            number(1000.0 * s["draw_in_max_m"], 3) if s["draw_in_max_m"] is not None else "—",
            s["fabric_file"])) + "</tr>" for s in steps)
    return "<table><tr>" + "".join(f"<th>{e(h)}</th>" for h in head) + f"</tr>{rows}</table>"


def number(value, digits=4) -> str:
    return "—" if value is None else f"{value:.{digits}g}"


def peak_text(peak: dict) -> str:
    i, j = peak["spring_from_node"]
    x, y, z = (number(c * 1000, 4) for c in peak["at_m"])
    return f"{number(peak['strain'] * 100, 3)} % at node ({i}, {j}), ({x}, {y}, {z}) mm"


def position_error_text(result: dict) -> str:
    """The estimate of the largest node distance from the exact rest, how it was made, and the
    distance tolerance when the run had one."""
    how = {"newton_step": "the next Newton step",
           "convergence_rate": "the last move and the rate ‖V‖∞ falls at (the moves still to come)"}
    text = (f"{number(result.get('position_error_m'))} m, estimated from "
            f"{how.get(result.get('position_error_estimate'), 'an unknown estimate')}")
    if result.get("tolerance_m") is not None:
        text += f" (tolerance {number(result['tolerance_m'])} m"
        text += f"; stopped on {result['converged_on']})" if result.get("converged_on") else ")"
    return text


def summary_rows(result: dict) -> list:
    f = result.get("figures", {})
    flat, formed = f.get("area_flat_m2"), f.get("area_formed_m2")
    rows = [
        ("termination", f"{result['termination']}: {result['message']}"),
        ("solver", f"{result['solver']} on {result.get('threads', 1)} thread(s)"),
        ("iterations", result["iterations"]),
        ("residual ‖V‖∞", f"{number(result['residual_N'])} N (tolerance {number(result['tolerance_N'])} N; "
                          f"recomputed from positions {number(result['residual_recomputed_N'])} N)"),
        ("distance from the rest", position_error_text(result)),
        ("time", f"{number(result['wall_seconds'], 3)} s in all, {number(result['solve_seconds'], 3)} s solving"),
        ("nodes", f"{result['nodes']} ({result['grid'][0]} × {result['grid'][1]})"),
        ("contact", f"{result['contact_nodes']} nodes, {number(f.get('contact_area_m2', 0) * 1e4)} cm²"),
        ("largest penetration", f"{number(result['max_penetration_m'])} m"),
    ]
    if flat and formed:
        rows.append(("fabric area", f"{number(flat * 1e4)} cm² flat → {number(formed * 1e4)} cm² formed "
                                    f"({number((formed / flat - 1) * 100, 3)} %)"))
    if f.get("draw_in_max_m") is not None:
        rows.append(("largest draw-in", f"{number(f['draw_in_max_m'] * 1000, 3)} mm at {f.get('draw_in_max_node', '?')}"))
    if f.get("springs_cutting_bodies"):
        rows.append(("springs cutting a body", f"{f['springs_cutting_bodies']}, the deepest "
                                               f"{number(f['deepest_spring_cut_m'] * 1000, 3)} mm"))
    if f.get("springs_over_edges"):
        rows.append(("springs over a body's edges", f"{f['springs_over_edges']} (wrapped as a string over a corner)"))
    if "sliding_nodes" in f:
        rows.append(("on a body", f"{f['sliding_nodes']} nodes sliding, {f['stuck_nodes']} stuck"))
    if "load_steps" in result:
        rows.append(("load steps", f"{len(result.get('steps', []))} of {result['load_steps']} finished"))
    if f.get("shear_angle_max_deg") is not None:
        rows.append(("largest shear angle", f"{number(f['shear_angle_max_deg'], 3)}° (locking angle "
                                            f"{number(f['locking_angle_deg'], 3)}°, from the {f['locking_angle_from']})"))
    if f.get("thickness_ratio_min") is not None:
        rows.append(("smallest thickness ratio", f"{number(f['thickness_ratio_min'], 3)} of the flat fabric's"))
    if "wrinkle_cells" in f:
        rows.append(("cells at risk of wrinkling", f"{f['wrinkle_cells']} (sheared past locking or compressed both ways)"))
    if f.get("contact_pressure_max_Pa") is not None:
        rows.append(("contact pressure", f"largest {number(f['contact_pressure_max_Pa'], 4)} Pa "
                                         f"({number(f['contact_pressure_max_mmHg'], 3)} mmHg), mean "
                                         f"{number(f['contact_pressure_mean_Pa'], 4)} Pa "
                                         f"({number(f['contact_pressure_mean_mmHg'], 3)} mmHg)"))
    drape = result.get("drape")
    if drape:
        caveats = "; ".join(drape.get("caveats", []))
        rows.append(("drape coefficient", f"{number(drape['coefficient'] * 100, 4)} %, {drape['folds']} folds"
                                          + (f" — NOT a tester's reading: {caveats}" if caveats else "")))
    for direction in ("warp", "weft"):
        if f"max_{direction}_strain" in f:
            rows.append((f"largest {direction} strain", peak_text(f[f"max_{direction}_strain"])))
        if f"min_{direction}_strain" in f:
            rows.append((f"smallest {direction} strain", peak_text(f[f"min_{direction}_strain"])))
    return rows


def page(result: dict, pictures: list, view: str) -> str:
    e = html.escape
    converged = result.get("converged", False)
    banner = ("" if converged else
              f'<p class="alarm">This run did NOT converge ({e(result["termination"])}): '
              f'{e(result["message"])}. Its fabric is where the solver stopped.</p>')
    rows = "\n".join(f"<tr><th>{e(str(k))}</th><td>{e(str(v))}</td></tr>" for k, v in summary_rows(result))
    figures = "\n".join(f'<figure><img src="{e(name)}" alt="{e(caption)}"><figcaption>{e(caption)}'
                        f"</figcaption></figure>" for name, caption in pictures)
    steps = result.get("steps") or []
    steps_section = (f"<h2>Load steps</h2>{steps_table(steps)}<p>Each step's fabric and bodies are in the "
                     f"files named, and <code>fabric_steps.pvd</code> plays them in ParaView.</p>") if steps else ""
    modelled = "".join(f"<li>{e(m)}</li>" for m in result.get("modelled", []))
    warnings = "".join(f"<li>{e(w)}</li>" for w in result.get("warnings", [])) or "<li>none</li>"
    inputs = "".join(f"<tr><td>{e(i['role'])}</td><td>{e(i['path'])}</td><td><code>{e(i['sha256'])}</code></td></tr>"
                     for i in result.get("inputs", []))
    overrides = ", ".join(f"{o['key']}={o['value']}" for o in result.get("overrides", [])) or "none"
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>fabform report: {e(result['scene'])}</title>
<style>
body {{ font-family: sans-serif; margin: 2em; max-width: 70em; color: #222; }}
table {{ border-collapse: collapse; margin-bottom: 1.5em; }}
th, td {{ text-align: left; padding: 0.25em 0.8em; border-bottom: 1px solid #ddd; vertical-align: top; }}
figure {{ display: inline-block; margin: 0 1em 1em 0; }} img {{ max-width: 34em; }}
.alarm {{ background: #fdd; border: 2px solid #c00; padding: 0.6em; font-weight: bold; }}
.missing {{ color: #c00; font-weight: bold; }}
{view3d.VIEW_CSS}</style></head>
<body>
<h1>{e(result['scene'])}: {e(result['termination'])}</h1>
{banner}
<h2>Summary</h2>
<table>
{rows}
</table>
{view}
<h2>Pictures</h2>
{figures}
{steps_section}
<h2>What was modelled</h2><ul>{modelled}</ul>
<h2>Warnings</h2><ul>{warnings}</ul>
<h2>Inputs</h2>
<table><tr><th>role</th><th>file</th><th>SHA-256</th></tr>{inputs}</table>
<p>Overrides: {e(overrides)}. fabform {e(result.get('fabform_version', '?'))}.</p>
<script>
// A picture that did not load is said so in place (a report copied without its pictures).
window.addEventListener("load", () => {{
  const images = Array.from(document.images);
  const shown = images.filter(i => i.complete && i.naturalWidth > 0);
  for (const i of images.filter(i => !shown.includes(i))) {{
    const note = document.createElement("p");
    note.className = "missing";
    note.textContent = "missing picture: " + i.getAttribute("src");
    i.replaceWith(note);
  }}
  document.body.dataset.picturesShown = shown.length + "/" + images.length;
}});
</script>
</body></html>
"""


def make_report(run: pathlib.Path) -> pathlib.Path:
    result = pc.read_result(run)
    for key in ("scene", "termination", "message", "iterations", "figures"):
        if key not in result:
            raise pc.InputError(f"{run / 'result.json'}: no '{key}' (written by an older fabform?)")
    fabric = read_obj(run / "fabric.obj")
    formed = vtk_files.read_legacy(run / "fabric.vtk")
    fields = {**formed.point_fields, **formed.cell_fields}
    bodies = read_obj(run / "bodies.obj") if (run / "bodies.obj").is_file() else None
    pc.plot_run(run, run / "convergence")
    pictures = []
    for direction in ("warp", "weft"):
        name = f"strain_{direction}"
        if name not in fields:
            raise pc.InputError(f"{run / 'fabric.vtk'}: no field {name}")
        strain_map(run, fabric, fields[name], bodies, direction)
        pictures.append((f"{name}.png", f"{direction} strain over the bodies"))
    for name, label, title, cmap in (
            ("shear_angle_deg", "shear angle (°)", "shear angle per cell", "viridis"),
            ("thickness_ratio", "thickness ratio h/h₀ (1: as flat)", "thickness ratio per cell", "viridis"),
            ("wrinkle_risk", "wrinkle risk (1: locked or compressed both ways)", "wrinkle risk per cell", "Reds")):
        if name not in fields:
            raise pc.InputError(f"{run / 'fabric.vtk'}: no field {name}")
        stem = name.removesuffix("_deg")
        fabric_map(run, fabric, fields[name], bodies, stem, label, title, per_cell=True, cmap_name=cmap)
        pictures.append((f"{stem}.png", title))
    if (run / "blank.obj").is_file():  # a checkpoint's folder has no flat-formed map yet
        draw_in_map(run, fabric, read_obj(run / "blank.obj"), fields["draw_in_m"])
        pictures.append(("draw_in.png", "draw-in round the blank's edge"))
    if bodies:
        pressure = vtk_files.read_legacy(run / "bodies.vtk").point_fields
        if "contact_pressure_Pa" not in pressure:
            raise pc.InputError(f"{run / 'bodies.vtk'}: no field contact_pressure_Pa")
        pressure_map(run, fabric, bodies, pressure["contact_pressure_Pa"])
        pictures.append(("contact_pressure.png", "contact pressure on the bodies (Pa and mmHg)"))
    if result["figures"]["strain_histogram"]["strain_edges"]:
        histogram_picture(run, result["figures"]["strain_histogram"])
        pictures.append(("strain_histogram.png", "fabric area by strain"))
    pictures.append(("convergence.png", "convergence: ‖V‖∞ against iteration"))
    if result.get("steps"):
        steps_picture(run, result["steps"])
        pictures.append(("steps.png", "load steps: strain and draw-in against the tool's travel"))
    path = run / "report.html"
    pc.write_text(path, page(result, pictures, view3d.write_view(run, result)))
    return path


def report_main(argv, tool: str, folder: str, make) -> int:
    """A report tool's command line: `tools/TOOL FOLDER`; exit 2 with one line on bad input."""
    if len(argv) != 1 or argv[0].startswith("-"):
        print(f"usage: tools/{tool} {folder}", file=sys.stderr)
        return 2
    try:
        path = make(pathlib.Path(argv[0]))
    except pc.InputError as error:
        print(f"{tool}: {error}", file=sys.stderr)
        return 2
    print(f"wrote {path}")
    return 0


def main(argv) -> int:
    return report_main(argv, "report.py", "RUN_DIR", make_report)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
