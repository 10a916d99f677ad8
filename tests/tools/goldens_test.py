#!/usr/bin/python3
"""tools/goldens.py's comparison and tools/plot_convergence.py's reader, on synthetic curves and
files: a curve inside the band passes, one that leaves it is caught where it leaves, a golden
with a missing column is refused in one line naming the file."""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools"))
import goldens  # noqa: E402
import plot_convergence as pc  # noqa: E402


def curve(n: int, start: float = 10.0, end: float = 1e-6) -> tuple:
    """A straight line on the log axis from start to end in n iterations."""
    its = list(range(n + 1))
    return its, [start * (end / start) ** (i / n) for i in its]


class FirstParting(unittest.TestCase):
    def test_same_curve_is_inside(self):
        self.assertIsNone(goldens.first_parting(curve(100), curve(100)))

    def test_a_few_iterations_sooner_is_inside(self):
        self.assertIsNone(goldens.first_parting(curve(100), curve(95)))

    def test_a_stall_is_caught_where_it_starts(self):
        its, res = curve(100)
        stalled = res[:50] + [res[50]] * 51  # stops improving at iteration 50
        parting = goldens.first_parting((its, res), (its, stalled))
        self.assertIsNotNone(parting)
        golden_it, new_it, decades = parting
        self.assertGreater(golden_it, 50)
        self.assertLess(golden_it, 60)  # 0.5 decades is 7 iterations of this curve
        self.assertGreater(decades, goldens.BAND_DECADES)

    def test_a_curve_a_decade_higher_is_caught_at_once(self):
        its, res = curve(100)
        parting = goldens.first_parting((its, res), (its, [10 * r for r in res]))
        self.assertEqual(parting[0], 0)
        self.assertAlmostEqual(parting[2], 1.0)


class ReadHistory(unittest.TestCase):
    def write(self, text: str) -> pathlib.Path:
        folder = pathlib.Path(self.enterContext(tempfile.TemporaryDirectory()))
        path = folder / "golden.csv"
        path.write_text(text)
        return path

    def test_reads_iterations_and_residuals(self):
        its, res = pc.read_history(self.write("iteration,residual_N,seconds\n0,1.5,0\n1,0.25,0.1\n"))
        self.assertEqual(its, [0, 1])
        self.assertEqual(res, [1.5, 0.25])

    def test_load_steps_are_laid_end_to_end(self):
        its, res = pc.read_history(self.write(
            "step,iteration,residual_N,seconds,contact_nodes\n1,0,2.0,0,0\n1,1,0.5,0,0\n1,2,0.1,0,0\n"
            "2,0,3.0,0,0\n2,1,0.2,0,0\n3,0,0.1,0,0\n"))
        self.assertEqual(its, [0, 1, 2, 2, 3, 3])
        self.assertEqual(res, [2.0, 0.5, 0.1, 3.0, 0.2, 0.1])

    def test_missing_column_names_the_file_and_the_column(self):
        path = self.write("iteration,seconds\n0,0\n")
        with self.assertRaises(pc.InputError) as caught:
            pc.read_history(path)
        self.assertEqual(str(caught.exception), f"{path}:1: missing column(s) residual_N")

    def test_bad_number_names_the_line(self):
        path = self.write("iteration,residual_N\n0,1.0\n1,fast\n")
        with self.assertRaises(pc.InputError) as caught:
            pc.read_history(path)
        self.assertTrue(str(caught.exception).startswith(f"{path}:3: "))

    def test_empty_history_is_refused(self):
        with self.assertRaises(pc.InputError):
            pc.read_history(self.write("iteration,residual_N\n"))


if __name__ == "__main__":
    unittest.main()
