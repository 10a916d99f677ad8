#!/usr/bin/python3
"""tools/bench_solvers.py --scale (tools/bench_scale.py): its options (bad ones exit 2 in one
line), the fitted exponent and the time ratio on synthetic figures, and on tiny domes (needs
fabform: $FABFORM_BINARY, else build/fabform; skipped without it) a table whose estimate is
within a factor of 3 of the measured distance, and a size over the timeout reported as such,
with the larger sizes after it not run."""
import csv
import io
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest
from contextlib import redirect_stderr

TOOLS = pathlib.Path(__file__).resolve().parents[2] / "tools"
sys.path.insert(0, str(TOOLS))
import bench_scale  # noqa: E402


def exit_status(argv: list) -> int:
    with redirect_stderr(io.StringIO()):
        try:
            bench_scale.parse_args(argv)
        except SystemExit as stop:
            return stop.code
    return 0


class Options(unittest.TestCase):
    def test_defaults_are_the_issues_sizes(self):
        args = bench_scale.parse_args(["--scale"])
        self.assertEqual(args.sizes, [101, 201, 401, 1001])
        self.assertEqual(args.timeout, 600.0)

    def test_thread_counts_keep_their_order(self):
        self.assertEqual(bench_scale.parse_args(["--scale", "--threads", "2,1,2"]).threads, [2, 1])

    def test_sizes_are_sorted_without_duplicates(self):
        self.assertEqual(bench_scale.parse_args(["--scale", "--sizes", "201,101,201"]).sizes, [101, 201])

    def test_seeds_keep_their_order(self):
        self.assertEqual(bench_scale.parse_args(["--scale", "--seeds", "3,1,3"]).seeds, [3, 1])
        self.assertEqual(bench_scale.parse_args(["--scale"]).seeds, [])

    def test_bad_options_exit_2(self):
        for bad in (["--sizes", "abc"], ["--sizes", ""], ["--sizes", "2"], ["--sizes", "10002"],
                    ["--timeout", "0"], ["--timeout", "-5"], ["--timeout", "nan"], ["--timeout", "soon"],
                    ["--runs", "0"], ["--threads", "0"], ["--threads", "1,x"], ["--threads", "65"],
                    ["--reference-tol", "0"], ["--linear-solver", "lu"], ["--continuation", "11"],
                    ["--continuation", "-1"], ["--baseline", "/nonexistent/fabform"], ["--seeds", "1,x"],
                    ["--seeds", "-1"], ["--perturbation", "0"], ["--perturbation", "inf"]):
            with self.subTest(bad=bad):
                self.assertEqual(exit_status(["--scale", *bad]), 2)


class Fits(unittest.TestCase):
    def test_a_power_law_gives_its_exponent(self):
        points = [(n * n, 3e-6 * (n * n) ** 1.37) for n in (101, 201, 401)]
        self.assertAlmostEqual(bench_scale.fit_exponent(points), 1.37, places=12)

    def test_least_squares_through_scatter(self):
        # log t = 1 + 2 log n off by +0.1, -0.1, +0.1 at log n = 0, 1, 2: slope 2, as the line's.
        points = [(1.0, 2.718281828 ** 1.1), (2.718281828, 2.718281828 ** 2.9), (2.718281828 ** 2, 2.718281828 ** 5.1)]
        self.assertAlmostEqual(bench_scale.fit_exponent(points), 2.0, places=6)

    def test_one_size_is_not_fitted(self):
        self.assertIsNone(bench_scale.fit_exponent([(10201, 1.0)]))
        self.assertIsNone(bench_scale.fit_exponent([]))

    def test_ratio_of_two_finished_sizes(self):
        rows = [{"N": 201, "status": "converged", "solve_s": 2.0}, {"N": 1001, "status": "converged", "solve_s": 50.0}]
        self.assertEqual(bench_scale.time_ratio(rows, "solve_s"), (25.0, ""))

    def test_ratio_says_why_it_is_missing(self):
        rows = [{"N": 201, "status": "converged", "solve_s": 2.0},
                {"N": 1001, "status": "over the timeout", "note": "killed after 600 s"}]
        ratio, why = bench_scale.time_ratio(rows, "solve_s")
        self.assertIsNone(ratio)
        self.assertIn("N=1001 over the timeout (killed after 600 s)", why)
        ratio, why = bench_scale.time_ratio(rows[:1], "solve_s")
        self.assertIsNone(ratio)
        self.assertIn("N=1001 was not asked for", why)


def overrides_of(run: pathlib.Path) -> dict:
    return {o["key"]: o["value"] for o in json.loads((run / "result.json").read_text())["overrides"]}


BINARY = pathlib.Path(os.environ.get("FABFORM_BINARY", TOOLS.parent / "build" / "fabform"))


@unittest.skipUnless(BINARY.exists(), f"{BINARY} is not built")
class TinyDomes(unittest.TestCase):
    def scale(self, out: str, *options: str) -> list:
        done = subprocess.run([sys.executable, str(TOOLS / "bench_solvers.py"), "--scale", "--out", out, *options],
                              capture_output=True, text=True, env=dict(os.environ, FABFORM_BINARY=str(BINARY)))
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(pathlib.Path(out) / "scale.csv", newline="") as f:
            return list(csv.DictReader(f)), done.stdout

    def test_table_with_the_estimate_against_the_measured_distance(self):
        with tempfile.TemporaryDirectory() as out:
            rows, text = self.scale(out, "--sizes", "11,21", "--runs", "2", "--timeout", "120",
                                    "--reference-max", "21")
        self.assertEqual([r["status"] for r in rows], ["converged", "converged"])
        for r in rows:
            self.assertEqual(r["runs"], "2")
            estimate, measured = float(r["position_error_m"]), float(r["measured_distance_m"])
            self.assertTrue(measured / 3 <= estimate <= 3 * measured, r)
        self.assertIn("p = ", text)
        self.assertIn("t(1001) / t(201): could not be computed: N=1001 was not asked for", text)

    def test_the_linear_solve_asked_for_is_the_one_reported(self):
        with tempfile.TemporaryDirectory() as out:
            rows, text = self.scale(out, "--sizes", "11,21", "--runs", "1", "--timeout", "120",
                                    "--reference-max", "0", "--linear-solver", "multigrid")
        # The dome lies on a lattice: its multigrid is the geometric one.
        self.assertEqual([r["linear_solver"] for r in rows], ["multigrid (lattice)", "multigrid (lattice)"])
        self.assertTrue(all(int(r["cg_iterations"]) >= int(r["iterations"]) for r in rows), rows)
        self.assertIn("linear solve multigrid", text)

    def test_thread_counts_and_a_baseline_each_get_rows_and_a_speed_up(self):
        # The baseline is this binary: the same work, so its time ratio is near 1 on any machine.
        with tempfile.TemporaryDirectory() as out:
            rows, text = self.scale(out, "--sizes", "11,21", "--runs", "1", "--timeout", "120",
                                    "--reference-max", "0", "--threads", "1,2", "--continuation", "1",
                                    "--baseline", str(BINARY))
            # The baseline runs with none of the --set options: no coarser grid first.
            solved = {d.name: json.loads((d / "run1" / "result.json").read_text())
                      for d in (pathlib.Path(out) / "N21").iterdir()}
            baseline_scene = (pathlib.Path(out) / "baseline_dome.toml").read_text()
        self.assertEqual([(r["N"], r["build"], r["threads"]) for r in rows],
                         [(n, b, t) for n in ("11", "21") for b, t in (("this", "1"), ("this", "2"), ("baseline", "1"))])
        self.assertTrue(all(r["status"] == "converged" for r in rows), rows)
        for n in (11, 21):
            self.assertIn(f"- N={n}: this, 2 thread(s) against this, 1 thread(s): ", text)
            self.assertIn(f"- N={n}: this, 1 thread(s) against baseline, 1 thread(s): ", text)
        self.assertIn("continuation levels 1", text)
        self.assertEqual(sorted(solved), ["baseline-T1", "this-T1", "this-T2"])
        self.assertEqual([c["divisions"] for c in solved["this-T1"]["continuation"]], [[10, 10]])
        self.assertEqual(solved["this-T2"]["threads"], 2)
        self.assertNotIn("continuation", solved["baseline-T1"])
        # An older build may not know the dome's newer keys: it runs a copy without them, whose
        # paths still lead to the mold and the tables.
        self.assertTrue(solved["baseline-T1"]["scene_file"].endswith("baseline_dome.toml"))
        self.assertNotIn("slack_stiffness", baseline_scene)
        self.assertNotIn('"../', baseline_scene)

    def test_each_seed_runs_once_from_its_own_start(self):
        with tempfile.TemporaryDirectory() as out:
            rows, text = self.scale(out, "--sizes", "21", "--runs", "1", "--timeout", "120", "--reference-max", "21",
                                    "--seeds", "4,7", "--perturbation", "1e-4")
            seeds = [overrides_of(pathlib.Path(out) / "N21" / "this-T1" / run) for run in ("run1", "run2", "reference")]
        row = rows[0]
        self.assertEqual((row["status"], row["runs"]), ("converged", "2"))  # the seeds, not --runs
        low, median, high = (int(row[k]) for k in ("iterations_min", "iterations", "iterations_max"))
        self.assertTrue(low <= median <= high, row)
        self.assertIn(f"| {low}–{high} |", text)
        self.assertIn("seeds 4,7 (0.0001 m imperfection)", text)
        # Each seed's own start; the distance is measured from the first seed's.
        self.assertEqual([(o["initial.seed"], o["initial.perturbation_m"]) for o in seeds],
                         [("4", "0.0001"), ("7", "0.0001"), ("4", "0.0001")])
        estimate, measured = float(row["position_error_m"]), float(row["measured_distance_m"])
        self.assertTrue(measured / 3 <= estimate <= 3 * measured, row)

    def test_a_size_over_the_timeout_is_reported_and_larger_ones_not_run(self):
        with tempfile.TemporaryDirectory() as out:
            rows, text = self.scale(out, "--sizes", "11,21", "--timeout", "0.001")
        self.assertEqual([r["status"] for r in rows], ["over the timeout", "not run"])
        self.assertIn("killed after", rows[0]["note"])
        self.assertIn("N=11 was already over the timeout", rows[1]["note"])
        self.assertIn("not fitted", text)


if __name__ == "__main__":
    unittest.main()
