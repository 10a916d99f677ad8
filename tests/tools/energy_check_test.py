#!/usr/bin/python3
"""tools/energy_check.cpp on real runs: a knit pulled over the dome mold, stopped after two newton
iterations far from its rest (forces of newtons), has the energy its forces say at every free
node (each term's derivative is checked against its energy this way); a checkpoint missing or
made for another model is refused in one line naming the file, exit status 2. Needs
$FABFORM_BINARY and $FABFORM_ENERGY_CHECK (else build/fabform and build/fabform_energy_check)."""
import os
import pathlib
import subprocess
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FABFORM = os.environ.get("FABFORM_BINARY", str(ROOT / "build" / "fabform"))
CHECK = os.environ.get("FABFORM_ENERGY_CHECK", str(ROOT / "build" / "fabform_energy_check"))
DOME = str(ROOT / "scenes" / "dome.toml")
SMALL = "fabric.divisions=[20,20]"


class EnergyCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = str(pathlib.Path(cls.tmp.name) / "dome")
        run = subprocess.run([FABFORM, "run", DOME, "--out", cls.run_dir, "--quiet", "--set", SMALL,
                              "--max-iter", "2"], capture_output=True, text=True)
        assert run.returncode == 3, run.stderr  # stopped at its cap, as asked

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_every_free_node_agrees_with_its_force(self):
        check = subprocess.run([CHECK, DOME, self.run_dir, SMALL], capture_output=True, text=True)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)
        checked = int(check.stdout.split(":")[1].split()[0])
        self.assertGreater(checked, 100)  # most of the 441 nodes were free and pulled
        self.assertIn("; 0 disagree", check.stdout)

    def test_a_checkpoint_of_another_model_is_refused(self):
        check = subprocess.run([CHECK, DOME, self.run_dir], capture_output=True, text=True)
        self.assertEqual(check.returncode, 2)
        self.assertIn(self.run_dir + "/checkpoint.bin: made for 441 nodes", check.stderr)
        self.assertEqual(check.stderr.count("\n"), 1)

    def test_a_missing_checkpoint_is_refused(self):
        missing = str(pathlib.Path(self.tmp.name) / "none")
        check = subprocess.run([CHECK, DOME, missing], capture_output=True, text=True)
        self.assertEqual(check.returncode, 2)
        self.assertIn(missing + "/checkpoint.bin", check.stderr)


if __name__ == "__main__":
    unittest.main()
