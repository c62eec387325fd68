"""scripts/same_results.py: the check that a restructuring changed no result.

    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import os
import subprocess
import sys
import tempfile
import unittest

from result_files import write

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "same_results.py")

STATES = ("load_N,T_mean_C,wall_ms,branch\n"
          "100,30.65482386,69.014,cool\n"
          "115,30.94110021,23.7,cool\n")


def compare(before, after):
    run = subprocess.run([sys.executable, SCRIPT, before, after], capture_output=True, text=True)
    return run.returncode, run.stdout + run.stderr


class SameResults(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.before = os.path.join(self.tmp.name, "before")
        self.after = os.path.join(self.tmp.name, "after")
        write(os.path.join(self.before, "paper", "states.csv"), STATES)

    def tearDown(self):
        self.tmp.cleanup()

    def test_the_same_numbers_but_the_timings_are_the_same(self):
        write(os.path.join(self.after, "paper", "states.csv"), STATES.replace("69.014", "71.2"))
        code, out = compare(self.before, self.after)
        self.assertEqual(code, 0, out)
        self.assertIn("the same", out)

    def test_a_cell_that_differs_in_its_last_digit_is_named(self):
        write(os.path.join(self.after, "paper", "states.csv"), STATES.replace("30.94110021", "30.94110022"))
        code, out = compare(self.before, self.after)
        self.assertEqual(code, 1, out)
        self.assertIn("paper/states.csv: row 2, T_mean_C: 30.94110021 / 30.94110022", out)

    def test_a_missing_file_or_row_or_column_differs(self):
        write(os.path.join(self.after, "paper", "states.csv"), STATES.rsplit("115", 1)[0])
        write(os.path.join(self.after, "paper", "distress.csv"), "speed_rad_s\n545\n")
        code, out = compare(self.before, self.after)
        self.assertEqual(code, 1, out)
        self.assertIn("2 rows / 1 rows", out)
        self.assertIn("paper/distress.csv: only in after", out)
        write(os.path.join(self.after, "paper", "states.csv"), STATES.replace(",branch", ",regime"))
        code, out = compare(self.before, self.after)
        self.assertEqual(code, 1, out)
        self.assertIn("columns differ", out)


if __name__ == "__main__":
    unittest.main()
