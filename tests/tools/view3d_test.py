#!/usr/bin/python3
"""The report's 3-D view (tools/view3d.py, tools/view3d/viewer.js) on a real run of the cup in three
load steps: view3d/data.js holds every step's fabric and bodies as the VTK files do (read here
with Python's own XML parser and a few lines for the legacy file); in headless Chromium with
software WebGL the view opens on the field, frame and node its address asks for, picks the node
through the screen as a click does and reads back that node's position and values as the step's
file holds them; a field a frame does not have is named, not left blank; without WebGL, or
without its data, the view says so and the pictures stay.

Usage: FABFORM_BINARY=build/fabform /usr/bin/python3 tests/tools/view3d_test.py
"""
import base64
import html
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "tools"))
import numpy as np  # noqa: E402
from report_test import PICTURES, open_in_chromium  # noqa: E402

FABFORM = os.environ.get("FABFORM_BINARY", str(ROOT / "build" / "fabform"))
REPORT = [sys.executable, str(ROOT / "tools" / "report.py")]
SIDE = 17          # nodes a side of the 16 × 16 blank
FLANGE_NODE = 2 * SIDE + 10   # on the flat flange, on the side the view looks from
TOP_NODE = 8 * SIDE + 8       # the blank's centre, on the punch's top
MMHG_PA = 133.322387415
FLOAT32 = dict(rtol=2e-7, atol=1e-12)   # what a float32 keeps of a double


def step_file(path: pathlib.Path) -> dict:
    """Points and point data of a step's VTK XML file."""
    piece = ET.parse(path).getroot().find("./PolyData/Piece")
    arrays = {a.get("Name"): np.array(a.text.split(), dtype=float) for a in piece.findall("./PointData/DataArray")}
    arrays["points"] = np.array(piece.find("./Points/DataArray").text.split(), dtype=float).reshape(-1, 3)
    return arrays


def legacy_cell_field(path: pathlib.Path, name: str) -> np.ndarray:
    lines = path.read_text().splitlines()
    count = int(next(line for line in lines if line.startswith("CELL_DATA")).split()[1])
    at = lines.index(f"SCALARS {name} double 1")
    return np.array(lines[at + 2: at + 2 + count], dtype=float)


def view_data(run: pathlib.Path) -> dict:
    text = (run / "view3d" / "data.js").read_text()
    return json.loads(text.removeprefix("window.FABFORM_VIEW = ").rstrip().removesuffix(";"))


def decoded(text: str, kind: str) -> np.ndarray:
    return np.frombuffer(base64.b64decode(text), dtype=kind)


def picked(dom: str) -> tuple:
    """(the node the view's pick shows, its values) from the DOM."""
    match = re.search(r'<div id="view3d-pick"[^>]*data-node="(\d+)" data-values="([^"]*)"', dom)
    if not match:
        raise AssertionError("no node picked: " + re.search(r'<div id="view3d"[^>]*>', dom).group(0))
    return int(match.group(1)), json.loads(html.unescape(match.group(2)))


def view_state(dom: str) -> dict:
    tag = re.search(r'<div id="view3d"[^>]*>', dom).group(0)
    return dict(re.findall(r'data-([a-z-]+)="([^"]*)"', tag))


class ViewOfLoadSteps(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = pathlib.Path(tempfile.mkdtemp(prefix="fabform-view3d-"))
        cls.cup = cls.folder / "cup"
        command = [FABFORM, "run", str(ROOT / "scenes" / "cup.toml"), "--out", str(cls.cup), "--quiet",
                   "--set", "fabric.divisions=[16,16]", "--set", "body.0.path.steps=3"]
        assert subprocess.run(command, stderr=subprocess.PIPE).returncode == 0
        subprocess.run(REPORT + [str(cls.cup)], check=True, capture_output=True)
        cls.result = json.loads((cls.cup / "result.json").read_text())
        cls.steps = [step_file(cls.cup / s["fabric_file"]) for s in cls.result["steps"]]

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)

    def test_the_data_holds_every_step_as_its_files_do(self):
        data = view_data(self.cup)
        self.assertEqual(len(data["frames"]), 3)
        self.assertEqual(data["nodes"], self.result["nodes"])
        triangles = decoded(data["triangles"], "<u4").reshape(-1, 3)
        self.assertEqual(len(triangles), 2 * self.result["fabric"]["faces"])  # four-sided faces, two each
        for frame, step in zip(data["frames"], self.steps):
            points = decoded(frame["buffers"]["points"], "<f4").reshape(-1, 3)
            np.testing.assert_allclose(points, step["points"], **FLOAT32)
            for name in ("strain_warp", "strain_weft", "draw_in_m", "contact_pressure_Pa"):
                np.testing.assert_allclose(decoded(frame["fields"][name], "<f4"), step[name], **FLOAT32)
            np.testing.assert_allclose(decoded(frame["fields"]["contact_pressure_mmHg"], "<f4"),
                                       step["contact_pressure_Pa"] / MMHG_PA, **FLOAT32)
        final = data["frames"][-1]["fields"]
        np.testing.assert_allclose(decoded(final["shear_angle_deg"], "<f4"),
                                   legacy_cell_field(self.cup / "fabric.vtk", "shear_angle_deg"), **FLOAT32)
        self.assertIn("body_contact_pressure_Pa", final)
        self.assertNotIn("shear_angle_deg", data["frames"][0]["fields"])
        ranges = {f["name"]: (f["min"], f["max"]) for f in data["fields"]}
        self.assertAlmostEqual(ranges["strain_warp"][1], max(s["strain_warp"].max() for s in self.steps), places=6)

    def test_chromium_picks_the_node_it_is_asked_for_and_reads_its_file(self):
        for frame, node in ((2, FLANGE_NODE), (3, TOP_NODE), (3, FLANGE_NODE)):
            with self.subTest(frame=frame, node=node):
                dom, console = open_in_chromium(self.cup / "report.html", f"#field=strain_weft&frame={frame}&node={node}")
                self.assertEqual(console, [])
                state = view_state(dom)
                self.assertEqual((state["state"], state["field"], state["frame"]), ("ready", "strain_weft", str(frame)))
                got, values = picked(dom)
                self.assertEqual(got, node)
                step = self.steps[frame - 1]
                np.testing.assert_allclose(values["position_m"], step["points"][node], **FLOAT32)
                for name in ("strain_warp", "strain_weft", "draw_in_m", "contact", "contact_pressure_Pa"):
                    np.testing.assert_allclose(values[name], step[name][node], **FLOAT32, err_msg=name)
                self.assertEqual("shear_angle_deg" in values, frame == 3)

    def test_a_field_the_frame_does_not_have_is_named(self):
        dom, console = open_in_chromium(self.cup / "report.html", "#field=shear_angle_deg&frame=1")
        self.assertEqual(console, [])
        self.assertEqual(view_state(dom)["state"], "ready")
        self.assertIn("not written for load step 1 of 3 (per-cell fields are the final state's)", dom)

    def test_without_webgl_the_view_says_so_and_the_pictures_stay(self):
        dom, console = open_in_chromium(self.cup / "report.html", webgl=False)
        self.assertEqual(console, [])
        self.assertEqual(view_state(dom)["state"], "no-webgl")
        self.assertIn("WebGL is unavailable in this browser", dom)
        self.assertIn(f'data-pictures-shown="{PICTURES + 1}/{PICTURES + 1}"', dom)

    def test_without_its_data_the_view_says_so(self):
        copy = self.folder / "copy"
        shutil.copytree(self.cup, copy)
        (copy / "view3d" / "data.js").unlink()
        dom, _ = open_in_chromium(copy / "report.html")
        self.assertEqual(view_state(dom)["state"], "no-data")
        self.assertIn("view3d/data.js is missing", dom)

    def test_nothing_is_loaded_from_a_url(self):
        page = (self.cup / "report.html").read_text()
        scripts = re.findall(r'<script src="([^"]+)"', page)
        self.assertEqual(scripts, ["view3d/three.min.js", "view3d/OrbitControls.js", "view3d/data.js", "view3d/viewer.js"])
        for name in (*scripts, "view3d/three-copyright.txt"):
            self.assertTrue((self.cup / name).is_file(), name)
        self.assertIn("Upstream-Name: three.js", (self.cup / "view3d" / "three-copyright.txt").read_text())
        self.assertNotRegex(page + (self.cup / "view3d" / "viewer.js").read_text(), r"https?://")


if __name__ == "__main__":
    unittest.main()
