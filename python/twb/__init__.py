"""twb from Python: thrust washer bearings in mixed lubrication (Jackson & Green 2006).

    import twb
    r = twb.run("configs/jackson_green_2006.yaml",
                overrides={"operating.load": "150 N", "study": {"type": "point"}})
    r.states["f_eff"], r.distress["W_d_N"]        # numpy arrays, the columns of the CSV files
    pandas.DataFrame(r.states)                     # one line to a data frame

A scene is loaded and validated exactly as `twb run` loads it; a defect raises
twb.SceneError with the file, line and column of the offending text. Results are the
numbers `twb run` writes, unrounded (the CSV files hold them to ten digits). The
figures are in twb.plot, which needs only the results files, not the compiled core.
"""

import json
import numbers
import os
import re

try:
    from . import _twb
except ImportError as _error:  # the plotting part (twb.plot) works without it
    _twb = None
    _import_error = _error

__all__ = ["Bearing", "Scene", "Results", "Table", "SceneError", "SolverFailure", "InternalError", "run",
           "override_texts", "schedule"]


def _core():
    if _twb is None:
        raise ImportError(
            "twb's compiled core (twb/_twb*.so) is not built or not on the path: build the "
            "project with CMake (docs/api.md, 'Python') and put build/python on PYTHONPATH, "
            f"or install it ({_import_error})")
    return _twb


if _twb is not None:
    SceneError = _twb.SceneError
    SolverFailure = _twb.SolverFailure
    InternalError = _twb.InternalError
    __version__ = _twb.__version__
else:
    __version__ = None

    class SceneError(ValueError):
        """A defect in a scene; has file, line, column and message."""

    class SolverFailure(RuntimeError):
        """A state a run needed could not be solved."""

    class InternalError(RuntimeError):
        """A broken precondition inside twb: a bug, to be reported."""


# Text YAML reads as the same plain string inside a flow list or map: anything else
# (a comma, a colon, a bracket, a quote ...) is quoted.
_PLAIN = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_ .+\-/]*")


def _flow(value, nested=False):
    """A Python value as YAML flow text, as one writes it after `twb run --set path=`.
    A string at the top is that text as it is (so "[a, b]" is a list, as with --set);
    inside a list or map it is quoted where YAML would read it otherwise."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    if isinstance(value, str):
        return value if not nested or _PLAIN.fullmatch(value) else json.dumps(value)
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_flow(v, True)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_flow(v, True) for v in value) + "]"
    raise TypeError(f"override value {value!r}: use str, int, float, bool, list or dict")


def override_texts(overrides):
    """Overrides as `twb run --set` takes them: from a mapping {"operating.load": "150 N",
    "study": {"type": "point"}} (a dict value replaces the key's map as `--set
    'study={type: point}'` does), or from "path=value" strings as they are."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [f"{path}={_flow(value)}" for path, value in overrides.items()]
    if isinstance(overrides, str):
        return [overrides]
    return [str(o) for o in overrides]


def schedule(t, load=None, speed=None, ambient=None, tilt=None):
    """A duty cycle's schedule from arrays (lists, tuples or numpy arrays of one length),
    as the scene's `study.schedule` takes it: one point per time, e.g.

        twb.run(scene, {"study": {"type": "duty_cycle",
                                  "schedule": twb.schedule(t=[0, 20, 60], load=[100, 300, 300])}})

    A number is in SI (s, N, rad/s, K, rad), as a bare number in a scene; a string carries
    its unit ("3000 rpm", "90 degC"); a single value for an input holds at every point. An
    array left out, or None in one, leaves the value to the point before (the first
    point's to the scene's operating point and gear tilt)."""
    columns = {"t": t, "load": load, "speed": speed, "ambient": ambient, "tilt": tilt}
    if isinstance(t, (str, numbers.Number)):
        raise ValueError("schedule: t is one value; give the points' times as an array")
    n = len(list(t))
    # A single value (a number or a string with its unit) holds at every point.
    columns = {k: ([v] * n if isinstance(v, (str, numbers.Number)) else list(v))
               for k, v in columns.items() if v is not None}
    for key, values in columns.items():
        if len(values) != n:
            raise ValueError(f"schedule: {key} has {len(values)} values, t has {n}: one a point")
    points = []
    for i in range(n):
        point = {}
        for key, values in columns.items():
            v = values[i]
            if v is None:
                if key == "t":
                    raise ValueError(f"schedule: point {i + 1} has no time")
                continue
            point[key] = v if isinstance(v, str) else float(v)
        points.append(point)
    return points


class Scene:
    """A scene file loaded, converted to SI and validated, with its overrides."""

    def __init__(self, path, overrides=None, *, _text=None):
        self.path = os.fspath(path)
        self.overrides = override_texts(overrides)
        self._text = _text
        if _text is None:
            self._scene = _core().load_scene(self.path, self.overrides)
        else:
            self._scene = _core().load_scene_text(_text, self.path, self.overrides)

    @classmethod
    def from_text(cls, text, name="<scene>", overrides=None):
        """A scene held in a string; `name` stands for the file in error messages
        (a scene read from text cannot extend a file by a relative path)."""
        return cls(name, overrides, _text=text)

    def override(self, overrides):
        """A new Scene: this one's overrides, then these."""
        return Scene(self.path, self.overrides + override_texts(overrides), _text=self._text)

    def resolved(self):
        """The resolved scene, every default filled in, as run.json records it: nested
        dicts with numbers in SI and the unit in each key's name, as in the CSVs
        (resolved()["operating"]["load_N"])."""
        return json.loads(self._scene.record_json())

    def resolved_text(self):
        """The same as nested dicts of the "value unit" strings `twb check` prints."""
        return self._scene.resolved_text()

    def resolved_yaml(self):
        return self._scene.resolved_yaml()

    def unknowns(self):
        """The unknown blocks the scene's effects bring: [{"name", "effect", "size"}]."""
        return self._scene.unknowns()

    def unknowns_per_effect(self):
        counts = {}
        for block in self.unknowns():
            counts[block["effect"]] = counts.get(block["effect"], 0) + block["size"]
        return counts

    def inputs(self):
        """Every input the scene file writes, by its scene path: [(path, SI value, SI unit)],
        what a sensitivity study's parameters, a map's axis and Bearing.sensitivity name."""
        return list(self._scene.inputs())

    def sources(self):
        """Where each value was written: [(path, file, line)] (scenes that extend scenes)."""
        if self._text is not None:
            raise ValueError("a scene read from text has no files to trace")
        return _core().value_sources(self.path, self.overrides)

    @property
    def warnings(self):
        return list(self._scene.warnings)

    @property
    def study_type(self):
        return self._scene.study_type

    def run(self, progress=None, threads=0, continue_from=None, out=None, resume=False):
        """Runs the scene's study (see twb.run)."""
        directory = _results_directory(self, out)
        text, from_directory = _continued(self, continue_from)
        results = Results(_core().run(self._scene, progress, threads, text, from_directory, directory, resume),
                          self)
        results.directory = directory
        return results

    def __repr__(self):
        extra = f", overrides={self.overrides!r}" if self.overrides else ""
        return f"twb.Scene({self.path!r}{extra})"


class Table(dict):
    """One results table: column name -> numpy array (float64, NaN where the CSV cell is
    empty; int64 for counts) or list of str. `formats` holds each column's printf format
    in the CSV file. pandas.DataFrame(table) makes a data frame of it."""

    def __init__(self, columns, formats):
        super().__init__(columns)
        self.formats = dict(formats)

    @property
    def rows(self):
        return len(next(iter(self.values()))) if self else 0

    def __repr__(self):
        return f"twb.Table({self.rows} rows: {', '.join(self)})"


class Results:
    """What a study gives back. Tables (None where the study writes no such file):
    states, distress, trajectory, sliding, fold_curve, sensitivity, reliability, design_point,
    calibration, calibration_correlation, calibration_points, cycle_events, life, worn_profile; fields: per
    state, its fields
    table (output.fields) or None; summary and limit_notes: the lines twb run prints at
    the end; message, solver_failed; timings: run.json's counts; directory: where twb.run
    wrote them (None where it wrote nothing)."""

    def __init__(self, raw, scene):
        self.scene = scene
        self.directory = None
        self.tables = {name: Table(columns, raw["formats"][name]) for name, columns in raw["tables"].items()}
        self.fields = [None if f is None else Table(f, {}) for f in raw["fields"]]
        self.summary = list(raw["summary"])
        self.limit_notes = list(raw["limit_notes"])
        self.diagnostics = list(raw["diagnostics"])
        self.solver_failed = bool(raw["solver_failed"])
        self.message = raw["message"]
        self.timings = dict(raw["timings"])
        # A duty cycle's end state (cycle_end_state.json's text) where it ran to its end:
        # twb.run(..., continue_from=these results) goes on from it.
        self.cycle_end = raw.get("cycle_end")
        # The washer a life wore (worn_washer.json's text): twb.run(..., continue_from=these
        # results) goes on from it, a life from its time, any other study with its depths held.
        self.worn_washer = raw.get("worn_washer")

    states = property(lambda self: self.tables.get("states"))
    distress = property(lambda self: self.tables.get("distress"))
    trajectory = property(lambda self: self.tables.get("trajectory"))
    sliding = property(lambda self: self.tables.get("sliding"))
    fold_curve = property(lambda self: self.tables.get("fold_curve"))
    sensitivity = property(lambda self: self.tables.get("sensitivity"))
    reliability = property(lambda self: self.tables.get("reliability"))
    design_point = property(lambda self: self.tables.get("design_point"))
    calibration = property(lambda self: self.tables.get("calibration"))
    calibration_correlation = property(lambda self: self.tables.get("calibration_correlation"))
    calibration_points = property(lambda self: self.tables.get("calibration_points"))
    cycle_events = property(lambda self: self.tables.get("cycle_events"))
    life = property(lambda self: self.tables.get("life"))
    worn_profile = property(lambda self: self.tables.get("worn_profile"))

    def __repr__(self):
        parts = ", ".join(f"{name}: {table.rows} rows" for name, table in self.tables.items())
        return f"twb.Results({parts})"


class Bearing:
    """The bearing of one scene for point after point, as a program embedding twb uses
    it (twb::Bearing): solve(load, speed) is the steady state there, Newton from the
    last state solved (a few iterations for a nearby point), cold the first time. It
    returns a mapping of states.csv's columns to their values, unrounded. Between W_d
    and the hot branch's return two states exist at one load: a warm start stays on
    its branch (a load_sweep study follows and names them)."""

    def __init__(self, scene, overrides=None):
        if not isinstance(scene, Scene):
            scene = Scene(scene, overrides)
        elif overrides:
            scene = scene.override(overrides)
        self.scene = scene
        self._bearing = _core().Bearing(scene._scene)

    def solve(self, load, speed):
        """The state at `load` (N) and `speed` (rad/s); twb.SolverFailure if none is found
        (the last good state is kept for the next warm start)."""
        return self._bearing.solve(float(load), float(speed))

    def sensitivity(self, path):
        """How the last state solved moves with one input of the scene, by its path
        ("geometry.gear.tilt", "lubricant.viscosity.kv40", "operating.speed"): a mapping
        of torque_Nm, f_eff, T_mean_C, T_max_C, hmin_over_sigma and fluid_share to their
        derivatives per SI unit of the input (a temperature's per kelvin); docs/physics.md
        section 16. ValueError for a path that names no input."""
        return self._bearing.sensitivity(str(path))

    def forget_state(self):
        """The next solve starts cold."""
        self._bearing.forget_state()


def run(scene, overrides=None, progress=None, threads=0, continue_from=None, out=None, resume=False):
    """Runs the study a scene names and returns its Results.

    scene: a path or a twb.Scene; overrides: as for twb.Scene (applied after the
    scene's own); progress: called with each progress line twb run would print (from
    the solving threads, one at a time); threads: for the study's independent searches,
    0 = one per core (the results do not depend on it); continue_from: an earlier run's
    Results or results directory to go on from (as twb run --continue-from): a duty cycle
    from where the earlier cycle ended (the schedule's first point must be that end's time
    and inputs), any other study from the washer an earlier life wore (a life from its
    time to study.duration, the others with its depths held); out:
    the results directory, written as twb run writes it (the tables, fields, run.json;
    twb.plot draws from it): None for the scene's output.directory, as twb run, a path
    for another, False for none (Results.directory says which, or None); the directory is
    claimed (locked against another run, an earlier run's files removed) before any work,
    and each finished search of a sweep, map or sliding choice is journaled there at once;
    resume: keep the searches a run into the same directory journaled before it was
    stopped or killed, and run only the others (as twb run --resume). The GIL is released
    while solving. An exception from the callback, or Ctrl-C, stops the study: the
    searches under way finish, no new one begins, nothing but the journal is written, and
    the exception is raised then."""
    if isinstance(scene, Scene):
        if overrides:
            scene = scene.override(overrides)
    else:
        scene = Scene(scene, overrides)
    return scene.run(progress=progress, threads=threads, continue_from=continue_from, out=out, resume=resume)


def _results_directory(scene, out):
    """Where twb.run writes: the scene's output.directory for None (as twb run), nothing
    for False, else the path given."""
    if out is False:
        return None
    if out is None:
        return scene.resolved_text()["output"]["directory"]
    return os.fspath(out)


def _continued(scene, continue_from):
    """What a run goes on from: a duty cycle's end state, or the washer a life wore, as the
    JSON text of Results or the results directory that holds it (which twb's core reads
    and checks as twb run --continue-from does), as (text, directory); (None, None) for none."""
    if continue_from is None:
        return None, None
    if isinstance(continue_from, Results):
        if scene.study_type == "duty_cycle" and continue_from.worn_washer is None:
            if continue_from.cycle_end is None:
                raise ValueError("continue_from: these results hold no cycle's end (not a duty cycle, "
                                 "or one that did not run to its end)")
            return continue_from.cycle_end, None
        if continue_from.worn_washer is None:
            raise ValueError("continue_from: these results hold no worn washer (not a life study); a "
                             f"{scene.study_type} study goes on from the washer a life wore")
        return continue_from.worn_washer, None
    return None, os.fspath(continue_from)
