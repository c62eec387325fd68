"""scripts/grooved_washer_summary.py: the grooved-washer study's tables and figures.

    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import csv
import os
import unittest

from result_files import ScriptOnResults, write


DISTRESS_HEADER = "speed_rad_s,{}W_fail_N,criterion,W_d_N,W_oil_temperature_N,W_oil_peak_temperature_N\n"
STATES = ("speed_rad_s,load_N,branch,T_mean_C,T_max_C,heat_carried_W,Q_supply_l_min\n"
          "545,50,cool,26,60,2,0.05\n"
          "545,150,cool,30,100,6,0.07\n"
          "545,400,hot,90,300,20,0.09\n")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class GroovedWasherSummary(ScriptOnResults):
    SCRIPT = "grooved_washer_summary.py"

    def test_variants_and_groove_maps_become_tables_and_figures(self):
        write(os.path.join(self.root, "fed_convection", "distress.csv"),
              DISTRESS_HEADER.format("") + "545,122.5,oil_peak_temperature,,802,122.5\n")
        write(os.path.join(self.root, "fed_convection", "states.csv"), STATES)
        write(os.path.join(self.root, "groove_count", "distress.csv"),
              DISTRESS_HEADER.format("groove_count,") +
              "545,3,131,oil_peak_temperature,,900,131\n"
              "545,12,73.2,oil_peak_temperature,2981,1431,73.2\n")
        run = self.run_script(self.root)
        self.assertEqual(run.returncode, 0, run.stderr)
        summary = rows(os.path.join(self.root, "summary.csv"))
        self.assertEqual(len(summary), 1)
        self.assertEqual(summary[0]["criterion"], "oil_peak_temperature")
        # The washer's temperature at 100 N, between the cool states at 50 and 150 N.
        self.assertAlmostEqual(float(summary[0]["T_mean_C_at_100N"]), 28.0)
        grooves = rows(os.path.join(self.root, "groove_parameters.csv"))
        self.assertEqual([(g["parameter"], float(g["value"])) for g in grooves],
                         [("groove_count", 3.0), ("groove_count", 12.0)])
        self.assertEqual(float(grooves[1]["W_d_N"]), 2981.0)
        self.assertEqual(grooves[0]["W_d_N"], "")  # no fold up to load_end
        for figure in ("grooved_washers.png", "groove_parameters.png"):
            self.assertGreater(os.path.getsize(os.path.join(self.root, figure)), 1000)

    def test_without_groove_maps_there_is_no_groove_table(self):
        write(os.path.join(self.root, "flat", "distress.csv"),
              DISTRESS_HEADER.format("") + "545,113,oil_peak_temperature,,374,113\n")
        write(os.path.join(self.root, "flat", "states.csv"), STATES)
        run = self.run_script(self.root)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.root, "groove_parameters.csv")))

    def test_no_results_is_bad_usage(self):
        self.assertEqual(self.run_script(self.root).returncode, 2)
        self.assertEqual(self.run_script().returncode, 2)


if __name__ == "__main__":
    unittest.main()
