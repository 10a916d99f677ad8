#!/usr/bin/python3
"""tools/report.py on real runs of the shipped mold and cup, opened in headless Chromium (Debian's
chromium): the page loads without console errors and shows every picture; a run in load steps
shows its steps, and its step files are VTK XML that Python's parser reads and that agree with
result.json; a run that did not converge says so at the top; a picture missing is reported in place (so the check can fail);
bad input is one line and exit status 2. And tools/raster.py's z-buffer against geometry known
by hand.

Usage: FABFORM_BINARY=build/fabform /usr/bin/python3 tests/tools/report_test.py
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import numpy as np  # noqa: E402
import raster  # noqa: E402

FABFORM = os.environ.get("FABFORM_BINARY", str(ROOT / "build" / "fabform"))
REPORT = [sys.executable, str(ROOT / "tools" / "report.py")]
# two strain maps, shear angle, thickness ratio, wrinkle risk, draw-in, contact pressure, the
# histogram, the convergence plot
PICTURES = 9


def fabform_run(out: pathlib.Path, *extra: str) -> int:
    command = [FABFORM, "run", str(ROOT / "scenes" / "mold.toml"), "--out", str(out), "--quiet",
               "--set", "fabric.divisions=[20,20]", "--tol", "1e-3", *extra]
    return subprocess.run(command, stderr=subprocess.PIPE).returncode


# WebGL on SwiftShader, Chromium's software renderer (these machines have no GPU), asked for by
# name: the automatic fallback prints a deprecation to the console.
SOFTWARE_WEBGL = ["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]
NO_WEBGL = ["--disable-gpu", "--disable-software-rasterizer"]


def open_in_chromium(page: pathlib.Path, fragment: str = "", webgl: bool = True) -> tuple:
    """(the DOM after load, the console lines) of the page in headless Chromium, its address
    ending in `fragment` (e.g. "#node=3")."""
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(
            ["chromium", "--headless", "--no-sandbox", *(SOFTWARE_WEBGL if webgl else NO_WEBGL),
             f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", "--virtual-time-budget=10000",
             "--dump-dom", page.resolve().as_uri() + fragment],
            capture_output=True, text=True, timeout=120)
    console = [line for line in done.stderr.splitlines() if ":CONSOLE" in line]
    return done.stdout, console


class Report(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = pathlib.Path(tempfile.mkdtemp(prefix="fabform-report-"))
        cls.converged = cls.folder / "converged"
        cls.capped = cls.folder / "capped"
        assert fabform_run(cls.converged) == 0
        assert fabform_run(cls.capped, "--max-iter", "5") == 3
        for run in (cls.converged, cls.capped):
            subprocess.run(REPORT + [str(run)], check=True, capture_output=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)

    def test_every_picture_and_the_summary_are_written(self):
        for name in ("report.html", "strain_warp.png", "strain_weft.png", "shear_angle.png", "thickness_ratio.png",
                     "wrinkle_risk.png", "draw_in.png", "contact_pressure.png", "strain_histogram.png",
                     "convergence.png", "convergence.svg"):
            self.assertTrue((self.converged / name).is_file(), name)
        page = (self.converged / "report.html").read_text()
        for label in ("termination", "largest warp strain", "largest weft strain", "fabric area",
                      "contact", "largest shear angle", "smallest thickness ratio", "cells at risk of wrinkling",
                      "contact pressure", "mmHg", "What was modelled", "Warnings", "SHA-256"):
            self.assertIn(label, page)
        self.assertNotIn('class="alarm"', page)
        self.assertEqual(page.count("<img "), PICTURES)

    def test_summary_figures_match_result_json(self):
        result = json.loads((self.converged / "result.json").read_text())
        page = (self.converged / "report.html").read_text()
        peak = result["figures"]["max_warp_strain"]
        self.assertIn(f"{peak['strain'] * 100:.3g} %", page)
        self.assertIn(f"{result['figures']['contact_area_m2'] * 1e4:.4g} cm²", page)
        self.assertIn(f"{result['figures']['shear_angle_max_deg']:.3g}°", page)
        self.assertIn(f"{result['figures']['contact_pressure_max_Pa']:.4g} Pa", page)

    def test_a_run_that_did_not_converge_says_so_plainly(self):
        page = (self.capped / "report.html").read_text()
        self.assertIn('class="alarm"', page)
        self.assertIn("did NOT converge (not converged)", page)

    def test_chromium_shows_every_picture_without_console_errors(self):
        dom, console = open_in_chromium(self.converged / "report.html")
        self.assertEqual(console, [])
        self.assertIn(f'data-pictures-shown="{PICTURES}/{PICTURES}"', dom)
        self.assertNotIn('<p class="missing">', dom)

    def test_chromium_reports_a_missing_picture_in_place(self):
        copy = self.folder / "copy"
        shutil.copytree(self.capped, copy)
        (copy / "strain_weft.png").unlink()
        dom, _ = open_in_chromium(copy / "report.html")
        self.assertIn(f'data-pictures-shown="{PICTURES - 1}/{PICTURES}"', dom)
        self.assertIn('<p class="missing">missing picture: strain_weft.png</p>', dom)

    def test_a_script_error_reaches_the_console_check(self):
        copy = self.folder / "broken"
        shutil.copytree(self.converged, copy)
        page = copy / "report.html"
        page.write_text(page.read_text().replace("</body>", "<script>no_such_function();</script></body>"))
        _, console = open_in_chromium(page)
        self.assertTrue(any("no_such_function" in line for line in console), console)


class ReportOfLoadSteps(unittest.TestCase):
    """The cup, small, in three steps: its step files are well-formed VTK XML (Python's own
    parser) that agree with result.json, and its report shows the steps and loads in Chromium."""

    @classmethod
    def setUpClass(cls):
        cls.cup = pathlib.Path(tempfile.mkdtemp(prefix="fabform-steps-"))
        command = [FABFORM, "run", str(ROOT / "scenes" / "cup.toml"), "--out", str(cls.cup), "--quiet",
                   "--set", "fabric.divisions=[16,16]", "--set", "body.0.path.steps=3"]
        assert subprocess.run(command, stderr=subprocess.PIPE).returncode == 0
        subprocess.run(REPORT + [str(cls.cup)], check=True, capture_output=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.cup, ignore_errors=True)

    def test_step_files_are_vtk_xml_that_agree_with_the_result(self):
        result = json.loads((self.cup / "result.json").read_text())
        self.assertEqual([s["step"] for s in result["steps"]], [1, 2, 3])
        collection = ET.parse(self.cup / "fabric_steps.pvd").getroot()
        data_sets = collection.findall("./Collection/DataSet")
        self.assertEqual([d.get("file") for d in data_sets if d.get("part") == "0"],
                         [s["fabric_file"] for s in result["steps"]])
        for step in result["steps"]:
            piece = ET.parse(self.cup / step["fabric_file"]).getroot().find("./PolyData/Piece")
            self.assertEqual(int(piece.get("NumberOfPoints")), result["nodes"])
            self.assertEqual(int(piece.get("NumberOfPolys")), result["fabric"]["faces"])
            arrays = {a.get("Name"): a.text.split() for a in piece.findall("./PointData/DataArray")}
            self.assertEqual(len(arrays["strain_warp"]), result["nodes"])
            self.assertAlmostEqual(max(float(v) for v in arrays["draw_in_m"]), step["draw_in_max_m"], places=9)
            self.assertEqual(sum(float(v) for v in arrays["contact"]), step["contact_nodes"])
            bodies = ET.parse(self.cup / step["bodies_file"]).getroot().find("./PolyData/Piece")
            self.assertGreater(int(bodies.get("NumberOfPolys")), 0)

    def test_the_report_shows_every_step_and_loads_in_chromium(self):
        page = (self.cup / "report.html").read_text()
        self.assertIn("<h2>Load steps</h2>", page)
        # So coarse a blank (8.75 mm springs) cuts the punch's 6 mm rounded shoulder, and says so.
        cuts = json.loads((self.cup / "result.json").read_text())["figures"]["springs_cutting_bodies"]
        self.assertGreater(cuts, 0)
        self.assertIn(f"springs cutting a body</th><td>{cuts}, the deepest", page)
        self.assertIn("largest draw-in", page)
        self.assertTrue((self.cup / "steps.png").is_file())
        dom, console = open_in_chromium(self.cup / "report.html")
        self.assertEqual(console, [])
        self.assertIn(f'data-pictures-shown="{PICTURES + 1}/{PICTURES + 1}"', dom)


class BadInput(unittest.TestCase):
    def report(self, folder: pathlib.Path) -> subprocess.CompletedProcess:
        return subprocess.run(REPORT + [str(folder)], capture_output=True, text=True)

    def test_missing_folder_and_old_result_are_one_line_exit_two(self):
        with tempfile.TemporaryDirectory() as tmp:
            folder = pathlib.Path(tmp)
            done = self.report(folder / "nowhere")
            self.assertEqual(done.returncode, 2)
            self.assertEqual(len(done.stderr.splitlines()), 1, done.stderr)
            (folder / "result.json").write_text('{"scene": "s", "termination": "converged"}')
            done = self.report(folder)
            self.assertEqual(done.returncode, 2)
            self.assertIn("result.json", done.stderr)
            self.assertEqual(len(done.stderr.splitlines()), 1, done.stderr)
            self.assertFalse((folder / "report.html").exists())


class Raster(unittest.TestCase):
    VIEW_FROM_ABOVE = raster.camera(90.0, -90.0)  # x to the right, y up the image

    def test_the_nearer_of_two_squares_wins_every_pixel_it_covers(self):
        def square(z, size):
            a, b, c, d = [(-size, -size, z), (size, -size, z), (size, size, z), (-size, size, z)]
            return [[a, b, c], [a, c, d]]
        triangles = np.array(square(0.0, 1.0) + square(1.0, 0.5))  # the small one above
        frame = raster.Frame(triangles.reshape(-1, 3), self.VIEW_FROM_ABOVE, width=200, margin=0.0)
        owner, weights = raster.rasterise(frame, triangles)
        near = np.isin(owner, [2, 3]).sum()
        self.assertAlmostEqual(near / owner.size, 0.25, delta=0.01)  # its quarter of the image
        self.assertTrue(np.all(owner >= 0), "the big square covers the whole image")
        self.assertTrue(np.allclose(weights[owner >= 0].sum(axis=1), 1.0))

    def test_a_triangle_covers_its_area_in_pixels(self):
        triangle = np.array([[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]])
        frame = raster.Frame(triangle.reshape(-1, 3), self.VIEW_FROM_ABOVE, width=400, margin=0.0)
        owner, _ = raster.rasterise(frame, triangle)
        self.assertAlmostEqual((owner == 0).sum() / owner.size, 0.5, delta=0.005)

    def test_many_chunks_give_the_same_picture_as_one(self):
        rng = np.random.default_rng(7)
        triangles = rng.random((300, 3, 3))
        frame = raster.Frame(triangles.reshape(-1, 3), raster.camera(35, -60), width=120)
        whole = raster.rasterise(frame, triangles)[0]
        chunk, raster.CHUNK_PAIRS = raster.CHUNK_PAIRS, 500
        try:
            chunked = raster.rasterise(frame, triangles)[0]
        finally:
            raster.CHUNK_PAIRS = chunk
        self.assertTrue(np.array_equal(whole, chunked))


if __name__ == "__main__":
    unittest.main()
