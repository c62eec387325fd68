"""The Python module (import twb; docs/api.md) against the twb command: the same scene
gives the same numbers, errors are SceneError with their location, overrides behave as
--set, progress reaches Python, and the GIL is free while solving.

Needs PYTHONPATH to hold the build's python directory and TWB_BINARY the twb command
(set by CTest)."""

import csv
import math
import os
import pickle
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import twb

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCENE = os.path.join(ROOT, "configs", "jackson_green_2006.yaml")
LIFE = os.path.join(ROOT, "configs", "studies", "life.yaml")
TWB = os.environ.get("TWB_BINARY", "twb")
COARSE = {"mesh.radial_nodes": 5, "mesh.circumferential_nodes": 24}
POINT = {"operating.load": "150 N", "study": {"type": "point"}}


_WORKING = tempfile.TemporaryDirectory(prefix="twb_python_cwd_")


def setUpModule():
    """twb.run writes into the scene's output.directory (relative: under the working
    directory), as twb run does: into a directory of the tests' own, not the source tree."""
    os.chdir(_WORKING.name)


def tearDownModule():
    os.chdir(ROOT)
    _WORKING.cleanup()


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def cell(value, fmt):
    """A value as twb run writes it (result_table.cpp): an absent number is an empty cell."""
    if fmt == "%s":
        return value
    if fmt != "%d" and math.isnan(value):
        return ""
    return fmt % value


class CommandComparison(unittest.TestCase):
    """One scene through the command (--full-precision) and through the module: every cell
    of every table, formatted as the CSV file formats it, is the same text, so the
    module's numbers are the command's to the last bit."""

    def compare(self, overrides, scene=SCENE):
        with tempfile.TemporaryDirectory(prefix="twb_python_") as out:
            # 17 significant digits: each number reads back as the very double the command
            # computed, so equal text is equal bits.
            args = [TWB, "run", scene, "--out", out, "--quiet", "--full-precision"]
            for o in twb.override_texts(overrides):
                args += ["--set", o]
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
            result = twb.run(scene, overrides=overrides, threads=2)
            written = sorted(f[:-4] for f in os.listdir(out) if f.endswith(".csv"))
            self.assertEqual(written, sorted(result.tables))
            for name, table in result.tables.items():
                header, rows = read_csv(os.path.join(out, name + ".csv"))
                self.assertEqual(header, list(table), name)
                self.assertEqual(len(rows), table.rows, name)
                for k, column in enumerate(header):
                    if column == "wall_ms":  # a time, not a result
                        continue
                    fmt = "%.17g" if table.formats[column] == "%.10g" else table.formats[column]
                    mine = [cell(v, fmt) for v in table[column]]
                    self.assertEqual([r[k] for r in rows], mine, f"{name}.csv, column {column}")
        return result

    def test_default_scene(self):
        result = self.compare({})
        self.assertEqual(result.scene.study_type, "load_sweep")
        self.assertEqual(len(result.distress["W_d_N"]), 1)
        self.assertFalse(math.isnan(result.distress["W_d_N"][0]))
        self.assertIsNotNone(result.trajectory)

    def test_point_with_overrides(self):
        result = self.compare(POINT)
        self.assertEqual(list(result.states["load_N"]), [150.0])
        self.assertIsNone(result.distress)
        self.assertEqual(result.states["converged"][0], 1)

    def test_distress_map_on_two_speeds(self):
        self.compare(dict(COARSE, study={"type": "distress_map", "speeds": ["545 rad/s", "953 rad/s"],
                                         "load_start": "100 N", "load_end": "800 N",
                                         "error_estimate": "none"}))

    def test_duty_cycle_from_arrays(self):
        """A duty cycle whose schedule is given as arrays (twb.schedule: SI numbers, strings
        with units, None for the point before's): the trajectory and the events the command
        writes, to the last bit."""
        points = twb.schedule(t=[0, 5, 30], load=[100, 150, None], speed=[None, "6000 rpm", None])
        self.assertEqual(points[1], {"t": 5.0, "load": 150.0, "speed": "6000 rpm"})
        self.assertEqual(points[2], {"t": 30.0})
        result = self.compare(dict(COARSE, **{"operating.load": "100 N", "study": {
            "type": "duty_cycle", "failure_load_at_worst": False, "schedule": points}}))
        self.assertEqual(result.scene.study_type, "duty_cycle")
        self.assertEqual(result.trajectory["t_s"][-1], 30.0)
        self.assertAlmostEqual(result.trajectory["speed_rad_s"][-1], 6000 * 2 * math.pi / 60, delta=1e-9)
        self.assertIn("least_margin", list(result.trajectory))
        self.assertEqual(list(result.cycle_events["event"]), ["end", "worst"])
        with self.assertRaises(ValueError):
            twb.schedule(t=[0, 1], load=[100])
        # A single value holds at every point; a single time is no schedule.
        self.assertEqual([p["speed"] for p in twb.schedule(t=[0, 1], speed="3000 rpm")], ["3000 rpm"] * 2)
        with self.assertRaises(ValueError):
            twb.schedule(t=5, load=[100])

    def test_life_as_its_table(self):
        """A washer's life (study type life): life.csv as the command writes it, a row at
        the start and at every reported time, the last saying how the life ended."""
        result = self.compare(dict(COARSE, study={"type": "life", "duration": "200 h", "report_every": "100 h"}),
                              scene=LIFE)
        self.assertEqual(list(result.life["event"]), ["", "", "end"])
        self.assertEqual(list(result.life["t_h"]), [0.0, 100.0, 200.0])
        self.assertGreater(result.life["worn_depth_rest_max_um"][-1], 0.0)
        self.assertEqual(result.states.rows, 3)

    def test_life_continued_and_its_worn_washer_studied(self):
        """A life run in two parts, the second continued from the first's Results (and from
        the command's results directory), ends where the whole life ends (to its tolerance);
        a point study of the worn washer holds
        the depths the life ended with."""
        def life(hours):
            return dict(COARSE, study={"type": "life", "duration": f"{hours} h", "report_every": "100 h",
                                       "tolerance": "1 nm", "failure_load": False})

        whole = twb.run(LIFE, overrides=life(200), out=False)
        part = twb.run(LIFE, overrides=life(100), out=False)
        self.assertIsNotNone(part.worn_washer)
        self.assertEqual(part.worn_profile.rows, 2 * 5 * 24)
        rest = twb.run(LIFE, overrides=life(200), continue_from=part, out=False)
        self.assertEqual(list(rest.life["t_h"]), [100.0, 200.0])
        deepest = "worn_depth_rest_max_um"
        # The whole life's IDA goes on at 100 h where the continued one starts afresh: each
        # within its tolerance (1 nm) of the true depth, so within two of each other.
        self.assertAlmostEqual(rest.life[deepest][-1], whole.life[deepest][-1], delta=0.002)
        with tempfile.TemporaryDirectory(prefix="twb_python_") as out:
            args = [TWB, "run", LIFE, "--out", out, "--quiet"]
            for o in twb.override_texts(life(100)):
                args += ["--set", o]
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
            point = twb.run(LIFE, overrides=dict(COARSE, study={"type": "point"}), continue_from=out, out=False)
            self.assertAlmostEqual(point.states["worn_depth_rest_um"][-1], part.life[deepest][-1], delta=1e-9)
        with self.assertRaises(ValueError):  # a point study's results hold no worn washer
            twb.run(LIFE, overrides=dict(COARSE, study={"type": "point"}),
                    continue_from=twb.run(LIFE, overrides=dict(COARSE, study={"type": "point"}), out=False))

    def test_duty_cycle_continued_from_its_results(self):
        """A cycle run in two parts, the second continued from the first's Results (and
        from the command's results directory), ends as the whole cycle does, to the last bit
        (tests/study/duty_cycle_test.cpp: IDA restarts at the same point from the same state)."""
        first = [{"t": "0 s", "load": "100 N"}, {"t": "4 s", "load": "140 N"}, {"t": "8 s"}]
        second = [{"t": "8 s", "load": "140 N"}, {"t": "12 s", "load": "120 N"}, {"t": "16 s"}]

        def cycle(points):
            return dict(COARSE, **{"operating.load": "100 N", "study": {
                "type": "duty_cycle", "failure_load_at_worst": False, "schedule": points}})

        whole = twb.run(SCENE, overrides=cycle(first + second[1:]))
        part = twb.run(SCENE, overrides=cycle(first))
        self.assertIsNotNone(part.cycle_end)
        rest = twb.run(SCENE, overrides=cycle(second), continue_from=part)
        for column in ("T_max_C", "hmin_over_sigma", "torque_Nm"):
            self.assertEqual(rest.trajectory[column][-1], whole.trajectory[column][-1], column)
        with tempfile.TemporaryDirectory(prefix="twb_python_") as out:
            args = [TWB, "run", SCENE, "--out", out, "--quiet"]
            for o in twb.override_texts(cycle(first)):
                args += ["--set", o]
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
            from_directory = twb.run(SCENE, overrides=cycle(second), continue_from=out)
            self.assertEqual(from_directory.trajectory["T_max_C"][-1], whole.trajectory["T_max_C"][-1])
            with self.assertRaises(ValueError):  # its results would replace the end it starts from
                twb.run(SCENE, overrides=cycle(second), continue_from=out, out=out)
        with self.assertRaises(ValueError):  # a point study has no cycle's end
            twb.run(SCENE, overrides=cycle(second), continue_from=twb.run(SCENE, overrides=dict(COARSE, **POINT)))
        with self.assertRaises(ValueError):  # nor has an empty directory
            with tempfile.TemporaryDirectory(prefix="twb_python_") as empty:
                twb.run(SCENE, overrides=cycle(second), continue_from=empty)


class Errors(unittest.TestCase):
    def test_malformed_scene_raises_scene_error_with_its_line(self):
        with tempfile.TemporaryDirectory(prefix="twb_python_") as d:
            path = os.path.join(d, "bad.yaml")
            with open(path, "w") as f:
                f.write(f"extends: {os.path.abspath(SCENE)}\n\noperating:\n  load: 150 kg\n")
            with self.assertRaises(twb.SceneError) as caught:
                twb.Scene(path)
            e = caught.exception
            self.assertEqual((e.file, e.line, e.column), (path, 4, 9))
            self.assertIn("bad.yaml:4:9", str(e))
            self.assertIsInstance(e, ValueError)
            # As a worker process of a multiprocessing pool hands it back: pickled.
            back = pickle.loads(pickle.dumps(e))
            self.assertIsInstance(back, twb.SceneError)
            self.assertEqual((back.file, back.line, back.column, back.message, str(back)),
                             (e.file, e.line, e.column, e.message, str(e)))

    def test_bad_override_names_the_override(self):
        with self.assertRaises(twb.SceneError) as caught:
            twb.run(SCENE, overrides={"operating.lod": "150 N"})
        self.assertIn("operating.lod", caught.exception.file)
        self.assertIn("load", str(caught.exception))  # the key it suggests

    def test_missing_file(self):
        with self.assertRaises(twb.SceneError):
            twb.Scene(os.path.join(ROOT, "configs", "no_such_scene.yaml"))


    def test_internal_error_asks_for_a_report(self):
        # No input reaches an internal error: the module's test hook raises one, to check
        # that it arrives as twb.InternalError with the command's words.
        with self.assertRaises(twb.InternalError) as caught:
            twb._core()._raise_internal_error("FoldSystem: borders of another size")
        self.assertIsInstance(caught.exception, RuntimeError)
        self.assertIn("FoldSystem: borders of another size", str(caught.exception))
        self.assertIn("please report", str(caught.exception))


class Scenes(unittest.TestCase):
    def test_overrides_as_mapping_and_as_set_texts(self):
        self.assertEqual(twb.override_texts(POINT), ["operating.load=150 N", "study={type: point}"])
        self.assertEqual(twb.override_texts({"effects": ["hydrodynamics", "thermal"], "mesh.radial_nodes": 5,
                                             "output.fields": True}),
                         ["effects=[hydrodynamics, thermal]", "mesh.radial_nodes=5", "output.fields=true"])
        self.assertEqual(twb.override_texts(["operating.load=1 kN"]), ["operating.load=1 kN"])

    def test_resolved_and_unknowns(self):
        scene = twb.Scene(SCENE, POINT)
        self.assertEqual(scene.resolved()["operating"]["load_N"], 150.0)
        # 0.635 mm converted to metres by udunits2: one rounding.
        self.assertAlmostEqual(scene.resolved()["geometry"]["washer"]["thickness_m"], 0.635e-3, delta=1e-18)
        self.assertEqual(scene.resolved_text()["operating"]["load"], "150 N")
        per_effect = scene.unknowns_per_effect()
        self.assertEqual(sum(b["size"] for b in scene.unknowns()), sum(per_effect.values()))
        self.assertIn("thermal", per_effect)
        isothermal = scene.override({"effects": ["hydrodynamics", "flow_factors", "asperity_contact"]})
        self.assertNotIn("thermal", isothermal.unknowns_per_effect())
        self.assertEqual(isothermal.overrides[:2], scene.overrides)

    def test_study_type_read_twice(self):
        # Read twice in one process: an accessor into a temporary once crashed it here.
        scene = twb.Scene(os.path.join(ROOT, "configs", "washers", "bronze_cusn8.yaml"))
        self.assertEqual(scene.study_type, "distress_map")
        self.assertEqual(scene.study_type, "distress_map")

    def test_summary_holds_the_distress_and_failure_lines(self):
        r = twb.run(os.path.join(ROOT, "configs", "washers", "bronze_cusn8.yaml"),
                    overrides=dict(COARSE, **{"study.load_end": "1000 N"}))
        self.assertTrue(any(line.startswith("distress at ") for line in r.summary), r.summary)
        failure = [line for line in r.summary if line.startswith("failure at ")]
        self.assertEqual(len(failure), 1, r.summary)
        self.assertIn("by the oil's peak temperature", failure[0])
        self.assertEqual(list(r.distress["criterion"]), ["oil_peak_temperature"])

    def test_reliability_tables(self):
        """A reliability study's answers reach Python as its tables: FORM's probability and
        the design point, each input's importance summing to one (sampling left out:
        the C++ test checks it)."""
        r = twb.run(os.path.join(ROOT, "configs", "studies", "reliability.yaml"),
                    overrides=dict(COARSE, **{"study.monte_carlo": "{max_samples: 0}", "study.probabilities": "[]"}))
        self.assertEqual(list(r.reliability["method"]), ["form"], r.summary)
        self.assertEqual(r.reliability["converged"][0], 1)
        self.assertGreater(r.reliability["probability"][0], 0.0)
        self.assertEqual(len(r.design_point["parameter"]), 4)
        self.assertAlmostEqual(sum(r.design_point["importance"]), 1.0, delta=1e-12)

    def test_calibration_tables(self):
        """A calibration's fit reaches Python as its tables: each fitted input with its
        standard deviation, and each reading measured against fitted (the fit itself is
        checked by the C++ test)."""
        data = os.path.join(ROOT, "tests", "scene", "data", "calibration_rig.csv")
        r = twb.run(SCENE, overrides=dict(COARSE, **{
            "study": "{type: calibration, data: '" + data + "', fit: {geometry.gear.tilt: {lower: 0.5 mrad, upper: 3 mrad}}}"}))
        self.assertFalse(r.solver_failed, r.message)
        self.assertEqual(list(r.calibration["parameter"]), ["geometry.gear.tilt"])
        fitted = r.calibration["fitted"][0]
        self.assertTrue(0.5e-3 <= fitted <= 3e-3, fitted)
        self.assertEqual(sorted(set(r.calibration_points["quantity"])), ["T_mean_C", "torque_Nm"])
        self.assertEqual(len(r.calibration_points["measured"]), 4)
        self.assertEqual(r.states.rows, 2)

    def test_sources_of_an_extending_scene(self):
        scene = twb.Scene(os.path.join(ROOT, "configs", "studies", "distress_map.yaml"))
        files = {os.path.basename(f) for _, f, _ in scene.sources()}
        self.assertEqual(files, {"distress_map.yaml", "jackson_green_2006.yaml"})


class Running(unittest.TestCase):
    def test_progress_lines_reach_python(self):
        lines = []
        twb.run(SCENE, overrides=dict(COARSE, **{"study.error_estimate": "none"}), progress=lines.append)
        self.assertTrue(any("fold" in line or "steady" in line for line in lines), lines[:5])

    def test_an_exception_in_progress_stops_the_study_and_is_raised(self):
        lines = []

        def stop(line):
            lines.append(line)
            if line.startswith("[1/4]"):
                raise KeyError("from the callback")
        overrides = dict(COARSE, study={"type": "distress_map", "speeds": ["400 rad/s", "545 rad/s", "700 rad/s",
                                                                           "953 rad/s"],
                                        "load_start": "60 N", "load_end": "900 N", "error_estimate": "none"})
        with self.assertRaises(KeyError):
            twb.run(SCENE, overrides=overrides, progress=stop, threads=1)
        # On one thread the first search's first line stops it: no other search begins.
        self.assertEqual([l for l in lines if l.startswith("[")], ["[1/4] 400 rad/s"])

    def test_a_stopped_run_into_a_directory_resumes_there(self):
        # Stopped once the first of three searches is done (one thread: no other has begun),
        # the run writes only its journal; resume=True reads that search, runs the two
        # others, and writes the numbers of a run never stopped.
        overrides = dict(COARSE, study={"type": "distress_map", "speeds": ["400 rad/s", "545 rad/s", "700 rad/s"],
                                        "load_start": "60 N", "load_end": "900 N", "error_estimate": "none"})

        def stop(line):
            if line.startswith("[1/3] done"):
                raise LookupError("stop here")
        with tempfile.TemporaryDirectory(prefix="twb_python_resume_") as out:
            with self.assertRaises(LookupError):
                twb.run(SCENE, overrides=overrides, progress=stop, threads=1, out=out)
            self.assertFalse(os.path.exists(os.path.join(out, "run.json")))
            self.assertFalse(os.path.exists(os.path.join(out, "distress.csv")))
            lines = []
            resumed = twb.run(SCENE, overrides=overrides, progress=lines.append, threads=1, out=out, resume=True)
            self.assertEqual(sum("from the journal" in line for line in lines), 1, lines)
            self.assertTrue(os.path.isfile(os.path.join(out, "run.json")))
        whole = twb.run(SCENE, overrides=overrides, threads=1, out=False)
        self.assertEqual(sorted(resumed.distress), sorted(whole.distress))
        for name in whole.distress:
            mine, theirs = list(resumed.distress[name]), list(whole.distress[name])
            same = [a == b or (isinstance(a, float) and math.isnan(a) and math.isnan(b)) for a, b in zip(mine, theirs)]
            self.assertTrue(len(mine) == len(theirs) and all(same), name)

    def test_resume_without_a_directory_is_refused(self):
        with self.assertRaises(ValueError) as caught:
            twb.run(SCENE, overrides=dict(COARSE, **POINT), out=False, resume=True)
        self.assertIn("resume=True needs out=DIR", str(caught.exception))

    def test_gil_is_released_while_solving(self):
        # Without a callback the solver never calls back into Python: were the GIL held, this
        # thread could not wake from a sleep until the run ended, and would count one or two
        # ticks. The default scene's sweep with its error bar takes seconds, ten 5-ms sleeps
        # 50 ms even on a loaded machine.
        done = threading.Event()
        worker = threading.Thread(target=lambda: (twb.run(SCENE, threads=1), done.set()))
        ticks = 0
        worker.start()
        while worker.is_alive():
            time.sleep(0.005)
            ticks += 1
        worker.join()
        self.assertTrue(done.is_set())
        self.assertGreaterEqual(ticks, 10)

    def test_threads_do_not_change_results(self):
        overrides = dict(COARSE, study={"type": "distress_map", "speeds": ["545 rad/s", "953 rad/s"],
                                        "load_start": "100 N", "load_end": "800 N", "error_estimate": "none"})
        one = twb.run(SCENE, overrides=overrides, threads=1)
        two = twb.run(SCENE, overrides=overrides, threads=2)
        for name in one.tables:
            for column in one.tables[name]:
                if column == "wall_ms":
                    continue
                a, b = list(one.tables[name][column]), list(two.tables[name][column])
                self.assertEqual([str(x) for x in a], [str(x) for x in b], f"{name}.{column}")


class Points(unittest.TestCase):
    def test_bearing_steps_through_loads_warm(self):
        bearing = twb.Bearing(SCENE, COARSE)
        cold = twb.Bearing(SCENE, COARSE).solve(120, 545)
        bearing.solve(100, 545)
        warm = bearing.solve(120, 545)
        self.assertEqual(set(warm), set(cold))
        self.assertEqual(warm["load_N"], 120.0)
        # Newton stops at a scaled residual of 1e-10: on this cool-branch state the reported
        # quantities agree to far better than 1e-7 (tests/bearing/bearing_test.cpp).
        self.assertAlmostEqual(warm["f_eff"], cold["f_eff"], delta=1e-7 * cold["f_eff"])
        self.assertLess(warm["iterations"], cold["iterations"])

    def test_scene_inputs_by_their_paths(self):
        inputs = {path: (value, unit) for path, value, unit in twb.Scene(SCENE).inputs()}
        self.assertEqual(inputs["geometry.gear.tilt"], (0.002, "rad"))
        self.assertEqual(inputs["operating.speed"], (545.0, "rad/s"))
        self.assertNotIn("mesh.radial_nodes", inputs)

    def test_bearing_sensitivity_of_the_last_state(self):
        """d f_eff / d speed at 120 N, 545 rad/s against the states at 545 +- 0.545 rad/s:
        the centred difference's truncation is far below its 1e-3 allowance (the C++
        test, tests/bearing/bearing_sensitivity_test.cpp, checks every quantity)."""
        bearing = twb.Bearing(SCENE, COARSE)
        with self.assertRaises(Exception):
            bearing.sensitivity("operating.speed")  # nothing solved yet
        bearing.solve(120, 545)
        d = bearing.sensitivity("operating.speed")
        self.assertEqual(set(d), {"torque_Nm", "f_eff", "T_mean_C", "T_max_C", "hmin_over_sigma", "fluid_share"})
        up = twb.Bearing(SCENE, COARSE).solve(120, 545.545)["f_eff"]
        down = twb.Bearing(SCENE, COARSE).solve(120, 544.455)["f_eff"]
        self.assertAlmostEqual(d["f_eff"], (up - down) / 1.09, delta=1e-3 * abs(d["f_eff"]))
        with self.assertRaises(ValueError):
            bearing.sensitivity("geometry.gear.tilted")


class ResultsDirectory(unittest.TestCase):
    """twb.run writes the results directory as twb run does, so that twb.plot can draw it."""

    def test_written_where_the_scene_says_or_where_asked_or_not_at_all(self):
        overrides = dict(COARSE, **POINT)
        r = twb.run(SCENE, overrides=overrides)
        self.assertEqual(r.directory, "results/jackson_green_2006")
        for name in ("states.csv", "run.json"):
            self.assertTrue(os.path.isfile(os.path.join(r.directory, name)), name)
        with tempfile.TemporaryDirectory(prefix="twb_python_out_") as out:
            cli = os.path.join(out, "cli")
            args = [TWB, "run", SCENE, "--out", cli, "--quiet"]
            for o in twb.override_texts(overrides):
                args += ["--set", o]
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
            mine = twb.run(SCENE, overrides=overrides, out=os.path.join(out, "module"))
            self.assertEqual(mine.directory, os.path.join(out, "module"))
            # The same files, and the same cells but the time each solve took.
            self.assertEqual(sorted(os.listdir(cli)), sorted(os.listdir(mine.directory)))
            header, rows = read_csv(os.path.join(cli, "states.csv"))
            header_m, rows_m = read_csv(os.path.join(mine.directory, "states.csv"))
            self.assertEqual(header, header_m)
            wall = header.index("wall_ms")
            self.assertEqual([r[:wall] + r[wall + 1:] for r in rows], [r[:wall] + r[wall + 1:] for r in rows_m])
            nothing = twb.run(SCENE, overrides=overrides, out=False)
            self.assertIsNone(nothing.directory)

    def test_a_directory_that_cannot_be_made_is_an_os_error_naming_it(self):
        # Under a regular file, which root cannot write under either.
        with tempfile.TemporaryDirectory(prefix="twb_python_out_") as out:
            blocker = os.path.join(out, "a_file")
            with open(blocker, "w") as f:
                f.write("not a directory")
            target = os.path.join(blocker, "results")
            with self.assertRaises(NotADirectoryError) as caught:
                twb.run(SCENE, overrides=dict(COARSE, **POINT), out=target)
            self.assertIn(f"cannot make the results directory '{target}'", str(caught.exception))
            self.assertNotIn("report", str(caught.exception))


class BadArguments(unittest.TestCase):
    """What a new user passed by mistake is named for what it is."""

    def test_a_load_that_is_not_a_number_says_so(self):
        with self.assertRaises(ValueError) as caught:
            twb.Bearing(SCENE, COARSE).solve(float("nan"), 545)
        self.assertIn("finite", str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            twb.Bearing(SCENE, COARSE).solve(120, float("inf"))
        self.assertIn("speed must be a finite number", str(caught.exception))

    def test_a_misspelt_input_is_named_before_the_missing_state(self):
        bearing = twb.Bearing(SCENE, COARSE)
        with self.assertRaises(ValueError) as caught:
            bearing.sensitivity("geometry.gear.tilted")  # nothing solved yet, and a path that names nothing
        self.assertIn("geometry.gear.tilted", str(caught.exception))

    def test_negative_threads_are_refused(self):
        with self.assertRaises(ValueError) as caught:
            twb.run(SCENE, overrides=POINT, threads=-1)
        self.assertIn("threads must be 0", str(caught.exception))


class Example(unittest.TestCase):
    def test_wd_over_speed_runs_and_draws(self):
        with tempfile.TemporaryDirectory(prefix="twb_python_") as d:
            out = os.path.join(d, "wd.png")
            run = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "python", "wd_over_speed.py"),
                                  "--mesh", "5x24", "--speeds", "300,900", "--out", out, "-q"],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertIn("900.0 rad/s   W_d =", run.stdout)
            self.assertGreater(os.path.getsize(out), 1000)


if __name__ == "__main__":
    unittest.main()
