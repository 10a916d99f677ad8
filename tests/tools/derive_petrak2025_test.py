#!/usr/bin/python3
"""tools/derive_petrak2025.py: a malformed fabrics.csv (a missing column, a value that is not a
positive number, no fabric) is one line naming the file and its line, exit status 2, and nothing
written; a usage error is exit status 2 as well.

Usage: /usr/bin/python3 tests/tools/derive_petrak2025_test.py
"""
import importlib.util
import io
import pathlib
import subprocess
import sys
import tempfile
import unittest
from contextlib import redirect_stderr

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = ROOT / "tools" / "derive_petrak2025.py"
HEADER = ("id,composition,weave,areal_mass_g_m2,stretch_warp_g_s2,stretch_weft_g_s2,shear_g_s2,"
          "bending_warp_g_mm2_s2,bending_weft_g_mm2_s2,measured_dc,clo3d_dc")


def load_tool(data, study):
    spec = importlib.util.spec_from_file_location("derive_petrak2025", TOOL)
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    tool.DATA, tool.STUDY = data, study
    return tool


class DerivePetrak2025(unittest.TestCase):
    def run_on(self, text):
        with tempfile.TemporaryDirectory() as tmp:
            data = pathlib.Path(tmp)
            (data / "fabrics.csv").write_text(text)
            tool = load_tool(data, data / "study.toml")
            err = io.StringIO()
            with redirect_stderr(err):
                status = tool.main([])
            written = sorted(p.name for p in data.iterdir())
        return status, err.getvalue(), written

    def test_a_malformed_table_is_one_line_and_writes_nothing(self):
        good = "M1,polyester,plain,135.17,477226,458614,41000,1950,610,0.223,0.349"
        cases = {
            "# a comment\n" + HEADER + "\n" + good.replace("135.17", "heavy") + "\n":
                "line 3: areal_mass_g_m2 = 'heavy' is not a number",
            HEADER + "\n" + good + "\n" + good.replace(",610,", ",-610,") + "\n":
                "line 3: bending_weft_g_mm2_s2 = '-610' must be positive",
            HEADER.replace(",shear_g_s2", "") + "\n": "no column shear_g_s2",
            HEADER + "\n": "no fabric",
        }
        for text, expected in cases.items():
            status, err, written = self.run_on(text)
            self.assertEqual(status, 2, err)
            self.assertIn(expected, err)
            self.assertEqual(err.count("\n"), 1, err)
            self.assertEqual(written, ["fabrics.csv"])

    def test_a_good_table_writes_its_tables_and_study(self):
        status, err, written = self.run_on(HEADER + "\nM1,polyester,plain,135.17,477226,458614,41000,1950,610,0.223,0.349\n")
        self.assertEqual(status, 0, err)
        self.assertEqual(written, ["M1_warp.csv", "M1_weft.csv", "fabrics.csv", "study.toml"])

    def test_a_usage_error_is_status_2(self):
        done = subprocess.run([sys.executable, str(TOOL), "--frobnicate"], capture_output=True, text=True)
        self.assertEqual(done.returncode, 2)
        self.assertIn("usage:", done.stderr)


if __name__ == "__main__":
    unittest.main()
