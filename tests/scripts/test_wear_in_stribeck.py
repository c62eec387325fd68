"""scripts/wear_in_stribeck.py: the wear-in study's Stribeck figure.

    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import os
import unittest

from result_files import ScriptOnResults, write

CASES = ("new", "worn", "worn_run_in", "run_in_0.3", "run_in_0.2", "run_in_0.1")


class WearInStribeck(ScriptOnResults):
    SCRIPT = "wear_in_stribeck.py"

    def write_case(self, name, branches=("cool", "cool", "cool", "hot")):
        rows = ["load_N,f_eff,stribeck,branch"]
        for k, branch in enumerate(branches):
            rows.append(f"{150 + 10 * k},{0.03 - 0.001 * k if branch == 'cool' else 0.19},{7e-6 - 5e-7 * k},{branch}")
        write(os.path.join(self.root, f"stribeck_{name}", "states.csv"), "\n".join(rows) + "\n")

    def test_every_case_is_drawn(self):
        for name in CASES:
            self.write_case(name)
        result = self.run_script(self.root)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertGreater(os.path.getsize(os.path.join(self.root, "wear_in_stribeck.png")), 1000)

    def test_a_missing_case_or_a_curve_without_a_cool_state_is_an_error(self):
        for name in CASES[:-1]:
            self.write_case(name)
        result = self.run_script(self.root)
        self.assertEqual(result.returncode, 1)
        self.assertIn("stribeck_run_in_0.1", result.stderr)
        self.write_case("run_in_0.1", branches=("hot", "hot"))
        result = self.run_script(self.root)
        self.assertEqual(result.returncode, 1)
        self.assertIn("no state on the cool branch", result.stderr)


if __name__ == "__main__":
    unittest.main()
