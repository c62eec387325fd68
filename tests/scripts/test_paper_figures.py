"""scripts/paper_figures.sh with a stand-in twb that writes small synthetic results.

Checks the plumbing: which scenes run, with which overrides, where results and figures
go, and the exit status. The figures themselves are tested in test_twb_plot.py.
    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import os
import subprocess
import tempfile
import unittest

from test_twb_plot import (SLIDING_HEADER, STATES_HEADER, sliding_rows, state_rows, trajectory_rows,
                           with_run_columns, write)

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts",
                      "paper_figures.sh")

PAPER_FIGURES = (
    "fig06_f_eff_vs_load", "fig07_mean_temperature_vs_load", "fig08_hmin_over_sigma_vs_load",
    "fig09_gamma_x_ratio_vs_load", "fig10_gamma_y_ratio_vs_load", "fig11_fluid_share_vs_load",
    "fig12_contact_share_vs_load", "fig13_contact_share_vs_hmin", "fig14_stribeck",
    "fig15_stribeck_by_friction", "distress_map", "transient_trajectory", "sliding_comparison")

# A twb that copies FIXTURES/<scene>/ into --out, logs its arguments, and exits 3 when
# the fixture holds a file named FAIL (a solver failure).
STUB = """#!/bin/sh
echo "$@" >> "{log}"
scene=$(basename "$2" .yaml)
out=$4
mkdir -p "$out"
cp "{fixtures}/$scene"/*.csv "$out"/
if [ -f "{fixtures}/$scene/FAIL" ]; then exit 3; fi
exit 0
"""


class PaperFiguresTest(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="paper_figures_test_")
        self.tmp = self._tmp.name
        self.fixtures = os.path.join(self.tmp, "fixtures")
        self.log = os.path.join(self.tmp, "twb_args.log")
        self.write_fixtures()
        self.twb = os.path.join(self.tmp, "twb")
        with open(self.twb, "w", encoding="utf-8") as f:
            f.write(STUB.format(log=self.log, fixtures=self.fixtures))
        os.chmod(self.twb, 0o755)

    def tearDown(self):
        self._tmp.cleanup()

    def write_fixtures(self):
        loads = [100, 400, 700, 1000]
        d = os.path.join(self.fixtures, "paper_load_sweeps")
        os.makedirs(d)
        write(os.path.join(d, "states.csv"),
              [STATES_HEADER] + [r for w in (136, 545, 953, 1367) for r in state_rows(w, loads)])
        write(os.path.join(d, "distress.csv"),
              ["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
               "136,,,,,no fold up to 1750 N (gradual heating)",
               "545,1117,1110,1125,1119,runaway; fold at 1119 N"])
        write(os.path.join(d, "trajectory.csv"),
              ["t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s"]
              + trajectory_rows(",545"))
        d = os.path.join(self.fixtures, "friction_coefficient")
        os.makedirs(d)
        write(os.path.join(d, "states.csv"),
              [STATES_HEADER.replace("speed_rad_s,", "speed_rad_s,friction_coefficient,")]
              + [r for f in (0.05, 0.1, 0.2) for r in with_run_columns(state_rows(545, loads), f"{f},")])
        d = os.path.join(self.fixtures, "sliding_choice")
        os.makedirs(d)
        write(os.path.join(d, "states.csv"),
              [STATES_HEADER.replace("speed_rad_s,", "speed_rad_s,sliding,")]
              + with_run_columns(state_rows(545, loads), "carrier_washer,"))
        write(os.path.join(d, "sliding.csv"), [SLIDING_HEADER] + sliding_rows(545, loads))

    def run_script(self, *args):
        env = dict(os.environ, MPLBACKEND="Agg")
        return subprocess.run(["sh", SCRIPT, "--twb", self.twb, "--out", os.path.join(self.tmp, "paper"),
                               "--format", "svg", *args], capture_output=True, text=True, env=env,
                              timeout=600)

    def figures(self):
        return os.path.join(self.tmp, "paper", "figures")

    def test_every_figure_in_one_directory(self):
        result = self.run_script("--quick")
        self.assertEqual(result.returncode, 0, result.stderr)
        for stem in PAPER_FIGURES:
            path = os.path.join(self.figures(), f"{stem}.svg")
            self.assertTrue(os.path.isfile(path), f"{path} missing")
        # Each study's own set stays beside them, and its results under results/.
        self.assertTrue(os.path.isfile(os.path.join(self.figures(), "friction_coefficient",
                                                    "fig06_f_eff_vs_load.svg")))
        self.assertTrue(os.path.isfile(os.path.join(self.tmp, "paper", "results", "sliding_choice",
                                                    "sliding.csv")))
        with open(self.log, encoding="utf-8") as f:
            runs = f.read().splitlines()
        self.assertEqual([os.path.basename(r.split()[1]) for r in runs],
                         ["paper_load_sweeps.yaml", "friction_coefficient.yaml", "sliding_choice.yaml"])
        for r in runs:
            self.assertIn("--set mesh.radial_nodes=5 --set mesh.circumferential_nodes=24", r)

    def test_full_mesh_has_no_overrides(self):
        result = self.run_script()
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(self.log, encoding="utf-8") as f:
            self.assertNotIn("--set", f.read())

    def test_a_failed_study_is_reported_and_the_rest_written(self):
        d = os.path.join(self.fixtures, "sliding_choice")
        os.remove(os.path.join(d, "sliding.csv"))
        write(os.path.join(d, "FAIL"), ["solver failure"])
        result = self.run_script()
        self.assertEqual(result.returncode, 1, result.stderr)
        self.assertIn("failure for sliding_choice", result.stderr)
        self.assertIn("sliding_comparison.svg was not written", result.stderr)
        self.assertTrue(os.path.isfile(os.path.join(self.figures(), "fig15_stribeck_by_friction.svg")))

    def test_usage_errors_exit_2(self):
        for args in (["--bogus"], ["--out"]):
            with self.subTest(args=args):
                result = subprocess.run(["sh", SCRIPT, *args], capture_output=True, text=True, timeout=60)
                self.assertEqual(result.returncode, 2)
                self.assertIn("--quick", result.stderr)
        result = subprocess.run(["sh", SCRIPT, "--twb", os.path.join(self.tmp, "no_twb")],
                                capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 2)
        self.assertIn("no twb binary", result.stderr)


if __name__ == "__main__":
    unittest.main()
