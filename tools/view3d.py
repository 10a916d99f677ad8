"""The interactive 3-D view of a run, for report.html: RUN_DIR/view3d/ with the formed fabric and
the bodies as binary buffers (data.js), three.js and its orbit controls, and the viewer
(tools/view3d/viewer.js), all opened from file:// with nothing loaded from a URL.

Why: a forming engineer turns the part to see its far side, zooms into the shoulder, reads the
strain at a point and plays the load steps; the report's pictures are one viewpoint each.

What it holds: one frame a load step (fabric_step_NNN.vtp with bodies_step_NNN.vtp; the last
step carries the final state's per-cell fields when fabric.vtk is that state), or the final
state alone (fabric.vtk, bodies.vtk); per node every field the VTK files carry, the contact
pressure also in mmHg; per cell the final state's fields; the bodies' contact pressure. Numbers
are little-endian float32 (positions, fields) and uint32 (triangles), base64 in one script so
that file:// needs no fetch. Each field's colours span the same range in every frame.
three.js is Debian's libjs-three (r111, MIT), copied from /usr/share/javascript/three with its
licence.

Imported by tools/report.py (write_view). numpy and the standard library only.
"""
import base64
import json
import pathlib
import shutil
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import numpy as np  # noqa: E402
import plot_convergence as pc  # noqa: E402  (InputError, write_text)
import vtk_files  # noqa: E402

THREE_DIR = pathlib.Path("/usr/share/javascript/three")
THREE_FILES = {"three.min.js": THREE_DIR / "three.min.js",
               "OrbitControls.js": THREE_DIR / "examples" / "js" / "controls" / "OrbitControls.js",
               "three-copyright.txt": pathlib.Path("/usr/share/doc/libjs-three/copyright")}
VIEWER = pathlib.Path(__file__).resolve().parent / "view3d" / "viewer.js"
MMHG_PA = 133.322387415  # 1 mmHg in Pa (contact_pressure.hpp)
# The colours span a field from its 0.5th to its 99.5th percentile over every frame: a few nodes'
# peaks (the pressure at a punch's rim) would leave the rest of the fabric one colour.
COLOUR_PERCENTILES = (0.5, 99.5)
# name: (what it is, unit shown, factor from the file's SI value to that unit)
FIELDS = {
    "strain_warp": ("warp strain", "%", 100.0),
    "strain_weft": ("weft strain", "%", 100.0),
    "shear_angle_deg": ("shear angle", "°", 1.0),
    "thickness_ratio": ("thickness ratio h/h₀ (1: as flat)", "", 1.0),
    "wrinkle_risk": ("wrinkle risk (1: locked or compressed both ways)", "", 1.0),
    "contact_pressure_Pa": ("contact pressure on the fabric", "Pa", 1.0),
    "contact_pressure_mmHg": ("contact pressure on the fabric", "mmHg", 1.0),
    "draw_in_m": ("draw-in", "mm", 1000.0),
    "contact": ("on a body (1: yes)", "", 1.0),
    "residual_N": ("residual force", "N", 1.0),
    "body_contact_pressure_Pa": ("contact pressure on the bodies", "Pa", 1.0),
    "body_contact_pressure_mmHg": ("contact pressure on the bodies", "mmHg", 1.0),
}


def packed(values, kind) -> str:
    return base64.b64encode(np.ascontiguousarray(values, dtype=kind).tobytes()).decode("ascii")


def triangles(polygons: list) -> tuple:
    """(corner indices (t, 3), each triangle's polygon): a polygon fanned from its corner 0, as
    fabform splits a four-sided face."""
    corners, owner = [], []
    for index, polygon in enumerate(polygons):
        for k in range(1, len(polygon) - 1):
            corners.append((polygon[0], polygon[k], polygon[k + 1]))
            owner.append(index)
    return np.array(corners, dtype=np.uint32).reshape(-1, 3), np.array(owner, dtype=np.uint32)


def with_mmhg(fields: dict, prefix: str = "") -> dict:
    out = {prefix + name: values for name, values in fields.items()}
    if prefix + "contact_pressure_Pa" in out:
        out[prefix + "contact_pressure_mmHg"] = out[prefix + "contact_pressure_Pa"] / MMHG_PA
    return out


def read_frames(run: pathlib.Path, result: dict) -> tuple:
    """(fabric polygons, body polygons, frames): a frame a load step, else the final state."""
    final = vtk_files.read_legacy(run / "fabric.vtk")
    bodies = vtk_files.read_legacy(run / "bodies.vtk") if (run / "bodies.vtk").is_file() else None
    body_fields = with_mmhg(bodies.point_fields, "body_") if bodies else {}
    frames = []
    for step in result.get("steps") or []:
        fabric = vtk_files.read_xml(run / step["fabric_file"])
        if len(fabric.points) != len(final.points):
            raise pc.InputError(f"{run / step['fabric_file']}: {len(fabric.points)} points, not the "
                                f"{len(final.points)} of fabric.vtk")
        posed = vtk_files.read_xml(run / step["bodies_file"]).points if bodies else None
        frames.append({"label": f"load step {step['step']} of {len(result['steps'])}", "points": fabric.points,
                       "node": with_mmhg(fabric.point_fields), "cell": {}, "bodies": posed, "body": {}})
    if frames and np.allclose(frames[-1]["points"], final.points, rtol=0.0, atol=1e-9):
        frames[-1].update(cell=final.cell_fields, body=body_fields)
    else:
        frames.append({"label": "final state", "points": final.points, "node": with_mmhg(final.point_fields),
                       "cell": final.cell_fields, "bodies": bodies.points if bodies else None, "body": body_fields})
    return final.polygons, bodies.polygons if bodies else [], frames


def field_list(frames: list) -> list:
    """Every field of any frame, in FIELDS' order then the others, with its range over the frames
    and the range its colours span (COLOUR_PERCENTILES)."""
    where = {}
    for frame in frames:
        for kind in ("node", "cell", "body"):
            for name in frame[kind]:
                where.setdefault(name, kind)
    names = [n for n in FIELDS if n in where] + sorted(n for n in where if n not in FIELDS)
    listed = []
    for name in names:
        values = [frame[where[name]][name] for frame in frames if name in frame[where[name]]]
        finite = np.concatenate([v[np.isfinite(v)] for v in values])
        what, unit, factor = FIELDS.get(name, (name, "", 1.0))
        low, high = np.percentile(finite, COLOUR_PERCENTILES) if finite.size else (0.0, 0.0)
        listed.append({"name": name, "where": where[name], "label": what, "unit": unit, "factor": factor,
                       "min": float(finite.min()) if finite.size else 0.0,
                       "max": float(finite.max()) if finite.size else 0.0, "low": float(low), "high": float(high)})
    return listed


def view_data(run: pathlib.Path, result: dict) -> str:
    """data.js: window.FABFORM_VIEW, the frames' numbers as base64 buffers."""
    fabric_polygons, body_polygons, frames = read_frames(run, result)
    fabric_triangles, cell_of = triangles(fabric_polygons)
    view = {"scene": result.get("scene", ""), "nodes": len(frames[0]["points"]),
            "triangles": packed(fabric_triangles, "<u4"), "triangle_cell": packed(cell_of, "<u4"),
            "body_triangles": packed(triangles(body_polygons)[0], "<u4"), "fields": field_list(frames), "frames": []}
    for frame in frames:
        buffers = {"points": packed(frame["points"], "<f4")}
        if frame["bodies"] is not None:
            buffers["bodies"] = packed(frame["bodies"], "<f4")
        view["frames"].append({"label": frame["label"], "buffers": buffers,
                               "fields": {name: packed(v, "<f4") for kind in ("node", "cell", "body")
                                          for name, v in frame[kind].items()}})
    return "window.FABFORM_VIEW = " + json.dumps(view, ensure_ascii=False) + ";\n"


def write_view(run: pathlib.Path, result: dict) -> str:
    """Writes RUN_DIR/view3d/ and returns the report's HTML for the view."""
    for name, source in THREE_FILES.items():
        if not source.is_file():
            raise pc.InputError(f"{source}: no such file (Debian's libjs-three: tools/setup.sh installs it)")
    folder = run / "view3d"
    folder.mkdir(exist_ok=True)
    for name, source in [*THREE_FILES.items(), ("viewer.js", VIEWER)]:
        shutil.copyfile(source, folder / (name + ".tmp"))
        (folder / (name + ".tmp")).replace(folder / name)
    pc.write_text(folder / "data.js", view_data(run, result))
    return VIEW_HTML


VIEW_HTML = """<h2>3-D view</h2>
<div id="view3d" class="view3d" data-state="loading">
<div class="view3d-bar">
<label>field <select id="view3d-field"></select></label>
<span id="view3d-steps"><label>frame <input id="view3d-step" type="range" min="0" max="0" value="0"></label>
<button id="view3d-play" type="button">play</button></span>
<span id="view3d-frame"></span>
</div>
<div id="view3d-canvas" class="view3d-canvas"><p id="view3d-message" class="view3d-message">The 3-D view
needs JavaScript and WebGL; the pictures below show the same results.</p></div>
<div id="view3d-legend" class="view3d-legend"></div>
<div id="view3d-pick" class="view3d-pick">Drag to turn, scroll to zoom, right-drag to pan; click the fabric
to read a node.</div>
</div>
<script src="view3d/three.min.js"></script>
<script src="view3d/OrbitControls.js"></script>
<script src="view3d/data.js"></script>
<script src="view3d/viewer.js"></script>
"""

VIEW_CSS = """
.view3d { border: 1px solid #ccc; padding: 0.5em; margin-bottom: 1.5em; max-width: 60em; }
.view3d-canvas { width: 100%; height: 34em; position: relative; background: #f4f4f4; }
.view3d-message { padding: 2em; color: #a00; }
.view3d-bar { margin-bottom: 0.4em; } .view3d-bar > * { margin-right: 1.2em; }
.view3d-legend { margin: 0.4em 0; } .view3d-pick { font-size: 0.9em; }
.view3d-pick table { margin: 0.3em 0; } .view3d-pick td, .view3d-pick th { padding: 0.1em 0.6em; }
"""
