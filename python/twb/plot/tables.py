"""Reading the files of a twb results directory, each checked line by line.

These files are the only contract between the solver and its figures, so a file that is
not what twb writes (a damaged cell, a missing column, a hand-edited row) stops the
plotting with an InputError naming the file, the line and the column, rather than
drawing a wrong figure from it.
"""

import csv
import json
import math
import os
from dataclasses import dataclass

import numpy as np

def _definition():
    """columns.json: the columns of every table as twb writes them, made by `twb columns`
    from the C++ functions that write the tables (a test keeps the two the same)."""
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "columns.json"), encoding="utf-8") as f:
        return json.load(f)


_DEFINITION = _definition()
_TABLES = _DEFINITION["tables"]
# Where a study's own columns go: its axes' values (zero or more) and its sliding film.
_RUN_PLACES = ("<parameter>", "sliding")


def _written(table, names):
    """names, each a column twb writes in the table: the plotting never names a column of
    its own making (a mistyped or retired name fails on import, in the tests)."""
    unknown = [n for n in names if n not in _TABLES[table]["columns"]]
    if unknown:
        raise ImportError(f"twb.plot names column(s) {', '.join(unknown)} that twb does not write "
                          f"in {table}.csv (columns.json)")
    return tuple(names)


def _optional(table):
    """The columns only some studies write, but for the run's own (parameter, sliding)."""
    return tuple(c for c in _TABLES[table]["optional"] if c not in _RUN_PLACES + ("<family>",))


# The states' columns the figures draw (a file may have more).
STATE_COLUMNS = _written("states", (
    "load_N", "speed_rad_s", "T_mean_C", "T_max_C", "hmin_over_sigma", "gamma_x_ratio",
    "gamma_y_ratio", "fluid_share", "contact_share", "torque_Nm", "f_eff", "stribeck",
    "converged", "iterations", "residual", "energy_error", "wall_ms"))
# A state's error bar (study.error_estimate: richardson on a point, every_state on a
# sweep): the mesh-converged value and its bar; empty cells in a state without one.
STATE_ERROR_COLUMNS = _optional("states")
TRAJECTORY_COLUMNS = _written("trajectory", (
    "t_s", "T_mean_C", "T_max_C", "hmin_over_sigma", "contact_share", "f_eff", "load_N"))
# distress.csv before every failure criterion was located (no W_fail_N): its columns
# after the run's, read by position; the method last, free text that twb wrote unquoted.
DISTRESS_TAIL = _written("distress", ("W_d_N", "bracket_low_N", "bracket_high_N", "fold_N", "method"))
# Written since W_d has an error bar (study.error_estimate: richardson), before the method.
DISTRESS_ERROR_COLUMNS = _written("distress", ("W_d_fine_N", "W_d_extrapolated_N", "W_d_error_N"))
SLIDING_COLUMNS = tuple(_TABLES["sliding"]["columns"])
SENSITIVITY_COLUMNS = tuple(_TABLES["sensitivity"]["columns"])
SENSITIVITY_TEXTS = tuple(_TABLES["sensitivity"]["texts"])
# A duty cycle's trajectory.csv (the cycle's own columns after the transient's) and its
# cycle_events.csv.
CYCLE_COLUMNS = _written("trajectory", (
    "t_s", "load_N", "speed_rad_s", "ambient_C", "T_mean_C", "T_max_C", "hmin_over_sigma", "least_margin"))
CYCLE_EVENT_COLUMNS = tuple(_TABLES["cycle_events"]["columns"])
CYCLE_EVENT_TEXTS = tuple(_TABLES["cycle_events"]["texts"])
# A life study's life.csv and worn_profile.csv.
LIFE_COLUMNS = tuple(_TABLES["life"]["columns"])
LIFE_TEXTS = tuple(_TABLES["life"]["texts"])
WORN_PROFILE_COLUMNS = tuple(_TABLES["worn_profile"]["columns"])
RELIABILITY_COLUMNS = tuple(_TABLES["reliability"]["columns"])
RELIABILITY_TEXTS = tuple(_TABLES["reliability"]["texts"])
DESIGN_POINT_COLUMNS = tuple(_TABLES["design_point"]["columns"])
DESIGN_POINT_TEXTS = tuple(_TABLES["design_point"]["texts"])
CALIBRATION_COLUMNS = tuple(_TABLES["calibration"]["columns"])
CALIBRATION_TEXTS = tuple(_TABLES["calibration"]["texts"])
CALIBRATION_CORRELATION_COLUMNS = tuple(_TABLES["calibration_correlation"]["columns"])
CALIBRATION_CORRELATION_TEXTS = tuple(_TABLES["calibration_correlation"]["texts"])
CALIBRATION_POINTS_COLUMNS = tuple(_TABLES["calibration_points"]["columns"])
CALIBRATION_POINTS_TEXTS = tuple(_TABLES["calibration_points"]["texts"])
# What calibration_points.csv's quantity names: the states' columns a calibration fits.
CALIBRATION_QUANTITIES = _written("states", ("torque_Nm", "f_eff", "T_mean_C", "T_max_C"))
# The columns twb adds after the speed when a study runs several configurations: the
# value of each of its axes (one column per axis of a grid), and the film that slides.
PARAMETER_COLUMNS = tuple(_DEFINITION["run_parameters"])


def is_parameter_column(name):
    """An axis of a study (its second, or one of a grid's): a named parameter's column, or
    an input's scene path with its unit (geometry.gear.tilt_rad): the only column names
    with a dot."""
    return name in PARAMETER_COLUMNS or "." in name


# A run's tag: which combination of the study's axes it is. A study over one axis keeps
# the form the figures and their users have always had, (column, value); only a grid
# (several axes) has the tuple of its axes' (column, value) pairs, in the scene's order.
def run_tag(axes):
    """The tag of a run whose axes have these (column, value) pairs: None, (column,
    value), or a grid's tuple of pairs."""
    axes = tuple(axes)
    if not axes:
        return None
    return axes[0] if len(axes) == 1 else axes


def run_axes(tag):
    """A run's tag as its axes' (column, value) pairs, whatever the number of axes."""
    if tag is None:
        return ()
    # A single axis's tag starts with its column's name, a grid's with a pair.
    return (tag,) if isinstance(tag[0], str) else tuple(tag)


def run_order(tag):
    """Runs sorted by each axis in turn (its column, then its value; a value not set
    first); a run without axes before all."""
    return tuple((c, -math.inf if value is None else value) for c, value in run_axes(tag))


SLIDING_LABELS = {
    "carrier_washer": "film 1 slides (washer stuck to the gear)",
    "washer_gear": "film 2 slides (washer stuck to the carrier)",
}
FIELDS_OPTIONAL = tuple(_TABLES["fields"]["optional"])
FIELDS_COLUMNS = tuple(c for c in _TABLES["fields"]["columns"] if c not in FIELDS_OPTIONAL)


def _labels_every(what, labels, names):
    """A figure's labels for a text column's values: one for each value twb writes."""
    if set(labels) != set(names):
        raise ImportError(f"twb.plot labels {what} {sorted(labels)}, twb writes {sorted(names)} (columns.json)")
    return labels


_labels_every("the sliding films", SLIDING_LABELS, _DEFINITION["sliding_films"])


class InputError(Exception):
    """An input that is not what twb writes; the message names the file and line."""


def _records(path):
    """(line number, fields) for every non-blank line, header included."""
    reader = None
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.reader(f)
            for fields in reader:
                if fields:
                    yield reader.line_num, fields
    except UnicodeDecodeError as e:
        raise InputError(f"{path}: not UTF-8 text ({e.reason})") from None
    except csv.Error as e:
        raise InputError(f"{path}: line {reader.line_num}: {e}") from None
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}") from None


def _number(path, line, column, text, optional=False):
    text = text.strip()
    if optional and text == "":
        return None
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    # twb never writes NaN or infinity (an absent value is an empty cell), so one here
    # means the file did not come from twb or was damaged.
    if not math.isfinite(value):
        expected = "a finite number or an empty cell" if optional else "a finite number"
        raise InputError(f"{path}: line {line}: column '{column}': expected {expected}, got {text!r}")
    return value


def _header_line(path, records, expected):
    """The header's line number and its column names; an empty file is an error that
    says which header was expected."""
    try:
        line, header = next(records)
    except StopIteration:
        raise InputError(f"{path}: line 1: expected the header {expected}, got an empty file") from None
    return line, [h.strip() for h in header]


def _header(path, records, required, what):
    line, header = _header_line(path, records, ",".join(required))
    missing = [c for c in required if c not in header]
    if missing:
        raise InputError(f"{path}: line {line}: expected the {what} header {','.join(required)}; "
                         f"missing column(s): {', '.join(missing)}")
    return header


def _check_width(path, line, fields, header):
    if len(fields) != len(header):
        raise InputError(f"{path}: line {line}: expected {len(header)} comma-separated fields "
                         f"as in the header, got {len(fields)}")


def _axes_tag(path, line, columns, cells):
    """The run tag of a row whose axes' columns hold these cells (an axis not set is
    an empty cell, read as None)."""
    return run_tag((c, _number(path, line, c, text, optional=True)) for c, text in zip(columns, cells))


def _run_tags(path, line, fields, header):
    """The run a row belongs to: (run tag, sliding film or None); the run tag is None,
    (parameter column, value), or a grid's ((column, value), ...) (run_tag)."""
    parameters = [c for c in header if is_parameter_column(c)]
    tag = _axes_tag(path, line, parameters, [fields[header.index(c)] for c in parameters])
    sliding = None
    if "sliding" in header:
        sliding = fields[header.index("sliding")].strip()
        if sliding not in SLIDING_LABELS:
            raise InputError(f"{path}: line {line}: column 'sliding': expected one of "
                             f"{', '.join(SLIDING_LABELS)}, got {sliding!r}")
    return tag, sliding


def _read_table(path, required, what, optional=(), blank_ok=()):
    """Columns of a twb table as float arrays (optional ones when present), in file
    order, and each row's run tags. Columns in blank_ok (optional ones) may have empty
    cells, read as NaN."""
    records = _records(path)
    header = _header(path, records, required, what)
    names = list(required) + [c for c in optional if c in header]
    index = {c: header.index(c) for c in names}
    columns = {c: [] for c in names}
    tags = []
    for line, fields in records:
        _check_width(path, line, fields, header)
        for c in names:
            value = _number(path, line, c, fields[index[c]], optional=c in blank_ok)
            columns[c].append(math.nan if value is None else value)
        tags.append(_run_tags(path, line, fields, header))
        if "converged" in columns and columns["converged"][-1] not in (0.0, 1.0):
            raise InputError(f"{path}: line {line}: column 'converged': expected 0 or 1, "
                             f"got {fields[index['converged']].strip()!r}")
    return {c: np.array(v, dtype=float) for c, v in columns.items()}, tags


def read_states(path):
    """Columns of states.csv as float arrays, in file order, and each state's run tags
    ((run tag, sliding film), _run_tags)."""
    return _read_table(path, STATE_COLUMNS, "states.csv", optional=STATE_ERROR_COLUMNS,
                       blank_ok=STATE_ERROR_COLUMNS)


def read_trajectory(path):
    # A file may lack the columns written only since (the speed, the run's): read where present.
    return _read_table(path, TRAJECTORY_COLUMNS, "trajectory.csv", optional=("speed_rad_s",))


# fold_curve.csv (study type distress_curve): the curve's parameter first, then these.
FOLD_CURVE_PARAMETERS = _labels_every("the curve parameters", {
    "speed_rad_s": r"speed $\omega$ (rad/s)", "friction_coefficient": "dry friction coefficient",
    "gear_tilt_rad": "gear tilt (rad)", "ambient_C": "ambient temperature (°C)",
    "viscosity_scale": "oil viscosity / the scene's", "roughness_Rq_m": "roughness Rq (m)"},
    _DEFINITION["curve_parameters"])
# W_d's error bar along the curve (study.error_estimate: richardson): after the tail in
# files written since it exists, empty cells where a fold has none.
FOLD_CURVE_ERROR = _written("fold_curve", ("W_fold_fine_N", "W_fold_extrapolated_N", "W_fold_error_N"))
# How each bar was reached (study.tolerance): after the error bar's columns in files written
# since they exist.
FOLD_CURVE_CONVERGENCE = _written("fold_curve", ("W_fold_meshes", "W_fold_order", "W_fold_tolerance_met"))
_CURVE = _TABLES["fold_curve"]["columns"]
FOLD_CURVE_TAIL = tuple(c for c in _CURVE[_CURVE.index("<parameter>") + 1:]
                        if c not in FOLD_CURVE_ERROR + FOLD_CURVE_CONVERGENCE)
# The failure criteria whose crossing a distress curve continues beside its fold (the row's
# load is where the criterion is crossed on the cool branch).
LIMIT_KINDS = tuple(c for c in _DEFINITION["failure_criteria"] if c != "distress")
FOLD_KINDS = tuple(_DEFINITION["fold_kinds"])


def read_fold_curve(path):
    """fold_curve.csv: (parameter column, rows as dicts with 'p', 'load', 'fold', ...,
    the error bar's columns (None where absent), and 'member': (family column, value) of
    a family of curves, else None)."""
    records = _records(path)
    expected = (f"[<family>,]<parameter>,{','.join(FOLD_CURVE_TAIL)}[,{','.join(FOLD_CURVE_ERROR)}"
                f"[,{','.join(FOLD_CURVE_CONVERGENCE)}]]")
    line, header = _header_line(path, records, expected)
    converged = tuple(header[-len(FOLD_CURVE_CONVERGENCE):]) == FOLD_CURVE_CONVERGENCE
    head = header[:-len(FOLD_CURVE_CONVERGENCE)] if converged else header
    errors = tuple(head[-len(FOLD_CURVE_ERROR):]) == FOLD_CURVE_ERROR
    body = head[:-len(FOLD_CURVE_ERROR)] if errors else head
    if converged and not errors:
        raise InputError(f"{path}: line {line}: expected the header {expected}, got {','.join(header)}")
    family = body[0] if len(body) == len(FOLD_CURVE_TAIL) + 2 and is_parameter_column(body[0]) else None
    first = 1 if family else 0
    if len(body) != len(FOLD_CURVE_TAIL) + 1 + first or body[first] not in FOLD_CURVE_PARAMETERS \
            or tuple(body[first + 1:]) != FOLD_CURVE_TAIL:
        raise InputError(f"{path}: line {line}: expected the header {expected} with <parameter> one of "
                         f"{', '.join(FOLD_CURVE_PARAMETERS)} and <family> one of {', '.join(PARAMETER_COLUMNS)}, "
                         f"got {','.join(header)}")
    rows = []
    for line, fields in records:
        _check_width(path, line, fields, header)
        kind = fields[first + 2].strip()
        if kind not in FOLD_KINDS:
            raise InputError(f"{path}: line {line}: column 'fold': expected one of {', '.join(FOLD_KINDS)}, "
                             f"got {kind!r}")
        row = {"p": _number(path, line, header[first], fields[first]),
               "load": _number(path, line, "W_fold_N", fields[first + 1]), "fold": kind,
               "member": (family, _number(path, line, family, fields[0])) if family else None}
        for k, c in enumerate(FOLD_CURVE_TAIL[2:], start=first + 3):
            row[c] = _number(path, line, c, fields[k])
        for k, c in enumerate(FOLD_CURVE_ERROR, start=len(body)):
            row[c] = _number(path, line, c, fields[k], optional=True) if errors else None
        for k, c in enumerate(FOLD_CURVE_CONVERGENCE, start=len(head)):
            if not converged:
                row[c] = None
            elif c == "W_fold_order":
                row[c] = _number(path, line, c, fields[k], optional=True)
            else:
                row[c] = fields[k].strip() or None
        rows.append(row)
    return header[first], rows


def read_sliding(path):
    """sliding.csv: the sliding choice's rows, as dicts of floats plus 'sliding'."""
    records = _records(path)
    header = _header(path, records, SLIDING_COLUMNS, "sliding.csv")
    rows = []
    for line, fields in records:
        _check_width(path, line, fields, header)
        row = {c: _number(path, line, c, fields[header.index(c)])
               for c in SLIDING_COLUMNS if c != "sliding"}
        row["sliding"] = _run_tags(path, line, fields, header)[1]
        if row["chosen"] not in (0.0, 1.0):
            raise InputError(f"{path}: line {line}: column 'chosen': expected 0 or 1, "
                             f"got {fields[header.index('chosen')].strip()!r}")
        rows.append(row)
    return rows


def _read_rows(path, columns, texts, what, optional):
    """One dict per row of a table twb writes: its text columns as text, the others
    numbers (None where empty and the column is optional)."""
    records = _records(path)
    header = _header(path, records, columns, what)
    rows = []
    for line, fields in records:
        _check_width(path, line, fields, header)
        row = {}
        for c in columns:
            text = fields[header.index(c)]
            row[c] = text.strip() if c in texts else _number(path, line, c, text, optional=optional(c))
        rows.append(row)
    return rows


def read_sensitivity(path):
    """sensitivity.csv: one dict per (quantity, parameter) row; elasticity None where
    twb left it empty (a quantity or an input of zero)."""
    return _read_rows(path, SENSITIVITY_COLUMNS, SENSITIVITY_TEXTS, "sensitivity.csv",
                      lambda c: c == "elasticity")


def read_cycle(path):
    """A duty cycle's trajectory.csv: its columns as float arrays (least_margin NaN where
    the scene applies no criterion)."""
    columns, _ = _read_table(path, CYCLE_COLUMNS, "trajectory.csv", blank_ok=("least_margin",))
    return columns


def read_cycle_events(path):
    """cycle_events.csv: one dict per event (crossing, recovery, runaway, settled, rest, resume,
    worst, end); a value an event does not have (a crossing's failure load) None."""
    return _read_rows(path, CYCLE_EVENT_COLUMNS, CYCLE_EVENT_TEXTS, "cycle_events.csv",
                      lambda c: c in ("margin", "failure_load_N"))


def read_life(path):
    """life.csv: one dict per reported time; the failure load None where it was not
    searched (study.failure_load: false) or not found."""
    return _read_rows(path, LIFE_COLUMNS, LIFE_TEXTS, "life.csv", lambda c: c == "W_fail_N")


def read_worn_profile(path):
    """worn_profile.csv: its columns as float arrays, one row per node of the sliding film
    at each reported time."""
    columns, _ = _read_table(path, WORN_PROFILE_COLUMNS, "worn_profile.csv")
    return columns


def read_reliability(path):
    """reliability.csv: one dict per answer (method form, monte_carlo or inverse_form);
    a value that does not apply to the method (a sampling's interval for FORM) None."""
    return _read_rows(path, RELIABILITY_COLUMNS, RELIABILITY_TEXTS, "reliability.csv",
                      lambda c: c not in ("load_N", "probability"))


def read_design_point(path):
    """design_point.csv: one dict per (answer, input); a distribution's parameter it
    does not have (a uniform's mean) None."""
    return _read_rows(path, DESIGN_POINT_COLUMNS, DESIGN_POINT_TEXTS, "design_point.csv",
                      lambda c: c in ("mean", "sd", "lower", "upper"))


def read_calibration(path):
    """calibration.csv: one dict per fitted input (SI values); sd None where the data do
    not determine it, at_bound "lower", "upper" or "" (within its bounds)."""
    return _read_rows(path, CALIBRATION_COLUMNS, CALIBRATION_TEXTS, "calibration.csv",
                      lambda c: c == "sd")


def read_calibration_correlation(path):
    """calibration_correlation.csv: one dict per pair of fitted inputs (each pair once,
    each input with itself); no rows where the fit has no covariance (not identifiable,
    or no degree of freedom left)."""
    return _read_rows(path, CALIBRATION_CORRELATION_COLUMNS, CALIBRATION_CORRELATION_TEXTS,
                      "calibration_correlation.csv", lambda c: False)


def read_calibration_points(path):
    """calibration_points.csv: one dict per measured value, in its quantity's unit (°C for
    a temperature); sd None where the fit is relative (the readings have none)."""
    return _read_rows(path, CALIBRATION_POINTS_COLUMNS, CALIBRATION_POINTS_TEXTS, "calibration_points.csv",
                      lambda c: c == "sd")


@dataclass
class DistressRow:
    speed: float
    parameter: object  # the run tag: (column name, value), a grid's tuple of them, or None
    w_d: object
    low: object
    high: object
    fold: object
    method: str
    sliding: object = None  # the sliding film of a sliding choice's row
    extrapolated: object = None  # mesh-converged W_d (Richardson), N
    error: object = None  # its error bar, N
    failure: object = None  # W_fail: where the bearing fails by its first criterion, N
    criterion: object = None  # the criterion that sets it ("distress", "oil_peak_temperature", ...)
    failure_converged: object = None  # W_fail mesh-converged (study.tolerance), N
    failure_error: object = None  # its error bar, N


# Written since every failure criterion is located (W_fail_N after the run's columns,
# failure before the method): read by name.
FAILURE_COLUMNS = _written("distress", ("W_fail_N", "criterion"))


# distress.csv's columns before its tail: the speed, then the run's axes (none, one, or a
# grid's several) and its sliding film.
DISTRESS_RUN_COLUMNS = "speed_rad_s[,<parameter>...][,sliding]"


def _axes_columns_ok(axes):
    """Whether the columns at <parameter> can be a run's axes. One column is read as the
    run's parameter whatever its name, as it always was; several are a grid's axes, each
    a parameter's column, so that a stray column is not taken for an axis."""
    return len(axes) <= 1 or all(is_parameter_column(c) for c in axes)


def _read_distress_by_name(path, records, line, header):
    start = header.index("W_fail_N")
    middle = header[1:start]
    sliding = bool(middle) and middle[-1] == "sliding"
    if sliding:
        middle = middle[:-1]
    written = set(_TABLES["distress"]["columns"]) | set(PARAMETER_COLUMNS)
    if (not _axes_columns_ok(middle) or header[0] != "speed_rad_s"
            or tuple(header[-2:]) != ("failure", "method")
            or any(c not in header for c in DISTRESS_TAIL + FAILURE_COLUMNS)
            or any(c not in written and not is_parameter_column(c) for c in header)):
        raise InputError(f"{path}: line {line}: expected the header {DISTRESS_RUN_COLUMNS},"
                         f"W_fail_N,criterion,W_d_N,...,failure,method, got {','.join(header)}")
    column = {c: k for k, c in enumerate(header)}
    rows = []
    for line, fields in records:
        _check_width(path, line, fields, header)
        number = lambda c: (_number(path, line, c, fields[column[c]], optional=True)  # noqa: E731
                            if c in column else None)
        parameter, film = _run_tags(path, line, fields, header)
        rows.append(DistressRow(_number(path, line, "speed_rad_s", fields[0]), parameter, number("W_d_N"),
                                number("bracket_low_N"), number("bracket_high_N"), number("fold_N"),
                                fields[-1].strip(), film, number("W_d_extrapolated_N"), number("W_d_error_N"),
                                number("W_fail_N"), fields[column["criterion"]].strip() or None,
                                number("W_fail_extrapolated_N"), number("W_fail_error_N")))
    return rows


def read_distress(path):
    records = _records(path)
    line, header = _header_line(path, records, f"{DISTRESS_RUN_COLUMNS},{','.join(DISTRESS_TAIL)}")
    if "W_fail_N" in header:
        return _read_distress_by_name(path, records, line, header)
    tail = DISTRESS_TAIL
    if tuple(header[-4:-1]) == DISTRESS_ERROR_COLUMNS:
        tail = DISTRESS_TAIL[:4] + DISTRESS_ERROR_COLUMNS + DISTRESS_TAIL[4:]
    middle = header[1:-len(tail)]
    sliding = bool(middle) and middle[-1] == "sliding"
    if sliding:
        middle = middle[:-1]
    if (not _axes_columns_ok(middle) or header[0] != "speed_rad_s" or "sliding" in middle
            or tuple(header[-len(tail):]) != tail):
        raise InputError(f"{path}: line {line}: expected the header {DISTRESS_RUN_COLUMNS},"
                         f"{','.join(DISTRESS_TAIL)}, got {','.join(header)}")
    rows = []
    for line, fields in records:
        if len(fields) < len(header):
            raise InputError(f"{path}: line {line}: expected {len(header)} comma-separated fields "
                             f"as in the header, got {len(fields)}")
        # The method is free text that twb writes unquoted, so any extra commas belong to it.
        n = len(header) - 1
        fields = fields[:n] + [",".join(fields[n:])]
        speed = _number(path, line, "speed_rad_s", fields[0])
        # The run's axes by their place (right after the speed), not by their names.
        parameter = _axes_tag(path, line, middle, fields[1:1 + len(middle)])
        k = len(header) - len(tail)
        w_d, low, high, fold = (_number(path, line, tail[i], fields[k + i], optional=True)
                                for i in range(4))
        extrapolated = error = None
        if len(tail) > len(DISTRESS_TAIL):
            extrapolated, error = (_number(path, line, tail[i], fields[k + i], optional=True) for i in (5, 6))
        film = _run_tags(path, line, fields, header)[1] if sliding else None
        rows.append(DistressRow(speed, parameter, w_d, low, high, fold, fields[-1].strip(), film,
                                extrapolated, error))
    return rows


def fields_path(directory, state):
    return os.path.join(directory, "fields", f"state_{state:04d}.csv")


def read_fields(path):
    """fields/state_NNNN.csv as {film: {"sliding": bool, "r": radii, "theta": angles,
    column: 2-D array [radius, angle]}}, checked to be a complete polar grid per film."""
    records = _records(path)
    header = _header(path, records, FIELDS_COLUMNS, "fields")
    # The optional columns a run wrote (the washer's deflection with elastic_washer).
    read = FIELDS_COLUMNS + tuple(c for c in FIELDS_OPTIONAL if c in header)
    index = {c: header.index(c) for c in read}
    rows = {}
    for line, fields in records:
        _check_width(path, line, fields, header)
        values = {c: _number(path, line, c, fields[index[c]]) for c in read}
        for c, allowed in (("film", (1.0, 2.0)), ("sliding", (0.0, 1.0))):
            if values[c] not in allowed:
                raise InputError(f"{path}: line {line}: column '{c}': expected "
                                 f"{' or '.join(f'{a:g}' for a in allowed)}, "
                                 f"got {fields[index[c]].strip()!r}")
        rows.setdefault(int(values["film"]), []).append((line, values))
    if not rows:
        raise InputError(f"{path}: line 2: expected one row per node of each film, got none")
    films = {}
    for film, entries in rows.items():
        r = np.unique([v["r_m"] for _, v in entries])
        theta = np.unique([v["theta_rad"] for _, v in entries])
        if len(entries) != r.size * theta.size or r.size < 2 or theta.size < 3:
            raise InputError(f"{path}: line {entries[-1][0]}: film {film}: expected a complete "
                             f"polar grid (every radius at every angle), got {len(entries)} rows "
                             f"for {r.size} radii and {theta.size} angles")
        grid = {c: np.full((r.size, theta.size), np.nan) for c in read[4:]}
        sliding = set()
        for line, v in entries:
            i, j = np.searchsorted(r, v["r_m"]), np.searchsorted(theta, v["theta_rad"])
            if not np.isnan(grid["h_m"][i, j]):
                raise InputError(f"{path}: line {line}: film {film}: node r = {v['r_m']:g} m, "
                                 f"theta = {v['theta_rad']:g} rad appears twice")
            for c in grid:
                grid[c][i, j] = v[c]
            sliding.add(v["sliding"])
        if len(sliding) != 1:
            raise InputError(f"{path}: line {entries[-1][0]}: film {film}: column 'sliding': "
                             f"expected the same value on every row of the film")
        films[film] = dict(grid, sliding=sliding.pop() == 1.0, r=r, theta=theta)
    return films
