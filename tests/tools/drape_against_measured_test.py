#!/usr/bin/python3
"""tools/drape_against_measured.py: fabform's specimen means set beside Petrak et al. 2025's
measured drape coefficients (materials/petrak2025/fabrics.csv), each simulator's mean absolute
error computed from them; a study folder without its table is one line and exit status 2.

Usage: /usr/bin/python3 tests/tools/drape_against_measured_test.py
"""
import csv
import pathlib
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = [sys.executable, str(ROOT / "tools" / "drape_against_measured.py")]


def measured():
    with open(ROOT / "materials" / "petrak2025" / "fabrics.csv", newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


class DrapeAgainstMeasured(unittest.TestCase):
    def test_the_errors_are_the_mean_distances_to_the_measurements(self):
        fabrics = measured()
        self.assertEqual(len(fabrics), 6)
        with tempfile.TemporaryDirectory() as tmp:
            rows = ["cases,fabric.warp,specimens,finished,converged,drape_coefficient mean,drape_coefficient sd,"
                    "drape.folds mean"]
            # fabform's means put 0.02 above every measurement but the last, 0.04 below that one.
            for i, fabric in enumerate(fabrics):
                mean = float(fabric["measured_dc"]) + (0.02 if i < 5 else -0.04)
                rows.append("%d-%d,../materials/petrak2025/%s_warp.csv,4,4,4,%r,0.01,9" % (4 * i, 4 * i + 3, fabric["id"], mean))
            (pathlib.Path(tmp) / "study_specimens.csv").write_text("\n".join(rows) + "\n")
            done = subprocess.run(TOOL + [tmp], capture_output=True, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            clo = sum(abs(float(f["clo3d_dc"]) - float(f["measured_dc"])) for f in fabrics) / 6
            self.assertIn("fabform %.1f points, CLO3D %.1f points" % ((5 * 2 + 4) / 6, 100 * clo), done.stdout)
            self.assertIn("| +2.0 |", done.stdout)
            self.assertIn("| -4.0 |", done.stdout)
            self.assertEqual((pathlib.Path(tmp) / "against_measured.md").read_text(), done.stdout)

    def test_a_bad_table_is_one_line_naming_it_exit_two(self):
        header = ("cases,fabric.warp,specimens,finished,converged,drape_coefficient mean,drape_coefficient sd,"
                  "drape.folds mean\n")
        row = "0-3,../materials/petrak2025/M1_warp.csv,4,4,4,0.3,0.01,9\n"
        for text, said in ((header, "no rows"), ("cases,fabric.warp\n" + "0-3,x\n", "no column"),
                           (header + row + row.replace("0-3", "4-7"), "a second time"),
                           (header + "0-3,../materials/petrak2025/M1_warp.csv,4,4,4,abc,0.01,9\n", "not a number"),
                           (header + "0-3,../materials/other/X_warp.csv,4,4,4,0.3,0.01,9\n", "none of")):
            with tempfile.TemporaryDirectory() as tmp:
                (pathlib.Path(tmp) / "study_specimens.csv").write_text(text)
                done = subprocess.run(TOOL + [tmp], capture_output=True, text=True)
                self.assertEqual(done.returncode, 2, text)
                self.assertEqual(len(done.stderr.splitlines()), 1, done.stderr)
                self.assertIn("study_specimens.csv", done.stderr)
                self.assertIn(said, done.stderr)

    def test_a_folder_without_the_table_is_one_line_exit_two(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = subprocess.run(TOOL + [tmp], capture_output=True, text=True)
            self.assertEqual(done.returncode, 2)
            self.assertEqual(len(done.stderr.splitlines()), 1, done.stderr)
            self.assertIn("study_specimens.csv", done.stderr)


if __name__ == "__main__":
    unittest.main()
