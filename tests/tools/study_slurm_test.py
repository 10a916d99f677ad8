#!/usr/bin/python3
"""`fabform study --on slurm` against a real Slurm: tools/slurm_local.sh starts Debian's munged,
slurmctld and slurmd on this machine (one node, its CPUs); a small dome study submitted as a job
array gives the very study.csv the local pool gives (every figure to the last digit; only wall
seconds differ); a case cancelled with scancel is a row marked with how it ended, and
`fabform study --resume DIR` redoes it (and it alone). If Slurm cannot start, the test fails.

Usage: FABFORM_BINARY=build/fabform /usr/bin/python3 tests/tools/study_slurm_test.py
"""
import csv
import os
import pathlib
import shutil
import subprocess
import tempfile
import time
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FABFORM = os.environ.get("FABFORM_BINARY", str(ROOT / "build" / "fabform"))
CLUSTER = str(ROOT / "tools" / "slurm_local.sh")
STUDY = f"""[study]
name = "slurm_dome"
scene = "{ROOT / 'scenes' / 'dome.toml'}"
figures = ["residual_N", "residual_recomputed_N", "figures.max_warp_strain", "contact_nodes"]

[study.set]
"fabric.divisions" = [16, 16]

[grid]
"solver.name" = ["newton", "dynamic"]
"solver.tolerance_N" = [1e-4, 1e-6]
"""


def table(folder: pathlib.Path) -> list:
    """study.csv's rows without wall seconds (the one column that differs between runs)."""
    with (folder / "study.csv").open(newline="") as f:
        return [{k: v for k, v in row.items() if k != "wall_seconds"} for row in csv.DictReader(f)]


def study(*arguments: str) -> subprocess.CompletedProcess:
    return subprocess.run([FABFORM, "study", *arguments], capture_output=True, text=True, timeout=600)


class StudyOnSlurm(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.was_running = subprocess.run([CLUSTER, "status"], capture_output=True).returncode == 0
        started = subprocess.run([CLUSTER, "start"], capture_output=True, text=True)
        if started.returncode != 0:
            raise AssertionError(f"Slurm did not start: {started.stderr}")
        cls.folder = pathlib.Path(tempfile.mkdtemp(prefix="fabform-slurm-", dir="/tmp"))
        cls.spec = cls.folder / "dome.toml"
        cls.spec.write_text(STUDY)
        local = study(str(cls.spec), "--out", str(cls.folder / "local"), "--jobs", "2")
        assert local.returncode == 0, local.stderr
        cls.local = table(cls.folder / "local")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.folder, ignore_errors=True)
        if not cls.was_running:
            subprocess.run([CLUSTER, "stop"], capture_output=True)

    def test_a_study_on_slurm_gives_the_local_pools_table(self):
        out = self.folder / "slurm"
        done = study(str(self.spec), "--out", str(out), "--on", "slurm", "--time-limit", "10", "--mem-mb", "500")
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("submitted to Slurm as job", done.stderr)
        script = (out / "slurm" / "study.sbatch").read_text()
        for flag in ("#SBATCH --array=0,1,2,3", "#SBATCH --cpus-per-task=1", "#SBATCH --time=10", "#SBATCH --mem=500"):
            self.assertIn(flag, script)
        self.assertEqual(table(out), self.local)
        self.assertTrue((out / "study.html").is_file())

    def test_a_cancelled_case_is_reported_and_redone_by_resume(self):
        out = self.folder / "cancelled"
        running = subprocess.Popen([FABFORM, "study", str(self.spec), "--out", str(out), "--on", "slurm"],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        jobs = out / "slurm" / "jobs.txt"
        deadline = time.monotonic() + 60
        while not (jobs.is_file() and jobs.read_text().strip()) and time.monotonic() < deadline:
            time.sleep(0.01)
        job = jobs.read_text().split()[0]
        subprocess.run(["scancel", f"{job}_1"], check=True)
        _, stderr = running.communicate(timeout=600)
        self.assertEqual(running.returncode, 3, stderr)
        rows = table(out)
        self.assertEqual(rows[1]["converged"], "false")
        self.assertIn(rows[1]["termination"], ("cancelled", "interrupted"))
        self.assertEqual(rows[1]["residual_N"], "")
        self.assertEqual([r["converged"] for i, r in enumerate(rows) if i != 1], ["true"] * 3)
        untouched = (out / "cases" / "0000" / "result.json").read_text()
        resumed = study("--resume", str(out), "--on", "slurm")
        self.assertEqual(resumed.returncode, 0, resumed.stderr)
        self.assertIn("4 cases (1 to run)", resumed.stderr)
        self.assertEqual((out / "cases" / "0000" / "result.json").read_text(), untouched)
        self.assertEqual(table(out), self.local)


if __name__ == "__main__":
    unittest.main()
