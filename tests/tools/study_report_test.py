#!/usr/bin/python3
"""tools/study_report.py on a real study (`fabform study`, a small dome grid), opened in headless
Chromium (Debian's chromium) as tests/tools/report_test.py opens a run's report: the page loads
without console errors and shows every plot (each figure against each varied value) and the
table; a picture missing is named in place; bad input is one line and exit status 2.

Usage: FABFORM_BINARY=build/fabform /usr/bin/python3 tests/tools/study_report_test.py
"""
import csv
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "tools"))
from report_test import open_in_chromium  # noqa: E402

FABFORM = os.environ.get("FABFORM_BINARY", str(ROOT / "build" / "fabform"))
REPORT = [sys.executable, str(ROOT / "tools" / "study_report.py")]
STUDY = f"""[study]
name = "small_dome"
scene = "{ROOT / 'scenes' / 'dome.toml'}"
figures = ["residual_recomputed_N", "figures.max_warp_strain"]

[study.set]
"fabric.divisions" = [12, 12]

[grid]
"solver.name" = ["newton", "dynamic"]
"solver.tolerance_N" = [1e-4, 1e-6]
"""
PICTURES = (2 + 2) * 2  # (figures + iterations + wall seconds) × varied keys


class RealStudy(unittest.TestCase):
    """A test class whose study (its STUDY text) runs once, with `fabform study --jobs 2`, into
    self.out; its standard error is self.stderr."""
    STUDY = ""

    @classmethod
    def setUpClass(cls):
        cls.folder = pathlib.Path(tempfile.mkdtemp(prefix="fabform-study-report-"))
        (cls.folder / "study.toml").write_text(cls.STUDY)
        cls.out = cls.folder / "out"
        done = subprocess.run([FABFORM, "study", str(cls.folder / "study.toml"), "--out", str(cls.out), "--jobs", "2"],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        cls.stderr = done.stderr

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)


class StudyReport(RealStudy):
    STUDY = STUDY

    def test_the_study_writes_its_report_with_every_plot_and_the_table(self):
        page = (self.out / "study.html").read_text()
        self.assertIn("Study small_dome: 4 of 4 cases converged", page)
        self.assertEqual(page.count("<img "), PICTURES)
        with (self.out / "study.csv").open(newline="") as f:
            for row in csv.DictReader(f):
                self.assertIn(f"<td>{row['residual_recomputed_N']}</td>", page)

    def test_chromium_shows_every_plot_without_console_errors(self):
        dom, console = open_in_chromium(self.out / "study.html")
        self.assertEqual(console, [])
        self.assertIn(f'data-pictures-shown="{PICTURES}/{PICTURES}"', dom)
        self.assertNotIn('<p class="missing">', dom)

    def test_chromium_names_a_missing_plot_in_place(self):
        copy = self.folder / "copy"
        shutil.copytree(self.out, copy)
        (copy / "study_0_1.png").unlink()
        dom, _ = open_in_chromium(copy / "study.html")
        self.assertIn(f'data-pictures-shown="{PICTURES - 1}/{PICTURES}"', dom)
        self.assertIn('<p class="missing">missing picture: study_0_1.png</p>', dom)

    def test_a_folder_without_a_study_is_one_line_exit_two(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = subprocess.run(REPORT + [tmp], capture_output=True, text=True)
            self.assertEqual(done.returncode, 2)
            self.assertEqual(len(done.stderr.splitlines()), 1, done.stderr)
            self.assertIn("study.json", done.stderr)
            self.assertFalse((pathlib.Path(tmp) / "study.html").exists())


SPECIMENS = f"""[study]
name = "dome_specimens"
scene = "{ROOT / 'scenes' / 'dome.toml'}"
figures = ["figures.max_warp_strain", "residual_recomputed_N"]
specimens = 3

[study.set]
"fabric.divisions" = [12, 12]
"initial.perturbation_m" = 2e-3

[grid]
"solver.tolerance_N" = [1e-4, 1e-6]
"""


class StudySpecimens(RealStudy):
    """A study with specimens: each case run with initial.seed 1 to 3, and study_specimens.csv's
    means and scatter equal to those of study.csv's rows, computed here with Python's statistics."""
    STUDY = SPECIMENS

    def test_the_means_and_deviations_are_those_of_the_specimens_rows(self):
        with (self.out / "study.csv").open(newline="") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["initial.seed"] for r in rows], ["1", "2", "3"] * 2)
        with (self.out / "study_specimens.csv").open(newline="") as f:
            summary = list(csv.DictReader(f))
        self.assertEqual(len(summary), 2)
        for case, row in enumerate(summary):
            specimens = rows[3 * case:3 * case + 3]
            self.assertEqual(row["solver.tolerance_N"], specimens[0]["solver.tolerance_N"])
            self.assertEqual((row["specimens"], row["finished"], row["converged"]), ("3", "3", "3"))
            for figure in ("figures.max_warp_strain", "residual_recomputed_N"):
                readings = [float(r[figure]) for r in specimens]
                self.assertGreater(max(readings), min(readings), "the seeds made no difference")
                scale = max(abs(v) for v in readings)
                self.assertAlmostEqual(float(row[figure + " mean"]), statistics.mean(readings), delta=1e-14 * scale)
                self.assertAlmostEqual(float(row[figure + " sd"]), statistics.stdev(readings), delta=1e-12 * scale)
                self.assertEqual(float(row[figure + " min"]), min(readings))
                self.assertEqual(float(row[figure + " max"]), max(readings))
        self.assertIn("study_specimens.csv", self.stderr)

    def test_the_report_shows_the_specimens_table(self):
        page = (self.out / "study.html").read_text()
        self.assertIn("Over 3 specimens (initial.seed 1 to 3)", page)
        self.assertIn("<th>figures.max_warp_strain mean</th>", page)


if __name__ == "__main__":
    unittest.main()
