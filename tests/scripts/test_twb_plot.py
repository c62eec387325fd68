"""twb.plot (python/twb/plot/) and its command line, scripts/twb_plot.py, on small
synthetic results directories.

Run with Debian's interpreter (the one with python3-matplotlib):
    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCRIPT = os.path.join(ROOT, "scripts", "twb_plot.py")
PYTHON_DIR = os.path.join(ROOT, "python")
sys.path.insert(0, PYTHON_DIR)
import twb.plot as tp  # noqa: E402  (the readers, beside the script's command line)
import matplotlib.legend  # noqa: E402  (after twb.plot, which chooses the backend)
import matplotlib.pyplot as plt  # noqa: E402

STATES_HEADER = ("load_N,speed_rad_s,T_mean_C,T_max_C,hmin_over_sigma,gamma_x_ratio,gamma_y_ratio,"
                 "fluid_share,contact_share,torque_Nm,f_eff,stribeck,converged,iterations,residual,"
                 "energy_error,wall_ms")

STATE_FIGURES = (
    "fig06_f_eff_vs_load", "fig07_mean_temperature_vs_load", "fig08_hmin_over_sigma_vs_load",
    "fig09_gamma_x_ratio_vs_load", "fig10_gamma_y_ratio_vs_load", "fig11_fluid_share_vs_load",
    "fig12_contact_share_vs_load", "fig13_contact_share_vs_hmin", "fig14_stribeck")


def state_rows(speed, loads, unconverged_at=None):
    """Plausible-looking states: the film thins and contact takes over as the load grows."""
    rows = []
    for load in loads:
        lift = speed / 545.0
        h = 0.5 + 6.0 * lift * math.exp(-load / 800.0)
        contact = 1.0 / (1.0 + math.exp(2.5 * (h - 3.0)))
        # An exactly zero contact share must not break the logarithmic Fig. 12.
        if load == loads[0] and speed > 500:
            contact = 0.0
        f_eff = 0.02 + 0.12 * contact
        rows.append(",".join(str(v) for v in (
            load, speed, 24 + 0.02 * load * (1 + contact), 30 + 0.05 * load, h, 0.2 * lift,
            0.5 + 0.5 * (1 - contact), 1 - contact, contact, f_eff * load * 0.008, f_eff,
            0.04 * speed / (2 * math.pi) / (load / 3.1e-4), 0 if load == unconverged_at else 1,
            12, "1.0e-12", "3.0e-15", "12.5")))
    return rows


def trajectory_rows(tail=""):
    """tail: the cells after load_N (speed_rad_s and the run's columns), e.g. ",545"."""
    rows = []
    for k in range(20):
        t = 0.5 * k
        runaway = math.exp(0.4 * t) - 1
        rows.append(f"{t},{30 + 5 * runaway},{40 + 9 * runaway},{max(4.0 - 0.3 * runaway, 0.4)},"
                    f"{min(0.001 * (1 + runaway), 1.0)},{0.02 + 0.01 * runaway},1200{tail}")
    return rows


# distress.csv as twb writes it since every failure criterion is located, after the run's columns.
DISTRESS_FAIL_TAIL = (
    "W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N,W_d_N,bracket_low_N,bracket_high_N,fold_N,"
    "W_d_fine_N,W_d_extrapolated_N,W_d_error_N,W_oil_temperature_N,W_oil_peak_temperature_N,"
    "W_material_temperature_carrier_N,W_material_temperature_washer_N,W_material_temperature_gear_N,"
    "W_film_ratio_N,W_oil_temperature_error_N,W_oil_peak_temperature_error_N,"
    "W_material_temperature_carrier_error_N,W_material_temperature_washer_error_N,"
    "W_material_temperature_gear_error_N,W_film_ratio_error_N,failure,method")


def distress_fail_row(header, cells):
    """A row of a distress.csv header: the named cells, the others empty."""
    return ",".join(str(cells.get(c, "")) for c in header.split(","))


# A grid of two axes (a named parameter and an input by its scene path) at two speeds.
GRID_AXES = "friction_coefficient,geometry.gear.tilt_rad"
GRID = [(f, t) for f in (0.1, 0.3) for t in (0.001, 0.002)]
GRID_SPEEDS = (136, 545)


def grid_distress(limited=(), unreached=()):
    """distress.csv of the grid: (header, rows, W_d by (speed, f, t)). W_d falls with the
    coefficient and the tilt and rises with the speed, each combination its own; a
    combination in `limited` fails first by the oil's peak temperature, 100 N below, with no
    W_d, one in `unreached` finds no failure up to 2000 N (both left out of W_d)."""
    header = f"speed_rad_s,{GRID_AXES},{DISTRESS_FAIL_TAIL}"
    w_d, rows = {}, []
    for speed in GRID_SPEEDS:
        for f, t in GRID:
            w = round(1200 - 1000 * f - 1e5 * t + 0.2 * speed, 6)
            cells = {"speed_rad_s": speed, "friction_coefficient": f, "geometry.gear.tilt_rad": t}
            if (f, t) in unreached:
                cells["method"] = "no fold up to 2000 N (gradual heating)"
            elif (f, t) in limited:
                cells.update({"W_fail_N": w - 100, "criterion": "oil_peak_temperature",
                              "W_oil_peak_temperature_N": w - 100,
                              "failure": f"fails at {w - 100} N by the oil's peak temperature",
                              "method": "no fold up to 2000 N (gradual heating)"})
            else:
                w_d[(speed, f, t)] = w
                cells.update({"W_fail_N": w, "criterion": "distress", "W_d_N": w, "bracket_low_N": w - 2,
                              "bracket_high_N": w + 2, "fold_N": w,
                              "failure": f"fails at {w} N by thermo-viscous distress",
                              "method": f"runaway; fold at {w} N"})
            rows.append(distress_fail_row(header, cells))
    return header, rows, w_d


def with_run_columns(rows, cells):
    """States rows with run cells (e.g. "0.1," or "washer_gear,") after the speed."""
    out = []
    for row in rows:
        load, speed, rest = row.split(",", 2)
        out.append(f"{load},{speed},{cells}{rest}")
    return out


SLIDING_HEADER = ("speed_rad_s,load_N,sliding,film_area_m2,fluid_force_N,fluid_share,contact_share,"
                  "torque_Nm,f_eff,hmin_over_sigma,T_mean_C,chosen")


def sliding_rows(speed, loads):
    """Film 1 (the washer's annulus) lifts more and rubs less than film 2 (the gear's)."""
    rows = []
    for load in loads:
        for film, area, lift in (("carrier_washer", 3.0794e-4, 1.0), ("washer_gear", 2.1357e-4, 0.7)):
            fluid = lift * load * math.exp(-load / 400.0) * speed / 545.0
            torque = 0.002 * load * (1.2 - 0.5 * lift * math.exp(-load / 400.0))
            rows.append(f"{speed},{load},{film},{area},{fluid},{fluid / load},{1 - fluid / load},"
                        f"{torque},{torque / load / 0.008},{3 * lift},{30 + load / 20},"
                        f"{1 if film == 'carrier_washer' else 0}")
    return rows


# A calibration study's tables as a real run wrote them (two inputs fitted to torques and
# a mean temperature, relative: the readings have no sd).
CALIBRATION = ["parameter,parameter_unit,start,lower,upper,fitted,sd,at_bound",
               "lubricant.viscosity.G0,1,3.545,2.5,5,3.9,1.149350494e-10,",
               "surfaces.asperities.summit_radius,m,2e-05,1e-05,4e-05,2.400000164e-05,4.014595666e-12,"]
CALIBRATION_CORRELATION = [
    "parameter_a,parameter_b,covariance,correlation",
    "lubricant.viscosity.G0,lubricant.viscosity.G0,1.321006557e-20,1",
    "lubricant.viscosity.G0,surfaces.asperities.summit_radius,2.581916048e-22,0.559561491",
    "surfaces.asperities.summit_radius,surfaces.asperities.summit_radius,1.611697836e-23,1"]
CALIBRATION_POINTS = ["point,line,load_N,speed_rad_s,quantity,measured,at_start,fitted,sd,residual",
                      "1,3,100,300,torque_Nm,0.03787066079,0.02765355743,0.03787066079,,1e-10",
                      "1,3,100,300,T_mean_C,28.22709602,27.08629111,28.22709602,,-2e-10",
                      "2,4,115,300,torque_Nm,0.03967643456,0.04158691243,0.03967643456,,0"]


FIELDS_HEADER = "film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s"


def fields_rows(nr=5, nt=12):
    """A tilted film 1 that slides (pressure before its thin side at theta = 0, contact at
    the outer rim there) and a film 2 without pressure, as twb writes them."""
    rows = []
    for film, (r_in, r_out) in ((1, (5.55e-3, 11.35e-3)), (2, (7.8e-3, 11.35e-3))):
        for i in range(nr):
            r = r_in + (r_out - r_in) * i / (nr - 1)
            for j in range(nt):
                theta = 2 * math.pi * j / nt
                h = 4e-6 - 3e-4 * r * math.cos(theta)
                edge = 0 < i < nr - 1
                p = 2e6 * max(math.sin(-theta), 0.0) * (1 - math.cos(theta)) if film == 1 and edge else 0.0
                contact = 5e7 * math.exp(-h / 3e-7)
                rows.append(f"{film},{1 if film == 1 else 0},{r:.10g},{theta:.10g},{h:.10g},{p:.10g},"
                            f"{contact:.10g},{40 + 20 * contact / 5e7},{35},{0.03}")
    return rows


def write(path, lines):
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def run_json(directory, friction):
    with open(os.path.join(directory, "run.json"), "w", encoding="utf-8") as f:
        json.dump({"scene_file": "scene.yaml", "outcome": "ok", "scene": {"friction": friction}}, f)


def plot(*args):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True, env=env,
                          timeout=300)


class TwbPlotTest(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="twb_plot_test_")
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def results_dir(self, name, speeds=(136, 545), distress=None, trajectory=False, friction=None,
                    fields=()):
        d = os.path.join(self.tmp, name)
        os.makedirs(d)
        rows = []
        for speed in speeds:
            rows += state_rows(speed, [100, 300, 500, 700, 900, 1100, 1300], unconverged_at=1300)
        write(os.path.join(d, "states.csv"), [STATES_HEADER] + rows)
        if distress is not None:
            write(os.path.join(d, "distress.csv"), distress)
        if trajectory:
            write(os.path.join(d, "trajectory.csv"),
                  ["t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N"] + trajectory_rows())
        if friction is not None:
            run_json(d, friction)
        if fields:
            os.makedirs(os.path.join(d, "fields"))
            for state in fields:
                write(self.fields_file(d, state), [FIELDS_HEADER] + fields_rows())
        return d

    @staticmethod
    def fields_file(directory, state):
        return os.path.join(directory, "fields", f"state_{state:04d}.csv")

    def assert_figures(self, out_dir, stems, formats=("png", "svg")):
        for stem in stems:
            for fmt in formats:
                path = os.path.join(out_dir, f"{stem}.{fmt}")
                self.assertTrue(os.path.isfile(path), f"{path} missing")
                self.assertGreater(os.path.getsize(path), 0, f"{path} empty")
                if fmt == "png":
                    with open(path, "rb") as f:
                        self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", path)
                if fmt == "svg":
                    root = ET.parse(path).getroot()
                    self.assertTrue(root.tag.endswith("svg"), path)

    def grid_results(self, name, limited=(), unreached=()):
        """A results directory of a load sweep and distress map over GRID (grid_distress):
        distress.csv, states.csv and two runs' trajectories; (directory, distress.csv's
        header, its rows, W_d by (speed, f, t))."""
        d = os.path.join(self.tmp, name)
        os.makedirs(d)
        header, rows, w_d = grid_distress(limited, unreached)
        write(os.path.join(d, "distress.csv"), [header] + rows)
        states = []
        for f, t in GRID:
            for speed in GRID_SPEEDS:
                states += with_run_columns(state_rows(speed, [100, 400, 700, 1000]), f"{f},{t},")
        write(os.path.join(d, "states.csv"),
              [STATES_HEADER.replace("speed_rad_s,", f"speed_rad_s,{GRID_AXES},")] + states)
        write(os.path.join(d, "trajectory.csv"),
              [f"t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,{GRID_AXES}"]
              + trajectory_rows(",545,0.1,0.001") + trajectory_rows(",545,0.3,0.002"))
        return d, header, rows, w_d

    @staticmethod
    def legends(ax):
        """Every legend of the axes (a second one added as an artist included)."""
        return [c for c in ax.get_children() if isinstance(c, matplotlib.legend.Legend)]

    @staticmethod
    def extents(fig, artists):
        """The artists' boxes on the laid-out figure, as save() lays it out."""
        fig.tight_layout()
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        return [a.get_window_extent(renderer) for a in artists]

    def svg_text(self, path):
        with open(path, encoding="utf-8") as f:
            return f.read()

    def test_every_figure_from_one_directory(self):
        d = self.results_dir(
            "sweep",
            distress=["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
                      # Free-text method with a comma, and no fold: the empty cell.
                      "545,1117,1110,1125,,runaway; no fold: the branch goes on, smoothly",
                      "136,,,,,not reached below 2000 N"],
            trajectory=True, friction={"law": "empirical"})
        result = plot(d)
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        stems = STATE_FIGURES + ("distress_map", "transient_trajectory")
        self.assert_figures(out_dir, stems)
        # One friction law only: Fig. 15 compares several.
        self.assertFalse(os.path.exists(os.path.join(out_dir, "fig15_stribeck_by_friction.png")))
        listed = set(result.stdout.split())
        expected = {os.path.join(out_dir, f"{s}.{fmt}") for s in stems for fmt in ("png", "svg")}
        self.assertEqual(listed, expected)
        self.assertIn("136 rad/s", result.stderr)  # the speed without distress is reported
        fig6 = self.svg_text(os.path.join(out_dir, "fig06_f_eff_vs_load.svg"))
        for text in ("136 rad/s", "545 rad/s", "distress load", "not converged"):
            self.assertIn(text, fig6)
        # Fig. 14 marks where the paper puts the optimum (Figs. 14 and 16, text).
        fig14 = self.svg_text(os.path.join(out_dir, "fig14_stribeck.svg"))
        for text in ("paper, numerical: optimum near 2.0e-6", "paper, experiments: optimum near 1.0e-6"):
            self.assertIn(text, fig14)

    def test_directories_are_merged(self):
        a = self.results_dir("f_empirical", speeds=(136,), friction={"law": "empirical"})
        b = self.results_dir("f_constant", speeds=(545, 953),
                             friction={"law": "constant", "coefficient": 0.2})
        out_dir = os.path.join(self.tmp, "figs")
        result = plot(a, b, "--out", out_dir, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(out_dir, STATE_FIGURES + ("fig15_stribeck_by_friction",), formats=("svg",))
        self.assertFalse(any(name.endswith(".png") for name in os.listdir(out_dir)))
        self.assertFalse(os.path.exists(os.path.join(a, "figures")))
        fig6 = self.svg_text(os.path.join(out_dir, "fig06_f_eff_vs_load.svg"))
        for speed in ("136 rad/s", "545 rad/s", "953 rad/s"):
            self.assertIn(speed, fig6)
        fig15 = self.svg_text(os.path.join(out_dir, "fig15_stribeck_by_friction.svg"))
        self.assertIn("dry friction coefficient 0.2", fig15)

    def test_distress_map_with_second_parameter(self):
        d = self.results_dir(
            "map",
            distress=["speed_rad_s,friction_coefficient,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
                      "545,0.1,1117,1110,1125,1119,runaway; fold at 1119 N",
                      "953,0.1,1728,1720,1735,,runaway; no fold",
                      "545,0.3,900,895,905,902,runaway; fold at 902 N",
                      "953,0.3,1400,1390,1410,1405,runaway; fold at 1405 N"])
        out_dir = os.path.join(self.tmp, "figs")
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(out_dir, STATE_FIGURES + ("distress_map",))
        text = self.svg_text(os.path.join(out_dir, "distress_map.svg"))
        for label in ("dry friction coefficient 0.1", "dry friction coefficient 0.3",
                      "fold of the steady branch"):
            self.assertIn(label, text)
        # One axis is no grid: no small multiples.
        self.assertFalse(any(name.startswith("distress_grid") for name in os.listdir(out_dir)))

    def test_distress_map_over_an_input_by_its_scene_path(self):
        """A map's axis named by a scene path: its column is the path with its unit, the
        only kind of column with a dot, read as the run's parameter."""
        d = self.results_dir(
            "map_path",
            distress=["speed_rad_s,materials.carrier.conductivity_W_m_K,W_d_N,bracket_low_N,bracket_high_N,fold_N,"
                      "method",
                      "545,30,142.9,142.7,143.0,142.9,runaway; fold at 142.9 N",
                      "545,90,173.3,173.1,173.4,173.3,runaway; fold at 173.3 N"])
        out_dir = os.path.join(self.tmp, "figs_path")
        result = plot(d, "--out", out_dir, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "distress_map.svg"))
        for label in ("materials.carrier.conductivity_W_m_K = 30", "materials.carrier.conductivity_W_m_K = 90"):
            self.assertIn(label, text)

    def test_distress_map_with_error_bars(self):
        """distress.csv as twb writes it with study.error_estimate: richardson: the three
        columns before the method, drawn as the mesh-converged W_d with its bar; a row
        without an estimate keeps empty cells."""
        d = self.results_dir(
            "map_error",
            distress=["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,"
                      "W_d_extrapolated_N,W_d_error_N,method",
                      "545,188.38,188.19,188.57,188.38,198.58,201.98,4.25,\"runaway; fold at 188.381 N, proven\"",
                      "953,221.5,221.28,221.72,221.5,,,,runaway; fold at 221.497 N",
                      "136,,,,,,,,no fold up to 2000 N (gradual heating)"])
        out_dir = os.path.join(self.tmp, "figs_error")
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "distress_map.svg"))
        self.assertIn("mesh-converged W_d (Richardson)", text)
        rows = tp.read_distress(os.path.join(d, "distress.csv"))
        self.assertEqual([(r.extrapolated, r.error) for r in rows], [(201.98, 4.25), (None, None), (None, None)])
        self.assertEqual(rows[0].method, "runaway; fold at 188.381 N, proven")

    def test_failure_load_on_the_map_and_load_axes(self):
        """distress.csv with W_fail and its criterion (a limit crossed before any distress):
        the map draws W_fail named by its criterion, the load figures mark it, and --rpm
        gives the legends' speeds in rpm too."""
        fail = ("speed_rad_s,W_fail_N,criterion,W_fail_extrapolated_N,W_fail_error_N,W_d_N,bracket_low_N,"
                "bracket_high_N,fold_N,W_d_fine_N,W_d_extrapolated_N,W_d_error_N,W_oil_temperature_N,"
                "W_oil_peak_temperature_N,W_material_temperature_carrier_N,W_material_temperature_washer_N,"
                "W_material_temperature_gear_N,W_film_ratio_N,W_oil_temperature_error_N,"
                "W_oil_peak_temperature_error_N,W_material_temperature_carrier_error_N,"
                "W_material_temperature_washer_error_N,W_material_temperature_gear_error_N,W_film_ratio_error_N,"
                "failure,method")
        d = self.results_dir(
            "failure",
            distress=[fail,
                      "136,650,oil_peak_temperature,655,3,,,,,,,,,650,,,,,,3,,,,,"
                      "\"fails at 650.00 N by the oil's peak temperature (no thermo-viscous distress up to 1300 N)\","
                      "no fold up to 1300 N (gradual heating)",
                      "545,188.4,distress,202,4.3,188.4,188.2,188.6,188.4,198.6,202,4.3,,,,,,,,,,,,,"
                      "fails at 188.40 N by thermo-viscous distress,runaway; fold at 188.4 N"])
        rows = tp.read_distress(os.path.join(d, "distress.csv"))
        self.assertEqual([(r.failure, r.criterion) for r in rows], [(650.0, "oil_peak_temperature"), (188.4, "distress")])
        out_dir = os.path.join(self.tmp, "figs_failure")
        result = plot(d, "--out", out_dir, "--rpm")
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "distress_map.svg"))
        self.assertIn("oil's peak temperature", text)
        self.assertIn("a limit crossed first", text)
        text = self.svg_text(os.path.join(out_dir, "fig07_mean_temperature_vs_load.svg"))
        self.assertIn("failure load", text)
        self.assertIn(f"{545 * 60 / (2 * math.pi):.4g} rpm", text)
        self.assertNotIn("545 rad/s", text)

    def test_states_error_bars_on_the_load_figures(self):
        """states.csv with the states' error bars (error_estimate: every_state): read as
        columns, NaN where a state has none, and drawn on the load figures of the quantities
        that have them, with their legend entry; a figure of a quantity without bars has
        neither."""
        d = os.path.join(self.tmp, "state_bars")
        os.makedirs(d)
        quantities = ("T_mean_C", "T_max_C", "hmin_over_sigma", "torque_Nm", "f_eff")
        header = STATES_HEADER + "," + ",".join(f"{q}_{p}" for q in quantities for p in ("extrapolated", "error"))
        rows = state_rows(545, [100, 300, 500])
        # The first state without a bar (empty cells), the others with one.
        bars = ["," * 9] + [",".join(["40", "2", "50", "3", "3.5", "0.2", "0.1", "0.01", "0.03", "0.002"])] * 2
        write(os.path.join(d, "states.csv"), [header] + [r + "," + b for r, b in zip(rows, bars)])
        states, _ = tp.read_states(os.path.join(d, "states.csv"))
        self.assertTrue(math.isnan(states["T_mean_C_error"][0]))
        self.assertEqual(list(states["T_mean_C_error"][1:]), [2.0, 2.0])
        out_dir = os.path.join(self.tmp, "figs_state_bars")
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("its error bar", self.svg_text(os.path.join(out_dir, "fig07_mean_temperature_vs_load.svg")))
        self.assertNotIn("its error bar", self.svg_text(os.path.join(out_dir, "fig11_fluid_share_vs_load.svg")))

    def test_limit_curves_beside_the_fold(self):
        """fold_curve.csv with failure criteria's crossings (their name in the fold column):
        each curve is drawn and labelled by its criterion, and the safe region is below the
        lowest curve, also where no fold exists (gradual heating is not read as safe)."""
        tail = "T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff"
        d = self.results_dir(
            "limits",
            distress=["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
                      "100,,,,,no fold up to 4000 N (gradual heating)",
                      "600,424.3,424,424.7,424.3,runaway; fold at 424.3 N"])
        curve = [f"speed_rad_s,W_fold_N,fold,{tail}",
                 "600,424.3,distress,90,180,2.7,0.014,0.028",
                 "433,348.5,cusp,95,190,2.5,0.02,0.03",
                 "100,296.8,oil_peak_temperature,85,180,4.2,0.0,0.02",
                 "430,346.5,oil_peak_temperature,95,180,2.6,0.02,0.03",
                 "100,683.9,material_temperature:washer,110,300,1.5,0.1,0.05",
                 "430,348.7,material_temperature:washer,96,195,2.5,0.02,0.03"]
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join(curve) + "\n")
        out_dir = os.path.join(self.tmp, "figs_limits")
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "fold_curve.svg"))
        for label in ("oil's peak temperature crossed", "washer's material temperature crossed",
                      "safe: below every criterion", "fails: past the lowest curve"):
            self.assertIn(label, text)
        column, rows = tp.read_fold_curve(os.path.join(d, "fold_curve.csv"))
        self.assertEqual(sorted({r["fold"] for r in rows}),
                         ["cusp", "distress", "material_temperature:washer", "oil_peak_temperature"])

    def test_fold_curve_as_safe_operating_region(self):
        """fold_curve.csv of a distress_curve study: the figure shades the safe region,
        marks the cusp (in rpm with --rpm) and keeps the search without W_d as '> load_end'
        on the distress map; a damaged fold column is an input error with its line."""
        tail = "T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff"
        d = self.results_dir(
            "curve",
            distress=["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,W_d_fine_N,"
                      "W_d_extrapolated_N,W_d_error_N,method",
                      "136,,,,,,,,no fold up to 2000 N (gradual heating)",
                      "2000,227.5,227.3,227.8,227.5,,,,runaway; fold at 227.5 N"])
        curve = [f"speed_rad_s,W_fold_N,fold,{tail}",
                 "2000,227.5,distress,64.9,132.9,2.7,0.014,0.028",
                 "1000,223.0,distress,50.0,120.0,2.5,0.02,0.03",
                 "400,165.0,distress,38.0,108.0,1.95,0.15,0.06",
                 "381.18,162.2,cusp,37.5,106.2,1.89,0.19,0.067",
                 "400,163.9,recovery,40.0,110.0,1.85,0.2,0.07",
                 "1000,151.0,recovery,45.0,115.0,1.7,0.3,0.08",
                 "2000,126.0,recovery,50.0,120.0,1.5,0.4,0.09"]
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join(curve) + "\n")
        out_dir = os.path.join(self.tmp, "figs_curve")
        result = plot(d, "--out", out_dir, "--rpm")
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "fold_curve.svg"))
        for label in ("cusp: sudden distress ends", "no fold: gradual heating", "speed (rpm)",
                      f"cusp {381.18 * 60 / (2 * math.pi):.4g} rpm"):
            self.assertIn(label, text)
        self.assertIn("&gt; 2000 N", self.svg_text(os.path.join(out_dir, "distress_map.svg")))
        column, rows = tp.read_fold_curve(os.path.join(d, "fold_curve.csv"))
        self.assertEqual(column, "speed_rad_s")
        self.assertEqual([r["fold"] for r in rows].count("cusp"), 1)
        # A family of curves: the family's column first, a colour and a cusp per member.
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join(["friction_coefficient," + curve[0]] + [f"{c}," + row for c in (0.1, 0.3)
                                                                       for row in curve[1:]]) + "\n")
        column, rows = tp.read_fold_curve(os.path.join(d, "fold_curve.csv"))
        self.assertEqual({r["member"] for r in rows}, {("friction_coefficient", 0.1), ("friction_coefficient", 0.3)})
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "fold_curve.svg"))
        self.assertIn("dry friction coefficient 0.3", text)
        # With the folds' error bars (study.error_estimate): the mesh-converged curve and
        # its band are drawn, an empty cell reads as None.
        errors = ",W_fold_fine_N,W_fold_extrapolated_N,W_fold_error_N"
        bars = {1: ",238.6,242.3,4.6", 2: ",234.0,237.7,4.6"}  # the rest without a bar
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join([curve[0] + errors] + [row + bars.get(k, ",,,")
                                                     for k, row in enumerate(curve[1:], start=1)]) + "\n")
        column, rows = tp.read_fold_curve(os.path.join(d, "fold_curve.csv"))
        self.assertEqual([r["W_fold_extrapolated_N"] for r in rows[:4]], [242.3, 237.7, None, None])
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("mesh-converged, with its error bar", self.svg_text(os.path.join(out_dir, "fold_curve.svg")))
        # To a tolerance (study.tolerance): how each bar was reached follows; the meshes and
        # the flag read as text, the order as a number, empty cells as None.
        convergence = ",W_fold_meshes,W_fold_order,W_fold_tolerance_met"
        reached = {1: ",9x66 17x132 33x264,1.83,yes", 2: ",9x66 17x132,,no"}
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join([curve[0] + errors + convergence] +
                              [row + bars.get(k, ",,,") + reached.get(k, ",,,")
                               for k, row in enumerate(curve[1:], start=1)]) + "\n")
        column, rows = tp.read_fold_curve(os.path.join(d, "fold_curve.csv"))
        self.assertEqual([r["W_fold_meshes"] for r in rows[:3]], ["9x66 17x132 33x264", "9x66 17x132", None])
        self.assertEqual([r["W_fold_order"] for r in rows[:3]], [1.83, None, None])
        self.assertEqual([r["W_fold_tolerance_met"] for r in rows[:3]], ["yes", "no", None])
        self.assertEqual(plot(d, "--out", out_dir).returncode, 0)
        # The convergence columns without the bar's are no header twb writes.
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join([curve[0] + convergence] + [row + ",,," for row in curve[1:]]) + "\n")
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 2)
        self.assertIn("expected the header", result.stderr)
        with open(os.path.join(d, "fold_curve.csv"), "w", encoding="utf-8") as f:
            f.write("\n".join(curve[:2] + ["1000,223.0,sudden,50.0,120.0,2.5,0.02,0.03"]) + "\n")
        result = plot(d, "--out", out_dir)
        self.assertEqual(result.returncode, 2)
        self.assertIn("line 3: column 'fold': expected one of distress, recovery, cusp, turn", result.stderr)

    def test_load_sweep_over_speeds_and_a_parameter(self):
        """One directory of a load sweep over speeds and friction coefficients: a curve per
        (speed, coefficient), Fig. 15 from the states' own coefficients, one transient
        per speed."""
        d = os.path.join(self.tmp, "friction_sweep")
        os.makedirs(d)
        header = STATES_HEADER.replace("speed_rad_s,", "speed_rad_s,friction_coefficient,")
        rows = []
        for f in (0.05, 0.2):
            for speed in (136, 545):
                rows += with_run_columns(state_rows(speed, [100, 400, 700, 1000]), f"{f},")
        write(os.path.join(d, "states.csv"), [header] + rows)
        write(os.path.join(d, "distress.csv"),
              ["speed_rad_s,friction_coefficient,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
               "136,0.05,,,,,no fold up to 1750 N (gradual heating)",
               "545,0.05,1117,1110,1125,1119,runaway; fold at 1119 N",
               "136,0.2,,,,,no fold up to 1750 N (gradual heating)",
               "545,0.2,900,895,905,902,runaway; fold at 902 N"])
        write(os.path.join(d, "trajectory.csv"),
              ["t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,"
               "friction_coefficient"] + trajectory_rows(",545,0.05") + trajectory_rows(",545,0.2"))
        run_json(d, {"law": "constant", "coefficient": 0.1})
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, STATE_FIGURES + ("fig15_stribeck_by_friction", "distress_map",
                                                      "transient_trajectory"), formats=("svg",))
        fig6 = self.svg_text(os.path.join(out_dir, "fig06_f_eff_vs_load.svg"))
        for label in ("136 rad/s, dry friction coefficient 0.05", "545 rad/s, dry friction coefficient 0.2",
                      "distress load"):
            self.assertIn(label, fig6)
        # The run's own coefficient (0.1 in run.json) labels nothing: each state has its own.
        fig15 = self.svg_text(os.path.join(out_dir, "fig15_stribeck_by_friction.svg"))
        self.assertIn("dry friction coefficient 0.05", fig15)
        self.assertNotIn("dry friction coefficient 0.1<", fig15)
        trajectory = self.svg_text(os.path.join(out_dir, "transient_trajectory.svg"))
        self.assertIn("545 rad/s, dry friction coefficient 0.05, 1200 N", trajectory)
        self.assertIn("545 rad/s, dry friction coefficient 0.2, 1200 N", trajectory)

    def test_grid_of_two_axes(self):
        """A load sweep and distress map over a grid (a named parameter and an input by its
        scene path): one column per axis after the speed, one run per combination, tagged
        with both values in the axes' order, each drawn and labelled with both; a column
        between the speed and W_fail_N that is no parameter is still refused."""
        d, header, rows, w_d = self.grid_results("grid")
        axes, grid = GRID_AXES, GRID

        def tag(f, t):
            return (("friction_coefficient", f), ("geometry.gear.tilt_rad", t))

        read = tp.read_distress(os.path.join(d, "distress.csv"))
        self.assertEqual({(r.speed, r.parameter): r.w_d for r in read},
                         {(speed, tag(f, t)): w for (speed, f, t), w in w_d.items()})
        _, tags = tp.read_states(os.path.join(d, "states.csv"))
        self.assertEqual(len(tags), 4 * 2 * 4)
        self.assertEqual({p for p, _ in tags}, {tag(f, t) for f, t in grid})
        self.assertEqual(tags[0], (tag(0.1, 0.001), None))
        self.assertEqual(tags[-1], (tag(0.3, 0.002), None))
        data = tp.merge([tp.read_run(d)])
        self.assertEqual(tp.states.parameter_order(data.parameters), [tag(f, t) for f, t in grid])
        self.assertEqual([label for label, _ in data.trajectories],
                         ["545 rad/s, dry friction coefficient 0.1, geometry.gear.tilt_rad = 0.001, 1200 N",
                          "545 rad/s, dry friction coefficient 0.3, geometry.gear.tilt_rad = 0.002, 1200 N"])
        # The coefficient axis gives each state its friction setting, as a single axis does.
        self.assertEqual(sorted(set(data.friction)), ["dry friction coefficient 0.1", "dry friction coefficient 0.3"])
        # The same grid in a distress.csv of before W_fail_N (axes read by place): the same tags.
        write(os.path.join(d, "distress.csv"),
              [f"speed_rad_s,{axes},W_d_N,bracket_low_N,bracket_high_N,fold_N,method"]
              + [f"{speed},{f},{t},{w},{w - 2},{w + 2},{w},runaway" for (speed, f, t), w in w_d.items()])
        self.assertEqual([r.parameter for r in tp.read_distress(os.path.join(d, "distress.csv"))],
                         [tag(f, t) for speed, f, t in w_d])
        write(os.path.join(d, "distress.csv"), [header] + rows)

        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, STATE_FIGURES + ("fig15_stribeck_by_friction", "distress_map",
                                                      "distress_grid", "transient_trajectory"), formats=("svg",))
        labels = [f"dry friction coefficient {f}, geometry.gear.tilt_rad = {t}" for f, t in grid]
        distress_map = self.svg_text(os.path.join(out_dir, "distress_map.svg"))
        fig6 = self.svg_text(os.path.join(out_dir, "fig06_f_eff_vs_load.svg"))
        for label in labels:
            self.assertIn(label, distress_map)
            for speed in (136, 545):
                self.assertIn(f"{speed} rad/s, {label}", fig6)
        self.assertIn("545 rad/s, dry friction coefficient 0.3, geometry.gear.tilt_rad = 0.002, 1200 N",
                      self.svg_text(os.path.join(out_dir, "transient_trajectory.svg")))

        # A column between the speed and W_fail_N that is no parameter (no dot, not named).
        bad = header.replace(f"{axes},", "friction_coefficient,tilt,")
        write(os.path.join(d, "distress.csv"), [bad] + rows)
        with self.assertRaises(tp.InputError) as caught:
            tp.read_distress(os.path.join(d, "distress.csv"))
        self.assertIn("line 1: expected the header speed_rad_s[,<parameter>...][,sliding]", str(caught.exception))

    def test_distress_map_names_every_run(self):
        """Every run drawn on the distress map has one legend entry, a run failing only by a
        limit (W_fail crosses, no W_d) too, with one axis and in a grid; a grid's many runs
        put the legend beside the axes, where it covers no data."""
        header = f"speed_rad_s,friction_coefficient,{DISTRESS_FAIL_TAIL}"
        d = self.results_dir("one_axis_limit", distress=[header] + [
            distress_fail_row(header, {"speed_rad_s": 545, "friction_coefficient": 0.1, "W_fail_N": 900,
                                       "criterion": "distress", "W_d_N": 900, "method": "runaway"}),
            distress_fail_row(header, {"speed_rad_s": 545, "friction_coefficient": 0.3, "W_fail_N": 700,
                                       "criterion": "oil_peak_temperature", "W_oil_peak_temperature_N": 700,
                                       "method": "no fold up to 2000 N (gradual heating)"})])
        fig = tp.distress.figure_distress_map(tp.merge([tp.read_run(d)]))
        texts = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
        for f in (0.1, 0.3):
            self.assertEqual(texts.count(f"dry friction coefficient {f}"), 1, texts)
        plt.close(fig)

        d, *_ = self.grid_results("grid_limit", limited=[(0.3, 0.002)])
        fig = tp.distress.figure_distress_map(tp.merge([tp.read_run(d)]))
        ax = fig.axes[0]
        texts = [t.get_text() for t in ax.get_legend().get_texts()]
        runs = [f"dry friction coefficient {f}, geometry.gear.tilt_rad = {t}" for f, t in GRID]
        self.assertEqual([t for t in texts if t.startswith("dry friction")], runs)
        legend, axes, whole = self.extents(fig, [ax.get_legend(), ax, fig])
        self.assertFalse(legend.overlaps(axes), (legend, axes))
        self.assertLessEqual(legend.x1, whole.x1 + 0.5, "the legend leaves the figure")
        plt.close(fig)

    def test_a_search_without_w_d_far_above_leaves_the_load_axis_to_the_loads_found(self):
        """A speed with no W_d up to a load_end far above the map's loads (8000 N against
        300-350 N) is marked at the axis's top, its load in its label: the axis is the loads
        found, not squashed under the search's range."""
        header = f"speed_rad_s,{DISTRESS_FAIL_TAIL}"
        d = self.results_dir("far_load_end", speeds=(136, 545, 953), distress=[header] + [
            distress_fail_row(header, {"speed_rad_s": 136, "method": "no fold up to 8000 N (gradual heating)"}),
            distress_fail_row(header, {"speed_rad_s": 545, "W_fail_N": 300, "criterion": "distress", "W_d_N": 300,
                                       "method": "runaway"}),
            distress_fail_row(header, {"speed_rad_s": 953, "W_fail_N": 350, "criterion": "distress", "W_d_N": 350,
                                       "method": "runaway"})])
        fig = tp.distress.figure_distress_map(tp.merge([tp.read_run(d)]))
        ax = fig.axes[0]
        self.assertAlmostEqual(ax.get_ylim()[1], 1.25 * 350)
        triangles = [line for line in ax.get_lines() if line.get_marker() == "^"]
        self.assertEqual([list(line.get_ydata()) for line in triangles], [[1.25 * 350]])
        self.assertIn("> 8000 N", [t.get_text() for t in ax.texts])
        plt.close(fig)

    def test_speeds_as_the_scene_gave_them(self):
        """run.json's speed_unit (rpm where the scene gave its speeds in rpm) sets the
        figures' speeds; --rad-s and --rpm override it, and a run.json without it (an
        older run) stays in rad/s."""
        def directory(name, unit):
            d = self.results_dir(name, speeds=(314.159,), friction={"law": "empirical"})
            with open(os.path.join(d, "run.json"), encoding="utf-8") as f:
                record = json.load(f)
            if unit is not None:
                record["speed_unit"] = unit
            with open(os.path.join(d, "run.json"), "w", encoding="utf-8") as f:
                json.dump(record, f)
            return d
        in_rpm = tp.read_run(directory("rpm", "rpm"))
        in_rad_s = tp.read_run(directory("rad_s", "rad/s"))
        older = tp.read_run(directory("older", None))
        self.assertEqual((in_rpm.speed_unit, in_rad_s.speed_unit, older.speed_unit), ("rpm", "rad/s", None))
        self.assertTrue(tp.merge([in_rpm]).rpm)
        self.assertFalse(tp.merge([in_rad_s]).rpm)
        self.assertFalse(tp.merge([older]).rpm)
        self.assertFalse(tp.merge([in_rpm, in_rad_s]).rpm)  # one axis for both: the SI unit
        self.assertFalse(tp.merge([in_rpm], rpm=False).rpm)
        self.assertTrue(tp.merge([in_rad_s], rpm=True).rpm)
        out_dir = os.path.join(self.tmp, "figs_rpm")
        result = plot(in_rpm.directory, "--out", out_dir, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "fig07_mean_temperature_vs_load.svg"))
        self.assertIn("3000 rpm", text)
        self.assertNotIn("314.159 rad/s", text)
        result = plot(in_rpm.directory, "--out", out_dir, "--format", "svg", "--rad-s")
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "fig07_mean_temperature_vs_load.svg"))
        self.assertIn("314.159 rad/s", text)
        self.assertEqual(plot(in_rpm.directory, "--rpm", "--rad-s").returncode, 2)

    def test_the_map_draws_the_mesh_converged_failure_load_and_names_each_criterion_once(self):
        """W_fail by a limit is drawn at its mesh-converged value with its bar (what the run
        prints first), and its criterion is named where it starts to set W_fail, not at
        every speed."""
        header = f"speed_rad_s,{DISTRESS_FAIL_TAIL}"
        rows = [distress_fail_row(header, {"speed_rad_s": w, "W_fail_N": 300 + w / 10, "criterion": c,
                                           "W_fail_extrapolated_N": 320 + w / 10, "W_fail_error_N": 4,
                                           "method": "no fold up to 700 N (not searched further)"})
                for w, c in ((136, "oil_peak_temperature"), (545, "oil_peak_temperature"), (953, "scuffing"))]
        d = self.results_dir("converged", speeds=(136, 545, 953), distress=[header] + rows)
        data = tp.merge([tp.read_run(d)])
        self.assertEqual([r.failure_converged for r in data.distress], [320 + 13.6, 320 + 54.5, 320 + 95.3])
        fig = tp.distress.figure_distress_map(data)
        ax = fig.axes[0]
        crosses = [line for line in ax.get_lines() if line.get_marker() == "X"]
        self.assertEqual(len(crosses), 1)
        self.assertEqual(list(crosses[0].get_ydata()), [320 + 13.6, 320 + 54.5, 320 + 95.3])
        names = [t.get_text() for t in ax.texts]
        self.assertEqual(names.count(tp.distress.LIMIT_LABELS["oil_peak_temperature"]), 1)
        self.assertEqual(names.count(tp.distress.LIMIT_LABELS["scuffing"]), 1)
        self.assertIn("mesh-converged", " ".join(t.get_text() for t in ax.get_legend().get_texts()))
        plt.close(fig)

    def test_the_searched_load_is_the_verdicts_not_a_notes(self):
        """A note before the verdict with a load of its own (the start check's supply bound)
        is not where the search ended; a bounded search's end is its bound."""
        self.assertEqual(tp.distress.searched_up_to(
            "the start's branch could not be checked (the oil supply may hold up to 40.2 N, too near the "
            "start for a lighter load); no fold up to 8000 N (gradual heating)"), 8000.0)
        self.assertEqual(tp.distress.searched_up_to(
            "no fold up to 575.534 N (not searched further: 2 times the first failure at 287.767 N, "
            "study.search_past_failure)"), 575.534)
        self.assertIsNone(tp.distress.searched_up_to("runaway; fold at 188.4 N"))

    def test_states_past_the_failure_load_are_faded(self):
        """States past W_fail (here a limit at 600 N at 545 rad/s) are drawn faded, from the
        last operating state on, with their own legend entry; the operating curve ends at
        or below W_fail; a speed without a failure load is drawn whole."""
        header = f"speed_rad_s,{DISTRESS_FAIL_TAIL}"
        d = self.results_dir("past_failure", distress=[header] + [
            distress_fail_row(header, {"speed_rad_s": 545, "W_fail_N": 600, "criterion": "oil_peak_temperature",
                                       "W_oil_peak_temperature_N": 600,
                                       "method": "no fold up to 1300 N (gradual heating)"}),
            distress_fail_row(header, {"speed_rad_s": 136, "method": "no fold up to 1300 N (gradual heating)"})])
        data = tp.merge([tp.read_run(d)])
        fig = tp.states.figure_vs_load(data, "T_mean_C", "T", "t", None)
        ax = fig.axes[0]
        faded = [line for line in ax.get_lines() if line.get_alpha() == 0.3]
        self.assertEqual(len(faded), 1)
        loads = [x for x, y in zip(faded[0].get_xdata(), faded[0].get_ydata()) if not math.isnan(y)]
        self.assertEqual(min(loads), 500)  # the last operating state, joined to the first past one
        self.assertGreater(min(x for x in loads if x > 500), 600)
        solid = [line for line in ax.get_lines() if line.get_alpha() is None and line.get_label().startswith("545")]
        self.assertEqual(len(solid), 1)
        kept = [x for x, y in zip(solid[0].get_xdata(), solid[0].get_ydata()) if not math.isnan(y)]
        self.assertLessEqual(max(kept), 600)
        self.assertIn("past $W_{fail}$: the washer has failed", [t.get_text() for t in ax.get_legend().get_texts()])
        plt.close(fig)

    def test_distress_grid_small_multiples(self):
        """A grid's failure loads: a panel per speed with a shared load axis, W_fail against
        the first axis (its label the package's), a line per value of the other, a marker
        per criterion and an open triangle at load_end where no failure was found; the
        legends beside the panels, each covering none."""
        d, *_ = self.grid_results("grid_small", limited=[(0.3, 0.002)], unreached=[(0.1, 0.001)])
        result = plot(d, "--format", "png,svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, ("distress_map", "distress_grid"))
        fig = tp.distress.figure_distress_grid(tp.merge([tp.read_run(d)]))
        panels = [ax for ax in fig.axes if ax.get_visible()]
        self.assertEqual([ax.get_title() for ax in panels], ["136 rad/s", "545 rad/s"])
        self.assertEqual({ax.get_xlabel() for ax in panels}, {"dry friction coefficient"})
        self.assertTrue(panels[0].get_shared_y_axes().joined(panels[0], panels[1]))
        # Each panel: W_fail at the first axis's values, per tilt; a point not found breaks
        # the line (NaN) and is drawn at 2000 N instead.
        lines = [line for line in panels[1].get_lines() if line.get_linestyle() == "-"]
        self.assertEqual(len(lines), 2)
        self.assertEqual(list(lines[0].get_xdata()), [0.1, 0.3])
        self.assertTrue(math.isnan(lines[0].get_ydata()[0]))
        self.assertAlmostEqual(lines[1].get_ydata()[1], 1200 - 300 - 200 + 0.2 * 545 - 100)  # the flash limit
        triangles = [line for line in panels[1].get_lines() if line.get_marker() == "^"]
        self.assertEqual([list(line.get_ydata()) for line in triangles], [[2000.0]])
        legends = self.legends(panels[-1])
        texts = [[t.get_text() for t in legend.get_texts()] for legend in legends]
        self.assertIn(["geometry.gear.tilt_rad = 0.001", "geometry.gear.tilt_rad = 0.002"], texts)
        self.assertIn(["thermo-viscous distress (fold)", "oil's peak temperature",
                       "not reached: no failure up to load_end"], texts)
        boxes = self.extents(fig, legends + panels)
        for i, box in enumerate(boxes):
            for other in boxes[i + 1:]:
                self.assertFalse(box.overlaps(other), (box, other))
        plt.close(fig)
        text = self.svg_text(os.path.join(out_dir, "distress_grid.svg"))
        for label in ("dry friction coefficient", "geometry.gear.tilt_rad = 0.002", "545 rad/s"):
            self.assertIn(label, text)

    def test_a_run_of_one_axis_or_none_keeps_its_tag(self):
        """Files of one axis or none read as before the grid: (column, value) or None."""
        d = os.path.join(self.tmp, "one_axis")
        os.makedirs(d)
        for columns, cells, expected in (("", "", None),
                                         ("friction_coefficient,", "0.2,", ("friction_coefficient", 0.2)),
                                         ("geometry.gear.tilt_rad,", ",", ("geometry.gear.tilt_rad", None))):
            header = f"speed_rad_s,{columns}{DISTRESS_FAIL_TAIL}"
            write(os.path.join(d, "distress.csv"), [header, distress_fail_row(header, {
                "speed_rad_s": 545, **dict(zip(columns.split(",")[:-1], cells.split(",")[:-1])),
                "W_fail_N": 188.4, "criterion": "distress", "W_d_N": 188.4, "method": "runaway"})])
            self.assertEqual(tp.read_distress(os.path.join(d, "distress.csv"))[0].parameter, expected)
            write(os.path.join(d, "states.csv"), [STATES_HEADER.replace("speed_rad_s,", "speed_rad_s," + columns)]
                  + with_run_columns(state_rows(545, [100]), cells))
            self.assertEqual(tp.read_states(os.path.join(d, "states.csv"))[1], [(expected, None)])

    def test_sensitivity_tornado(self):
        """sensitivity.csv of a sensitivity study: a tornado of W_fail's elasticities (here
        W_d's: no W_fail rows), the largest on top, rows without an elasticity left out;
        the torque's without a failure load."""
        d = self.results_dir("sensitivity")
        rows = ["quantity,value,parameter,parameter_value,parameter_unit,derivative,elasticity,step",
                "torque_Nm,0.9,operating.load,500,N,0.0013,0.74,0.05",
                "W_d_N,188.4,operating.ambient,297.15,K,-5.48,-8.64,0.0297",
                "W_d_N,188.4,geometry.gear.tilt,0.002,rad,-105613,-1.12,2e-07",
                "W_d_N,188.4,materials.gear.density,7850,kg/m^3,0,,0.785",
                "W_d_N,188.4,lubricant.viscosity.G0,3.545,1,250.8,4.72,0.0003545"]
        write(os.path.join(d, "sensitivity.csv"), rows)
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, ("sensitivity",), formats=("svg",))
        text = self.svg_text(os.path.join(out_dir, "sensitivity.svg"))
        for label in ("operating.ambient", "lubricant.viscosity.G0", "geometry.gear.tilt", "W_d (188.4 N)"):
            self.assertIn(label, text)
        self.assertNotIn("materials.gear.density", text)
        read = tp.read_sensitivity(os.path.join(d, "sensitivity.csv"))
        self.assertEqual(len(read), 5)
        self.assertIsNone(read[3]["elasticity"])
        self.assertEqual(read[1]["parameter"], "operating.ambient")
        write(os.path.join(d, "sensitivity.csv"), rows[:2])
        self.assertEqual(plot(d, "--format", "svg").returncode, 0)
        self.assertIn("friction torque", self.svg_text(os.path.join(out_dir, "sensitivity.svg")))
        write(os.path.join(d, "sensitivity.csv"), rows[:2] + ["W_d_N,188.4,operating.speed,545,rad/s,oops,0.4,0.05"])
        broken = plot(d, "--format", "svg")
        self.assertEqual(broken.returncode, 2)
        self.assertIn("sensitivity.csv: line 3", broken.stderr)

    def test_reliability_figure(self):
        """reliability.csv and design_point.csv of a reliability study: the probability of
        failure against load (FORM, inverse FORM, the sampled estimate with its interval)
        and the importances at FORM's design point; a malformed number is located."""
        d = self.results_dir("reliability")
        rows = ["method,load_N,speed_rad_s,probability,beta,cov,low,high,samples,failures,unresolved,evaluations,converged",
                "form,150,545,0.16,0.994,,,,,,,4,1",
                "monte_carlo,150,545,0.154,,0.098,0.124,0.184,150,72,0,150,1",
                "inverse_form,102.08,545,0.001,3.09,,,,,,,9,1",
                "inverse_form,114.5,545,0.01,2.326,,,,,,,7,1"]
        design = ["method,load_N,probability,parameter,parameter_unit,distribution,mean,sd,lower,upper,"
                  "design_value,u,alpha,importance,derivative",
                  "form,150,0.16,geometry.gear.tilt,rad,truncated_normal,0.002,0.0003,0.001,0.003,0.0022,0.70,0.70,0.49,-79417",
                  "form,150,0.16,materials.washer.conductivity,W/(m K),uniform,,,50,70,60.1,0.01,0.01,0.0001,0.3",
                  "inverse_form,102.08,0.001,geometry.gear.tilt,rad,truncated_normal,0.002,0.0003,0.001,0.003,0.0027,2.2,0.71,0.5,-80000"]
        write(os.path.join(d, "reliability.csv"), rows)
        write(os.path.join(d, "design_point.csv"), design)
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, ("reliability",), formats=("svg",))
        text = self.svg_text(os.path.join(out_dir, "reliability.svg"))
        for label in ("Probability of failure at 545 rad/s", "150 samples", "β = 0.99", "geometry.gear.tilt",
                      "materials.washer.conductivity"):
            self.assertIn(label, text)
        read = tp.read_reliability(os.path.join(d, "reliability.csv"))
        self.assertEqual([r["method"] for r in read], ["form", "monte_carlo", "inverse_form", "inverse_form"])
        self.assertIsNone(read[0]["cov"])
        self.assertEqual(read[1]["samples"], 150)
        points = tp.read_design_point(os.path.join(d, "design_point.csv"))
        self.assertIsNone(points[1]["mean"])
        self.assertEqual(points[1]["parameter_unit"], "W/(m K)")
        write(os.path.join(d, "reliability.csv"), rows[:2] + ["monte_carlo,150,545,oops,,0.1,0.1,0.2,150,72,0,150,1"])
        broken = plot(d, "--format", "svg")
        self.assertEqual(broken.returncode, 2)
        self.assertIn("reliability.csv: line 3", broken.stderr)

    def test_duty_cycle_figure(self):
        """trajectory.csv and cycle_events.csv of a duty cycle: the inputs, the temperatures
        and the least margin against time, the crossing and the runaway marked, the worst
        moment with the failure load there; not drawn as a pseudo-time transient; a
        malformed event is located."""
        d = self.results_dir("duty_cycle")
        header = ("t_s,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff,load_N,speed_rad_s,torque_Nm,"
                  "fluid_share,regime,heat_generated_W,heat_to_ambient_W,ambient_C,tilt_rad,least_margin,"
                  "least_margin_criterion")
        rows = [header]
        for k in range(21):
            t = 3.0 * k
            rows.append(f"{t},{30 + k},{34 + 8 * k},{6 - 0.2 * k},{0.01 * k},0.04,{100 + 5 * k},545,0.03,"
                        f"{1 - 0.01 * k},mixed,18,17,24,0.002,{0.9 - 0.09 * k},oil_peak_temperature")
        events = ["t_s,event,criterion,load_N,speed_rad_s,ambient_C,tilt_rad,margin,failure_load_N,failure_criterion",
                  "40.3,runaway,,200.8,545,24,0.002,0.68,,",
                  "47.5,crossing,oil_peak_temperature,218.7,545,24,0.002,0,,",
                  "60,end,,200,545,24,0.002,-0.9,,",
                  "60,worst,oil_peak_temperature,200,545,24,0.002,-0.9,188.38,distress"]
        write(os.path.join(d, "trajectory.csv"), rows)
        write(os.path.join(d, "cycle_events.csv"), events)
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, ("duty_cycle",), formats=("svg",))
        self.assertFalse(os.path.exists(os.path.join(out_dir, "transient_trajectory.svg")))
        text = self.svg_text(os.path.join(out_dir, "duty_cycle.svg"))
        for label in ("thermo-viscous runaway", "a limit crossed", "fails there at 188.4 N by distress",
                      "least margin"):
            self.assertIn(label, text)
        read = tp.read_cycle_events(os.path.join(d, "cycle_events.csv"))
        self.assertEqual([e["event"] for e in read], ["runaway", "crossing", "end", "worst"])
        self.assertIsNone(read[0]["failure_load_N"])
        write(os.path.join(d, "cycle_events.csv"), events[:2] + ["47.5,crossing,oil_peak_temperature,oops,545,24,0.002,0,,"])
        broken = plot(d, "--format", "svg")
        self.assertEqual(broken.returncode, 2)
        self.assertIn("cycle_events.csv: line 3", broken.stderr)

    def test_life_figure(self):
        """life.csv and worn_profile.csv of a life study: the depths and the failure load
        against time, the face at rest's map and the turning face's profiles; a failure
        load not searched is drawn as a gap; a malformed row is located."""
        d = self.results_dir("life")
        header = ("t_h,worn_depth_rest_max_um,worn_depth_rest_mean_um,worn_volume_rest_mm3,rq_rest_um,"
                  "worn_depth_turn_max_um,worn_depth_turn_mean_um,worn_volume_turn_mm3,rq_turn_um,wear_rate_rest_um_h,"
                  "wear_rate_turn_um_h,torque_Nm,f_eff,T_max_C,hmin_over_sigma,contact_share,W_fail_N,"
                  "failure_criterion,event")
        rows = [header]
        for k in range(3):
            fail = "" if k == 1 else f"{190 + 10 * k}"
            # (the faces run in: their Rq falls)
            rows.append(f"{100 * k},{0.5 * k},{0.01 * k},{0.001 * k},{0.4 - 0.1 * k},{0.05 * k},{0.01 * k},{0.001 * k},"
                        f"{0.3 - 0.05 * k},0.01,0.001,0.04,0.03,35,5,0.001,{fail},{'distress' if fail else ''},"
                        f"{'end' if k == 2 else ''}")
        profile = ["t_h,r_m,theta_rad,worn_rest_um,worn_turn_um,rq_rest_um,rq_turn_um"]
        for k in range(3):
            for i in range(3):
                for j in range(4):
                    profile.append(f"{100 * k},{0.0055 + 0.003 * i},{1.5707963267948966 * j},{0.1 * k * i * (j == 0)},"
                                   f"{0.02 * k * i},{0.4 - 0.05 * k * (j == 0)},0.3")
        write(os.path.join(d, "life.csv"), rows)
        write(os.path.join(d, "worn_profile.csv"), profile)
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, ("life",), formats=("svg",))
        text = self.svg_text(os.path.join(out_dir, "life.svg"))
        for label in ("face at rest, deepest", "turning face, mean", "Rq, face at rest", "failure load",
                      "the life ends at 200 h: lasts its duration",
                      "face at rest, worn at 200 h"):
            self.assertIn(label, text)
        read = tp.read_life(os.path.join(d, "life.csv"))
        self.assertEqual([r["event"] for r in read], ["", "", "end"])
        self.assertIsNone(read[1]["W_fail_N"])
        self.assertEqual(tp.read_worn_profile(os.path.join(d, "worn_profile.csv"))["r_m"].size, 36)
        write(os.path.join(d, "life.csv"), rows[:2] + ["oops" + rows[2][1:]])
        broken = plot(d, "--format", "svg")
        self.assertEqual(broken.returncode, 2)
        self.assertIn("life.csv: line 3", broken.stderr)

    def write_calibration(self, d, calibration=None, correlation=None, points=None):
        """A calibration study's three tables, by default those of a real run (two inputs
        fitted to torques and a mean temperature, a relative fit: no readings' sd)."""
        for name, rows in (("calibration.csv", calibration or CALIBRATION),
                           ("calibration_correlation.csv", correlation or CALIBRATION_CORRELATION),
                           ("calibration_points.csv", points or CALIBRATION_POINTS)):
            write(os.path.join(d, name), rows)

    def test_calibration_figure(self):
        """calibration.csv, calibration_correlation.csv and calibration_points.csv of a
        calibration study: read as rows (None for an empty sd), drawn as a parity plot per
        measured quantity with the fitted inputs beneath; a malformed number is located."""
        d = self.results_dir("calibration")
        self.write_calibration(d)
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, ("calibration",), formats=("svg",))
        text = self.svg_text(os.path.join(out_dir, "calibration.svg"))
        for label in ("2 inputs fitted to 3 measured values at 2 points", "friction torque (N m)",
                      "mean washer temperature (°C)", "at the start", "predicted = measured",
                      "T_mean_C: 1 value, rms relative residual 2e-10",
                      "lubricant.viscosity.G0 = 3.9 ± 1.1e-10 ",
                      "surfaces.asperities.summit_radius = 2.4e-05 ± 4e-12 m"):
            self.assertIn(label, text)
        self.assertNotIn("measured ± its sd", text)  # a relative fit: no error bars
        self.assertNotIn("bound,", text)
        fitted = tp.read_calibration(os.path.join(d, "calibration.csv"))
        self.assertEqual([r["parameter"] for r in fitted],
                         ["lubricant.viscosity.G0", "surfaces.asperities.summit_radius"])
        self.assertEqual((fitted[1]["fitted"], fitted[1]["sd"], fitted[1]["at_bound"]),
                         (2.400000164e-05, 4.014595666e-12, ""))
        self.assertEqual(fitted[0]["parameter_unit"], "1")
        pairs = tp.read_calibration_correlation(os.path.join(d, "calibration_correlation.csv"))
        self.assertEqual([(r["parameter_a"], r["parameter_b"], r["correlation"]) for r in pairs][1],
                         ("lubricant.viscosity.G0", "surfaces.asperities.summit_radius", 0.559561491))
        points = tp.read_calibration_points(os.path.join(d, "calibration_points.csv"))
        self.assertEqual([(r["point"], r["line"], r["quantity"]) for r in points],
                         [(1, 3, "torque_Nm"), (1, 3, "T_mean_C"), (2, 4, "torque_Nm")])
        self.assertIsNone(points[0]["sd"])
        self.assertEqual(points[1]["at_start"], 27.08629111)
        run = tp.read_run(d)
        self.assertEqual(len(run.calibration_correlation), 3)
        # A fit with the readings' sd, an input on its bound and one the data do not
        # determine (no sd), and no covariance: a header-only correlation table.
        self.write_calibration(
            d, calibration=[CALIBRATION[0], "lubricant.viscosity.G0,1,3.545,2.5,5,5,,upper",
                            "surfaces.asperities.summit_radius,m,2e-05,1e-05,4e-05,2.1e-05,3e-06,"],
            correlation=CALIBRATION_CORRELATION[:1],
            points=[CALIBRATION_POINTS[0], "1,3,100,300,f_eff,0.08,0.07,0.079,0.004,-0.25",
                    "1,3,100,300,T_max_C,41,38,40.5,1.5,-0.33"])
        self.assertEqual(tp.read_calibration_correlation(os.path.join(d, "calibration_correlation.csv")), [])
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        text = self.svg_text(os.path.join(out_dir, "calibration.svg"))
        for label in ("lubricant.viscosity.G0 = 5 ", "at its upper bound", "= 2.1e-05 ± 3e-06 m",
                      "measured ± its sd", "maximum film temperature (°C)",
                      "T_max_C: 1 value, rms residual 0.33 sd"):
            self.assertIn(label, text)
        self.assertNotIn("lubricant.viscosity.G0 = 5 ±", text)
        self.assertNotIn("friction torque", text)
        self.write_calibration(d, points=CALIBRATION_POINTS[:3] + ["2,4,115,300,torque_Nm,0.0397,oops,0.0397,,0"])
        with self.assertRaises(tp.InputError) as caught:
            tp.read_calibration_points(os.path.join(d, "calibration_points.csv"))
        self.assertIn("calibration_points.csv: line 4: column 'at_start'", str(caught.exception))
        broken = plot(d, "--format", "svg")
        self.assertEqual(broken.returncode, 2)
        self.assertIn(os.path.join(d, "calibration_points.csv") + ": line 4", broken.stderr)
        self.write_calibration(d, calibration=CALIBRATION[:2] + ["surfaces.asperities.summit_radius,m,2e-05,,4e-05,"
                                                                  "2.4e-05,,"])
        broken = plot(d, "--format", "svg")
        self.assertEqual(broken.returncode, 2)
        self.assertIn(os.path.join(d, "calibration.csv") + ": line 3: column 'lower'", broken.stderr)

    def test_calibrations_of_several_runs(self):
        """Each directory's calibration gets its own figure, named by its directory; one
        without a measured value is noted, not drawn."""
        a, b, empty = (self.results_dir(name, speeds=(545,)) for name in ("fit_a", "fit_b", "fit_empty"))
        for d in (a, b):
            self.write_calibration(d)
        self.write_calibration(empty, points=CALIBRATION_POINTS[:1])
        written = tp.make_figures(tp.merge([tp.read_run(d) for d in (a, b)]), os.path.join(self.tmp, "figs"), ["svg"])
        self.assertEqual(sorted(os.path.basename(p) for p in written if "calibration" in p),
                         ["calibration_1_fit_a.svg", "calibration_2_fit_b.svg"])
        result = plot(empty, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("fit_empty: calibration_points.csv has no measured value to draw", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(empty, "figures", "calibration.svg")))

    def test_sliding_comparison(self):
        d = os.path.join(self.tmp, "sliding")
        os.makedirs(d)
        header = STATES_HEADER.replace("speed_rad_s,", "speed_rad_s,sliding,")
        write(os.path.join(d, "states.csv"),
              [header] + with_run_columns(state_rows(545, [100, 400, 700]), "carrier_washer,")
              + with_run_columns(state_rows(953, [100, 400, 700]), "carrier_washer,"))
        write(os.path.join(d, "sliding.csv"),
              [SLIDING_HEADER] + sliding_rows(545, [100, 400, 700]) + sliding_rows(953, [100, 400, 700]))
        write(os.path.join(d, "distress.csv"),
              ["speed_rad_s,sliding,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
               "545,carrier_washer,1117,1110,1125,1119,runaway; fold at 1119 N",
               "545,washer_gear,800,795,805,801,runaway; fold at 801 N",
               "953,carrier_washer,,,,,no fold up to 1750 N",
               "953,washer_gear,1500,1490,1510,,runaway; no fold"])
        result = plot(d, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        self.assert_figures(out_dir, STATE_FIGURES + ("distress_map", "sliding_comparison"),
                            formats=("svg",))
        text = self.svg_text(os.path.join(out_dir, "sliding_comparison.svg"))
        for label in ("545 rad/s", "953 rad/s", "film 1 slides (washer stuck to the gear), 307.9 mm²",
                      "film 2 slides (washer stuck to the carrier), 213.6 mm²", "chosen: the lower torque",
                      "30.6 % below", "44.2 % above"):
            self.assertIn(label, text)
        distress = self.svg_text(os.path.join(out_dir, "distress_map.svg"))
        self.assertIn("film 2 slides (washer stuck to the carrier)", distress)
        self.assertIn("953 rad/s, film 1 slides", result.stderr)  # the row without distress
        # A sliding choice's W_d are not marked on the states' load axes: the chosen
        # configuration may change along the sweep.
        self.assertNotIn("distress load", self.svg_text(os.path.join(out_dir, "fig06_f_eff_vs_load.svg")))

    def test_module_and_python_m_write_what_the_script_writes(self):
        """The module's make_figures, called from Python, and `python3 -m twb.plot` write
        the script's files, byte for byte."""
        d = self.results_dir("api", distress=["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
                                              "545,1117,1110,1125,1119,runaway; fold at 1119 N"],
                             trajectory=True)
        script, module, api = (os.path.join(self.tmp, "figs_" + name) for name in ("script", "module", "api"))
        result = plot(d, "--out", script, "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        env = dict(os.environ, MPLBACKEND="Agg",
                   PYTHONPATH=os.pathsep.join(p for p in (PYTHON_DIR, os.environ.get("PYTHONPATH")) if p))
        result = subprocess.run([sys.executable, "-m", "twb.plot", d, "--out", module, "--format", "svg"],
                                capture_output=True, text=True, env=env, timeout=300)
        self.assertEqual(result.returncode, 0, result.stderr)
        os.makedirs(api)
        written = tp.make_figures(tp.merge([tp.read_run(d)]), api, ["svg"])
        names = sorted(os.listdir(script))
        self.assertIn("transient_trajectory.svg", names)
        self.assertEqual(sorted(os.listdir(module)), names)
        self.assertEqual(sorted(os.path.basename(p) for p in written), names)
        for name in names:
            with open(os.path.join(script, name), "rb") as f:
                expected = f.read()
            for other in (module, api):
                with open(os.path.join(other, name), "rb") as f:
                    self.assertEqual(f.read(), expected, os.path.join(other, name))

    def test_the_plotting_names_only_columns_twb_writes(self):
        """tables.py takes its lists from columns.json (made by `twb columns`, kept equal to
        it by the test python_columns_are_twb_columns): a column name twb does not write
        fails on import, and a distress.csv with such a column is refused with its line."""
        with self.assertRaises(ImportError) as caught:
            tp.tables._written("states", ("load_N", "T_hottest_C"))
        self.assertIn("T_hottest_C", str(caught.exception))
        with open(os.path.join(PYTHON_DIR, "twb", "plot", "columns.json"), encoding="utf-8") as f:
            states = json.load(f)["tables"]["states"]
        self.assertLessEqual(set(tp.tables.STATE_COLUMNS), set(states["columns"]) - set(states["optional"]))
        self.assertEqual(set(tp.tables.STATE_ERROR_COLUMNS) | {"<parameter>", "sliding"}, set(states["optional"]))
        d = os.path.join(self.tmp, "unknown_column")
        os.makedirs(d)
        write(os.path.join(d, "distress.csv"),
              ["speed_rad_s,W_fail_N,criterion,W_d_N,bracket_low_N,bracket_high_N,fold_N,W_wear_N,failure,method",
               "545,188.4,distress,188.4,188.2,188.6,188.4,3,fails,runaway"])
        with self.assertRaises(tp.InputError) as caught:
            tp.read_distress(os.path.join(d, "distress.csv"))
        self.assertIn("line 1", str(caught.exception))

    def test_malformed_input_exits_2_naming_the_file(self):
        cases = {
            "states_bad_number": ("states.csv", "line 3", lambda d: self.replace_line(
                d, "states.csv", 3, lambda line: line.replace(",136,", ",fast,", 1))),
            "states_short_row": ("states.csv", "line 2", lambda d: self.replace_line(
                d, "states.csv", 2, lambda line: line.rsplit(",", 2)[0])),
            "states_nan": ("states.csv", "line 4", lambda d: self.replace_line(
                d, "states.csv", 4, lambda line: "nan" + line[line.index(","):])),
            "states_header": ("states.csv", "line 1", lambda d: self.replace_line(
                d, "states.csv", 1, lambda line: line.replace("f_eff", "feff"))),
            "distress_short_row": ("distress.csv", "line 2", lambda d: write(
                os.path.join(d, "distress.csv"),
                ["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method", "545,1117,1110"])),
            "distress_bad_cell": ("distress.csv", "line 3", lambda d: write(
                os.path.join(d, "distress.csv"),
                ["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
                 "545,1117,1110,1125,,ok", "953,high,1720,1735,,ok"])),
            "trajectory_header": ("trajectory.csv", "line 1", lambda d: write(
                os.path.join(d, "trajectory.csv"), ["time,T_mean_C", "0,30"])),
            "sliding_unknown_film": ("sliding.csv", "line 3", lambda d: write(
                os.path.join(d, "sliding.csv"),
                [SLIDING_HEADER] + sliding_rows(545, [100])[:1]
                + [sliding_rows(545, [100])[1].replace("washer_gear", "gear_washer")])),
            "sliding_chosen_not_boolean": ("sliding.csv", "line 2", lambda d: write(
                os.path.join(d, "sliding.csv"),
                [SLIDING_HEADER, sliding_rows(545, [100])[0][:-1] + "2"])),
            # Two parameters are a grid (test_grid_of_two_axes); a second column that is no
            # parameter is not an axis.
            "distress_parameter_and_unknown": ("distress.csv", "line 1", lambda d: write(
                os.path.join(d, "distress.csv"),
                ["speed_rad_s,gear_tilt_rad,wear_rate,W_d_N,bracket_low_N,bracket_high_N,"
                 "fold_N,method", "545,0.002,0.1,1117,1110,1125,,ok"])),
        }
        for name, (file_name, line, damage) in cases.items():
            with self.subTest(name):
                d = self.results_dir(name)
                damage(d)
                result = plot(d)
                self.assertEqual(result.returncode, 2, result.stderr)
                self.assertIn(os.path.join(d, file_name), result.stderr)
                self.assertIn(line, result.stderr)
                self.assertFalse(os.path.exists(os.path.join(d, "figures")))

    def test_directory_without_states_exits_2(self):
        good = self.results_dir("good")
        empty = os.path.join(self.tmp, "empty")
        os.makedirs(empty)
        result = plot(good, empty)
        self.assertEqual(result.returncode, 2)
        self.assertIn(empty, result.stderr)
        self.assertIn("states.csv", result.stderr)

    def test_unknown_format_is_a_usage_error(self):
        result = plot(self.results_dir("fmt"), "--format", "png,gif")
        self.assertEqual(result.returncode, 2)
        self.assertIn("gif", result.stderr)

    # Rows 1-7 of states.csv are at 136 rad/s, rows 8-14 at 545 rad/s, loads 100 to 1300 N.
    def test_field_maps_default_to_the_last_state_below_distress(self):
        d = self.results_dir(
            "fields", fields=range(1, 15),
            distress=["speed_rad_s,W_d_N,bracket_low_N,bracket_high_N,fold_N,method",
                      "545,1117,1110,1125,1119,runaway; fold at 1119 N"])
        result = plot(d)
        self.assertEqual(result.returncode, 0, result.stderr)
        out_dir = os.path.join(d, "figures")
        # 545 rad/s, 1100 N: the last load below W_d = 1117 N.
        self.assert_figures(out_dir, ("fields_state_0013",))
        self.assertEqual(sorted(n for n in os.listdir(out_dir) if n.startswith("fields")),
                         ["fields_state_0013.png", "fields_state_0013.svg"])
        text = self.svg_text(os.path.join(out_dir, "fields_state_0013.svg"))
        for label in ("1100 N", "545 rad/s", "state 13", "fluid pressure", "(MPa)", "(µm)", "(°C)",
                      "asperity contact pressure", "film 1 (carrier–washer), sliding",
                      "film 2 (washer–gear)", "does not slide"):
            self.assertIn(label, text)

    # A washer that bends (elastic_washer) writes its deflection at every node of both
    # films: the maps gain its panel; a run without it keeps the four.
    def test_a_bent_washers_deflection_is_mapped(self):
        d = self.results_dir("bent")
        os.makedirs(os.path.join(d, "fields"))
        rows = [f"{row},{-2e-6 * float(row.split(',')[2]) / 11.35e-3:.10g}" for row in fields_rows()]
        write(self.fields_file(d, 2), [FIELDS_HEADER + ",washer_deflection_m"] + rows)
        result = plot(d, "--state", "2", "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("washer deflection", self.svg_text(os.path.join(d, "figures", "fields_state_0002.svg")))
        plain = self.results_dir("flat", fields=(2,))
        result = plot(plain, "--state", "2", "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertNotIn("washer deflection", self.svg_text(os.path.join(plain, "figures", "fields_state_0002.svg")))

    def test_field_maps_of_a_chosen_state_or_the_last(self):
        d = self.results_dir("chosen", fields=(3, 14))
        result = plot(d, "--state", "3", "--format", "png")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(os.path.join(d, "figures"), ("fields_state_0003",), formats=("png",))
        result = plot(d, "--out", os.path.join(self.tmp, "last"), "--format", "svg")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(os.path.join(self.tmp, "last"), ("fields_state_0014",), formats=("svg",))

    def test_malformed_fields_exit_2_naming_file_line_and_column(self):
        def damage_line(number, edit):
            return lambda d: self.replace_line(d, os.path.join("fields", "state_0002.csv"), number, edit)
        cases = {
            "bad_number": ("line 4", "column 'p_Pa'", damage_line(
                4, lambda line: ",".join(v if k != 5 else "high" for k, v in enumerate(line.split(","))))),
            "nan": ("line 5", "column 'h_m'", damage_line(
                5, lambda line: ",".join(v if k != 4 else "nan" for k, v in enumerate(line.split(","))))),
            "header": ("line 1", "T_film_C", damage_line(1, lambda line: line.replace("T_film_C", "T_C"))),
            "short_row": ("line 7", "expected 10", damage_line(7, lambda line: line.rsplit(",", 1)[0])),
            "film_number": ("line 3", "column 'film'", damage_line(3, lambda line: "3" + line[1:])),
            "missing_node": ("film 2", "complete polar grid", lambda d: self.drop_line(
                self.fields_file(d, 2), 100)),
        }
        for name, (where, what, damage) in cases.items():
            with self.subTest(name):
                d = self.results_dir(name, fields=(2,))
                damage(d)
                result = plot(d, "--state", "2")
                self.assertEqual(result.returncode, 2, result.stderr)
                self.assertIn(self.fields_file(d, 2), result.stderr)
                self.assertIn(where, result.stderr)
                self.assertIn(what, result.stderr)
                self.assertFalse(os.path.exists(os.path.join(d, "figures")))

    def test_state_without_fields_exits_2(self):
        d = self.results_dir("no_file", fields=(2,))
        for args, expected in ((("--state", "5"), self.fields_file(d, 5)),
                               (("--state", "15"), "1 to 14")):
            with self.subTest(args):
                result = plot(d, *args)
                self.assertEqual(result.returncode, 2, result.stderr)
                self.assertIn(expected, result.stderr)
        plain = self.results_dir("plain")
        result = plot(plain, "--state", "1")
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertIn("output.fields", result.stderr)
        result = plot(plain, "--state", "0")
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertIn("--state", result.stderr)

    @staticmethod
    def drop_line(path, number):
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
        del lines[number - 1]
        write(path, lines)

    @staticmethod
    def replace_line(directory, name, number, edit):
        path = os.path.join(directory, name)
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
        lines[number - 1] = edit(lines[number - 1])
        write(path, lines)


if __name__ == "__main__":
    unittest.main()
