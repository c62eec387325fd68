"""scripts/path_dependence_summary.py: the path-dependence study's table and figure.

    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import csv
import os
import unittest

from result_files import ScriptOnResults, write

TRAJECTORY = ("t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,fluid_share,"
              "regime,heat_generated_W,heat_to_ambient_W,ambient_C,tilt_rad,least_margin,least_margin_criterion\n")
EVENTS = "t_s,event,criterion,load_N,speed_rad_s,ambient_C,tilt_rad,margin,failure_load_N,failure_criterion\n"


class PathDependenceSummary(ScriptOnResults):
    SCRIPT = "path_dependence_summary.py"

    def write_path(self, name, hot):
        """A path's results: cool (contact share 0.007) or hot (0.61) at its end, with a
        runaway and its end where hot."""
        end = "76,318,1.37,0.61,0.165" if hot else "32.4,42.6,3.04,0.007,0.027"
        write(os.path.join(self.root, name, "trajectory.csv"),
              TRAJECTORY + "0,31,34,6.2,0,0.04,100,400,0.03,1,full_film,18,18,24,0.002,0.93,oil_peak_temperature\n"
              f"240,{end},175,545,0.2,0.4,mixed,60,60,24,0.002,0.5,oil_peak_temperature\n")
        write(os.path.join(self.root, name, "cycle_events.csv"),
              EVENTS + ("26.5,runaway,,175,400,24,0.002,0.6,,\n54.6,settled,,175,400,24,0.002,-0.8,,\n" if hot else "")
              + "240,end,,175,545,24,0.002,0.5,,\n")

    def test_each_path_where_it_ended(self):
        for name in ("speed_first", "brief_overload"):
            self.write_path(name, hot=False)
        for name in ("load_first", "long_overload"):
            self.write_path(name, hot=True)
        result = self.run_script(self.root)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.root, "summary.csv")) as f:
            rows = {r["path"]: r for r in csv.DictReader(f)}
        self.assertEqual([rows[p]["branch"] for p in ("speed_first", "load_first", "brief_overload", "long_overload")],
                         ["cool", "hot", "cool", "hot"])
        self.assertEqual(rows["load_first"]["runaway_s"], "26.50")
        self.assertEqual(rows["load_first"]["settled_s"], "54.60")
        self.assertEqual(rows["speed_first"]["runaway_s"], "")
        self.assertIn("| load first (past W_d at 400 rad/s), then speed | 175 N, 545 rad/s | 76.0 | 318.0 |",
                      result.stdout)
        self.assertGreater(os.path.getsize(os.path.join(self.root, "path_dependence.png")), 1000)

    def test_a_missing_path_is_an_error(self):
        self.write_path("speed_first", hot=False)
        result = self.run_script(self.root)
        self.assertEqual(result.returncode, 1)
        self.assertIn("load_first", result.stderr)


if __name__ == "__main__":
    unittest.main()
