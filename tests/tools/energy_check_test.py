#!/usr/bin/python3
"""tools/energy_check.cpp on real runs: the dome scene, stopped after two newton iterations far
from its rest (forces of newtons), has the energy its forces say at every free node, read with
the scene and --set overrides its result.json recorded; a folder without a result.json or a
checkpoint is refused in one line naming the file, exit status 2 (the check itself, and what it
finds where it disagrees: tests/analysis/energy_consistency_test.cpp). Needs $FABFORM_BINARY and
$FABFORM_ENERGY_CHECK (else build/fabform and build/fabform_energy_check)."""
import os
import pathlib
import shutil
import subprocess
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FABFORM = os.environ.get("FABFORM_BINARY", str(ROOT / "build" / "fabform"))
CHECK = os.environ.get("FABFORM_ENERGY_CHECK", str(ROOT / "build" / "fabform_energy_check"))


class EnergyCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = str(pathlib.Path(cls.tmp.name) / "dome")
        run = subprocess.run([FABFORM, "run", str(ROOT / "scenes" / "dome.toml"), "--out", cls.run_dir, "--quiet",
                              "--set", "fabric.divisions=[20,20]", "--max-iter", "2"], capture_output=True, text=True)
        assert run.returncode == 3, run.stderr  # stopped at its cap, as asked

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def check(self, folder: str) -> subprocess.CompletedProcess:
        return subprocess.run([CHECK, folder], capture_output=True, text=True)

    def test_every_free_node_agrees_with_its_force(self):
        check = self.check(self.run_dir)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)
        checked = int(check.stdout.split(":")[1].split()[0])
        self.assertGreater(checked, 100)  # most of the 441 nodes were free and pulled
        self.assertIn("; 0 disagree", check.stdout)

    def test_a_folder_without_a_result_is_refused(self):
        empty = str(pathlib.Path(self.tmp.name) / "empty")
        os.makedirs(empty)
        check = self.check(empty)
        self.assertEqual(check.returncode, 2)
        self.assertIn(empty + "/result.json", check.stderr)
        self.assertEqual(check.stderr.count("\n"), 1)

    def test_a_run_without_a_checkpoint_is_refused(self):
        copy = str(pathlib.Path(self.tmp.name) / "converged")
        shutil.copytree(self.run_dir, copy)
        os.remove(copy + "/checkpoint.bin")  # as a converged run leaves it
        check = self.check(copy)
        self.assertEqual(check.returncode, 2)
        self.assertIn(copy + "/checkpoint.bin", check.stderr)


if __name__ == "__main__":
    unittest.main()
