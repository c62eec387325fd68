#!/usr/bin/python3
"""Figures of twb results in the layout of Jackson & Green (2006), Figs. 6-15.

    twb_plot.py RESULTS_DIR [RESULTS_DIR ...] [--out FIGDIR] [--format png,svg] [--state N]

Reads states.csv (required), distress.csv, trajectory.csv, sliding.csv and run.json from each
directory, merges the directories (e.g. one load sweep per speed), and writes one file
per figure and format into FIGDIR (default: RESULTS_DIR/figures of the first
directory). A directory with fields/ (output.fields) also gets polar maps of one
state's fields: state N, or by default the last state below the distress load. Prints the files written. Exit status 2 when an input is missing or
malformed. docs/figures.md describes each figure.
"""

import argparse
import csv
import json
import math
import os
import re
import sys
from dataclasses import dataclass, field

import matplotlib

# Figures only ever go to files, and the machines that make them usually have no display.
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

STATE_COLUMNS = (
    "load_N", "speed_rad_s", "T_mean_C", "T_max_C", "hmin_over_sigma", "gamma_x_ratio",
    "gamma_y_ratio", "fluid_share", "contact_share", "torque_Nm", "f_eff", "stribeck",
    "converged", "iterations", "residual", "energy_error", "wall_ms")
TRAJECTORY_COLUMNS = (
    "t_s", "T_mean_C", "T_max_C", "hmin_over_sigma", "contact_share", "f_eff", "load_N")
DISTRESS_TAIL = ("W_d_N", "bracket_low_N", "bracket_high_N", "fold_N", "method")
# Written since W_d has an error bar (study.error_estimate: richardson), before the method.
DISTRESS_ERROR_COLUMNS = ("W_d_fine_N", "W_d_extrapolated_N", "W_d_error_N")
SLIDING_COLUMNS = (
    "speed_rad_s", "load_N", "sliding", "film_area_m2", "fluid_force_N", "fluid_share",
    "contact_share", "torque_Nm", "f_eff", "hmin_over_sigma", "T_mean_C", "chosen")
# The columns twb adds after the speed when a study runs several configurations: the
# value of its second parameter, and the film that slides.
PARAMETER_COLUMNS = ("friction_coefficient", "gear_tilt_rad", "roughness_Rq_m")
SLIDING_LABELS = {
    "carrier_washer": "film 1 slides (washer stuck to the gear)",
    "washer_gear": "film 2 slides (washer stuck to the carrier)",
}
LINESTYLES = ("-", "--", "-.", ":")
FIELDS_COLUMNS = (
    "film", "sliding", "r_m", "theta_rad", "h_m", "p_Pa", "p_contact_Pa", "T_film_C",
    "T_surfaces_C", "viscosity_Pa_s")
FORMATS = ("png", "svg", "pdf")
DPI = 150

LOAD_LABEL = r"load $F_{ext}$ (N)"
HMIN_LABEL = r"$h_{min}/\sigma$"
CONTACT_LABEL = r"$F_{cont}/F_{ext}$"
FEFF_LABEL = r"effective friction coefficient $f_{eff}$"
STRIBECK_LABEL = (r"Stribeck number $Z\,N\,/\,P$"
                  "\n(Z: viscosity in Pa·s, N: speed in rev/s, P: $F_{ext}$/washer area in Pa)")

PARAMETER_FORMATS = {
    "friction_coefficient": "dry friction coefficient {:g}",
    "gear_tilt_rad": r"$\gamma_{{tilt}}$ = {:g} rad",
    "roughness_Rq_m": r"$R_q$ = {:g} m",
}


class InputError(Exception):
    """An input that is not what twb writes; the message names the file and line."""


# ----------------------------------------------------------------------------- reading

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


def _run_tags(path, line, fields, header):
    """The run a row belongs to: ((parameter column, value) or None, sliding film or None)."""
    parameter = next((c for c in header if c in PARAMETER_COLUMNS), None)
    tag = None
    if parameter is not None:
        tag = (parameter, _number(path, line, parameter, fields[header.index(parameter)],
                                  optional=True))
    sliding = None
    if "sliding" in header:
        sliding = fields[header.index("sliding")].strip()
        if sliding not in SLIDING_LABELS:
            raise InputError(f"{path}: line {line}: column 'sliding': expected one of "
                             f"{', '.join(SLIDING_LABELS)}, got {sliding!r}")
    return tag, sliding


def _read_table(path, required, what, optional=()):
    """Columns of a twb table as float arrays (optional ones when present), in file
    order, and each row's run tags."""
    records = _records(path)
    header = _header(path, records, required, what)
    names = list(required) + [c for c in optional if c in header]
    index = {c: header.index(c) for c in names}
    columns = {c: [] for c in names}
    tags = []
    for line, fields in records:
        _check_width(path, line, fields, header)
        for c in names:
            columns[c].append(_number(path, line, c, fields[index[c]]))
        tags.append(_run_tags(path, line, fields, header))
        if "converged" in columns and columns["converged"][-1] not in (0.0, 1.0):
            raise InputError(f"{path}: line {line}: column 'converged': expected 0 or 1, "
                             f"got {fields[index['converged']].strip()!r}")
    return {c: np.array(v, dtype=float) for c, v in columns.items()}, tags


def read_states(path):
    """Columns of states.csv as float arrays, in file order, and each state's run tags."""
    return _read_table(path, STATE_COLUMNS, "states.csv")


def read_trajectory(path):
    # speed_rad_s is optional: twb wrote it only from the multi-speed load sweep on.
    return _read_table(path, TRAJECTORY_COLUMNS, "trajectory.csv", optional=("speed_rad_s",))


# fold_curve.csv (study type distress_curve): the curve's parameter first, then these.
FOLD_CURVE_PARAMETERS = {
    "speed_rad_s": r"speed $\omega$ (rad/s)", "friction_coefficient": "dry friction coefficient",
    "gear_tilt_rad": "gear tilt (rad)", "ambient_C": "ambient temperature (°C)",
    "viscosity_scale": "oil viscosity / the scene's", "roughness_Rq_m": "roughness Rq (m)"}
FOLD_CURVE_TAIL = ("W_fold_N", "fold", "T_mean_C", "T_max_C", "hmin_over_sigma", "contact_share", "f_eff")
FOLD_KINDS = ("distress", "recovery", "cusp", "turn")


def read_fold_curve(path):
    """fold_curve.csv: (parameter column, rows as dicts with 'p', 'load', 'fold', ...,
    and 'member': (family column, value) of a family of curves, else None)."""
    records = _records(path)
    expected = f"[<family>,]<parameter>,{','.join(FOLD_CURVE_TAIL)}"
    line, header = _header_line(path, records, expected)
    family = header[0] if len(header) == len(FOLD_CURVE_TAIL) + 2 and header[0] in PARAMETER_COLUMNS else None
    first = 1 if family else 0
    if len(header) != len(FOLD_CURVE_TAIL) + 1 + first or header[first] not in FOLD_CURVE_PARAMETERS \
            or tuple(header[first + 1:]) != FOLD_CURVE_TAIL:
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


@dataclass
class DistressRow:
    speed: float
    parameter: object  # (column name, value) or None
    w_d: object
    low: object
    high: object
    fold: object
    method: str
    sliding: object = None  # the sliding film of a sliding choice's row
    extrapolated: object = None  # mesh-converged W_d (Richardson), N
    error: object = None  # its error bar, N


def read_distress(path):
    records = _records(path)
    line, header = _header_line(path, records,
                                f"speed_rad_s[,<parameter>][,sliding],{','.join(DISTRESS_TAIL)}")
    tail = DISTRESS_TAIL
    if tuple(header[-4:-1]) == DISTRESS_ERROR_COLUMNS:
        tail = DISTRESS_TAIL[:4] + DISTRESS_ERROR_COLUMNS + DISTRESS_TAIL[4:]
    middle = header[1:-len(tail)]
    sliding = bool(middle) and middle[-1] == "sliding"
    if sliding:
        middle = middle[:-1]
    if (len(middle) > 1 or header[0] != "speed_rad_s" or "sliding" in middle
            or tuple(header[-len(tail):]) != tail):
        raise InputError(f"{path}: line {line}: expected the header speed_rad_s[,<parameter>][,sliding],"
                         f"{','.join(DISTRESS_TAIL)}, got {','.join(header)}")
    parameter = middle[0] if middle else None
    rows = []
    for line, fields in records:
        if len(fields) < len(header):
            raise InputError(f"{path}: line {line}: expected {len(header)} comma-separated fields "
                             f"as in the header, got {len(fields)}")
        # The method is free text that twb writes unquoted, so any extra commas belong to it.
        n = len(header) - 1
        fields = fields[:n] + [",".join(fields[n:])]
        speed = _number(path, line, "speed_rad_s", fields[0])
        value = None
        if parameter is not None:
            value = _number(path, line, parameter, fields[1], optional=True)
        k = len(header) - len(tail)
        w_d, low, high, fold = (_number(path, line, tail[i], fields[k + i], optional=True)
                                for i in range(4))
        extrapolated = error = None
        if len(tail) > len(DISTRESS_TAIL):
            extrapolated, error = (_number(path, line, tail[i], fields[k + i], optional=True) for i in (5, 6))
        film = _run_tags(path, line, fields, header)[1] if sliding else None
        rows.append(DistressRow(speed, None if parameter is None else (parameter, value),
                                w_d, low, high, fold, fields[-1].strip(), film, extrapolated, error))
    return rows


def fields_path(directory, state):
    return os.path.join(directory, "fields", f"state_{state:04d}.csv")


def read_fields(path):
    """fields/state_NNNN.csv as {film: {"sliding": bool, "r": radii, "theta": angles,
    column: 2-D array [radius, angle]}}, checked to be a complete polar grid per film."""
    records = _records(path)
    header = _header(path, records, FIELDS_COLUMNS, "fields")
    index = {c: header.index(c) for c in FIELDS_COLUMNS}
    rows = {}
    for line, fields in records:
        _check_width(path, line, fields, header)
        values = {c: _number(path, line, c, fields[index[c]]) for c in FIELDS_COLUMNS}
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
        grid = {c: np.full((r.size, theta.size), np.nan) for c in FIELDS_COLUMNS[4:]}
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


def friction_setting(path):
    """The boundary friction law of run.json's resolved scene, as a legend label.

    run.json is only used for labels, so an unreadable one is ignored, not an error."""
    try:
        with open(path, encoding="utf-8") as f:
            friction = json.load(f)["scene"]["friction"]
        law = friction["law"]
    except (OSError, ValueError, KeyError, TypeError):
        return None
    if law == "constant":
        return f"dry friction coefficient {friction.get('coefficient', '?')}"
    if law == "empirical":
        return "empirical friction law (eq. 18)"
    return str(law)


@dataclass
class Run:
    directory: str
    name: str
    states: dict
    tags: list = field(default_factory=list)  # per state: (parameter, sliding)
    distress: list = field(default_factory=list)
    trajectory: object = None
    trajectory_tags: list = field(default_factory=list)
    sliding: list = field(default_factory=list)
    friction: object = None
    has_fields: bool = False
    fold_curve: object = None  # (parameter column, rows) of fold_curve.csv


def read_run(directory):
    if not os.path.isdir(directory):
        raise InputError(f"{directory}: not a directory")
    states_path = os.path.join(directory, "states.csv")
    if not os.path.isfile(states_path):
        raise InputError(f"{directory}: no states.csv (every twb results directory has one)")
    states, tags = read_states(states_path)
    run = Run(directory, os.path.basename(os.path.normpath(os.path.abspath(directory))), states,
              tags)
    distress_path = os.path.join(directory, "distress.csv")
    if os.path.isfile(distress_path):
        run.distress = read_distress(distress_path)
    trajectory_path = os.path.join(directory, "trajectory.csv")
    if os.path.isfile(trajectory_path):
        run.trajectory, run.trajectory_tags = read_trajectory(trajectory_path)
    sliding_path = os.path.join(directory, "sliding.csv")
    if os.path.isfile(sliding_path):
        run.sliding = read_sliding(sliding_path)
    fold_curve_path = os.path.join(directory, "fold_curve.csv")
    if os.path.isfile(fold_curve_path):
        run.fold_curve = read_fold_curve(fold_curve_path)
    run.friction = friction_setting(os.path.join(directory, "run.json"))
    run.has_fields = os.path.isdir(os.path.join(directory, "fields"))
    return run


# ----------------------------------------------------------------------------- plotting

def speed_key(speed):
    # Speeds are written with 10 significant digits; rounding keeps 545 and 545.0000000001
    # (a speed given in rpm, say) on one curve.
    return float(f"{speed:.6g}")


def speed_label(speed):
    return f"{speed:g} rad/s"


MARKERS = ("o", "s", "^", "D", "v", "<", ">", "p", "h", "*")


class Style:
    """One colour and marker per speed (or other series key), the same in every figure."""

    def __init__(self, keys):
        self.keys = sorted(set(keys))
        cmap = plt.get_cmap("tab10" if len(self.keys) <= 10 else "viridis")
        n = max(len(self.keys) - 1, 1)
        self.colors = {k: cmap(i if len(self.keys) <= 10 else i / n) for i, k in enumerate(self.keys)}
        self.markers = {k: MARKERS[i % len(MARKERS)] for i, k in enumerate(self.keys)}


@dataclass
class Data:
    """All directories merged: one array per states.csv column, plus the rest."""
    states: dict
    friction: list          # per state: its friction setting as a label (or None)
    parameters: list        # per state: (parameter column, value) of its run, or None
    distress: list
    trajectories: list      # (label, columns)
    sliding: list           # rows of sliding.csv
    speed_style: Style
    fold_curves: list = field(default_factory=list)  # (run name, parameter column, rows)
    rpm: bool = False       # speeds drawn in rpm


def _split_trajectory(columns, tags):
    """A trajectory.csv of several runs (speeds, parameter values, sliding films) as one
    (key, columns) per run, in file order."""
    keys = []
    for k, tag in enumerate(tags):
        speed = speed_key(columns["speed_rad_s"][k]) if "speed_rad_s" in columns else None
        key = (speed,) + tuple(tag)
        if key not in keys:
            keys.append(key)
    out = []
    for key in keys:
        idx = np.array([((speed_key(columns["speed_rad_s"][k]) if "speed_rad_s" in columns else None),)
                        + tuple(tag) == key for k, tag in enumerate(tags)])
        out.append((key, {c: v[idx] for c, v in columns.items()}))
    return out


def merge(runs):
    states = {c: np.concatenate([r.states[c] for r in runs]) for c in STATE_COLUMNS}
    parameters = [tag[0] for r in runs for tag in r.tags]
    # A state of a friction coefficient sweep has its own coefficient; otherwise the
    # run's friction law (run.json) labels it.
    friction = [(parameter_label(tag[0]) if tag[0] and tag[0][0] == "friction_coefficient"
                 else r.friction) for r in runs for tag in r.tags]
    distress = [row for r in runs for row in r.distress]
    trajectories = []
    for r in runs:
        if r.trajectory is None:
            continue
        pieces = _split_trajectory(r.trajectory, r.trajectory_tags)
        for (speed, parameter, sliding), columns in pieces:
            parts = []
            speeds = {speed} if speed is not None else {speed_key(v) for v in r.states["speed_rad_s"]}
            if len(speeds) == 1:
                parts.append(speed_label(next(iter(speeds))))
            if parameter is not None:
                parts.append(parameter_label(parameter))
            if sliding is not None:
                parts.append(SLIDING_LABELS[sliding])
            loads = set(columns["load_N"])
            if len(loads) == 1:
                parts.append(f"{next(iter(loads)):g} N")
            trajectories.append((", ".join(parts) or r.name, columns))
    sliding = [row for r in runs for row in r.sliding]
    keys = ([speed_key(v) for v in states["speed_rad_s"]] + [speed_key(d.speed) for d in distress]
            + [speed_key(row["speed_rad_s"]) for row in sliding])
    data = Data(states, friction, parameters, distress, trajectories, sliding, Style(keys))
    data.fold_curves = [(r.name,) + r.fold_curve for r in runs if r.fold_curve is not None]
    return data


def parameter_order(parameters):
    """The distinct (column, value) runs of the merged states, sorted; None first."""
    found = {p for p in parameters if p is not None}
    return sorted(found, key=lambda p: (p[0], -math.inf if p[1] is None else p[1]))


def _positive(values):
    """Non-positive values as NaN, so that a log axis leaves a gap instead of a plunge."""
    out = np.array(values, dtype=float)
    out[out <= 0] = np.nan
    return out


def draw_by_speed(ax, data, xcol, ycol, logx=False, logy=False):
    """One curve per speed (and per value of a study's second parameter, in its own
    line style), points joined in order of load; returns whether any point had not
    converged."""
    s = data.states
    speeds = np.array([speed_key(v) for v in s["speed_rad_s"]])
    runs = parameter_order(data.parameters)
    styles = {p: LINESTYLES[i % len(LINESTYLES)] for i, p in enumerate(runs)}
    jumps = {(speed, parameter): w_d for speed, parameter, w_d in distress_lines(data)}
    any_unconverged = False
    for key in data.speed_style.keys:
        for run in [None] + runs:
            idx = np.flatnonzero((speeds == key) & np.array([p == run for p in data.parameters],
                                                            dtype=bool))
            if idx.size == 0:
                continue
            # Several directories may hold the same speed (e.g. one point run per load);
            # a stable sort keeps the solver's order among equal loads.
            idx = idx[np.argsort(s["load_N"][idx], kind="stable")]
            x, y = s[xcol][idx], s[ycol][idx]
            if logx:
                x = _positive(x)
            if logy:
                y = _positive(y)
            ok = s["converged"][idx] == 1
            color, marker = data.speed_style.colors[key], data.speed_style.markers[key]
            label = speed_label(key) + ("" if run is None else ", " + parameter_label(run))
            # Past W_d the state jumps to the hot branch: no line through the jump, an
            # arrow across it.
            w_d = jumps.get((key, run))
            loads = s["load_N"][idx]
            cut = np.flatnonzero((loads[:-1] <= w_d) & (loads[1:] > w_d)) if w_d is not None else []
            xs, ys = x[ok].astype(float), y[ok].astype(float)
            if len(cut) and ok[cut[0]] and ok[cut[0] + 1]:
                k = int(np.count_nonzero(ok[:cut[0] + 1]))
                # (an end off a log axis, a zero share, gets the break without the arrow)
                if np.isfinite([xs[k], ys[k], xs[k - 1], ys[k - 1]]).all():
                    ax.annotate("", xy=(xs[k], ys[k]), xytext=(xs[k - 1], ys[k - 1]),
                                arrowprops=dict(arrowstyle="->", color=color, linestyle=":", linewidth=1.0))
                xs, ys = np.insert(xs, k, np.nan), np.insert(ys, k, np.nan)
            ax.plot(xs, ys, color=color, marker=marker, markersize=4, linewidth=1.2,
                    linestyle=styles.get(run, "-"), label=label)
            if not ok.all():
                any_unconverged = True
                ax.plot(x[~ok], y[~ok], linestyle="none", marker=marker, markersize=6,
                        markerfacecolor="none", markeredgecolor=color)
    if logx:
        ax.set_xscale("log")
    if logy:
        ax.set_yscale("log")
    return any_unconverged


def distress_lines(data):
    """(speed, parameter, W_d) for the vertical distress marks on load axes.

    A sliding choice's rows are left out: its states are the chosen configuration at
    each load, which may change along the sweep."""
    return [(speed_key(d.speed), d.parameter, d.w_d) for d in data.distress
            if d.sliding is None and d.w_d is not None]


def finish_legend(ax, unconverged=False, distress=False):
    handles, labels = ax.get_legend_handles_labels()
    if distress:
        handles.append(Line2D([], [], color="black", linestyle=":", linewidth=1.2))
        labels.append(r"distress load $W_d$")
    if unconverged:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="o",
                              markerfacecolor="none"))
        labels.append("not converged")
    if handles:
        ax.legend(handles, labels, fontsize="small", framealpha=0.85)


def new_figure(title, paper_figure=None, size=(6.4, 4.8)):
    fig, ax = plt.subplots(figsize=size)
    if paper_figure is not None:
        title = f"{title}\n(cf. Jackson & Green 2006, Fig. {paper_figure})"
    ax.set_title(title, fontsize="medium")
    ax.grid(True, which="major", alpha=0.3)
    return fig, ax


def figure_vs_load(data, column, ylabel, title, paper_figure, logy=False):
    fig, ax = new_figure(title, paper_figure)
    unconverged = draw_by_speed(ax, data, "load_N", column, logy=logy)
    marks = distress_lines(data)
    for key, _, w_d in marks:
        ax.axvline(w_d, color=data.speed_style.colors[key], linestyle=":", linewidth=1.2)
    ax.set_xlabel(LOAD_LABEL)
    ax.set_ylabel(ylabel)
    finish_legend(ax, unconverged, distress=bool(marks))
    return fig


def figure_contact_vs_hmin(data):
    fig, ax = new_figure("Contact share vs minimum film thickness", 13)
    unconverged = draw_by_speed(ax, data, "hmin_over_sigma", "contact_share")
    # The paper reads its figure against this customary threshold of significant contact.
    ax.axvline(3.0, color="grey", linestyle="--", linewidth=0.8)
    ax.set_xlabel(HMIN_LABEL)
    ax.set_ylabel(CONTACT_LABEL)
    finish_legend(ax, unconverged)
    return fig


# Where the paper puts the optimum (the Stribeck curve's minimum) in its text on Figs. 14
# and 16: its simulation at Z N / P of about 2.0e-6, its experiments at about 1.0e-6.
PAPER_STRIBECK_OPTIMA = ((2.0e-6, "paper, numerical: optimum near 2.0e-6", "--"),
                         (1.0e-6, "paper, experiments: optimum near 1.0e-6", ":"))


def figure_stribeck(data):
    fig, ax = new_figure("Stribeck curve", 14)
    unconverged = draw_by_speed(ax, data, "stribeck", "f_eff", logx=True)
    for x, label, style in PAPER_STRIBECK_OPTIMA:
        ax.axvline(x, color="0.4", linestyle=style, linewidth=1.0, label=label)
    ax.set_xlabel(STRIBECK_LABEL)
    ax.set_ylabel(FEFF_LABEL)
    finish_legend(ax, unconverged)
    return fig


def figure_stribeck_by_friction(data):
    """Fig. 15: one colour per friction law across the merged runs, one curve per
    (law, speed)."""
    settings = sorted({f for f in data.friction if f is not None})
    style = Style(settings)
    s = data.states
    fig, ax = new_figure("Stribeck curve for several dry friction coefficients", 15)
    friction = np.array([f if f is not None else "" for f in data.friction], dtype=object)
    speeds = np.array([speed_key(v) for v in s["speed_rad_s"]])
    for setting in settings:
        labelled = False
        for key in data.speed_style.keys:
            idx = np.flatnonzero((friction == setting) & (speeds == key) & (s["converged"] == 1))
            if idx.size == 0:
                continue
            idx = idx[np.argsort(s["load_N"][idx], kind="stable")]
            ax.plot(_positive(s["stribeck"][idx]), s["f_eff"][idx], color=style.colors[setting],
                    marker=style.markers[setting], markersize=4, linewidth=1.2,
                    label=None if labelled else setting)
            labelled = True
    ax.set_xscale("log")
    ax.set_xlabel(STRIBECK_LABEL)
    ax.set_ylabel(FEFF_LABEL)
    finish_legend(ax)
    return fig


def parameter_label(parameter):
    name, value = parameter
    if value is None:
        return f"{name} not set"
    return PARAMETER_FORMATS.get(name, name + " = {:g}").format(value)


def series_label(key):
    parameter, sliding = key
    parts = ([] if parameter is None else [parameter_label(parameter)]) + \
        ([] if sliding is None else [SLIDING_LABELS[sliding]])
    return ", ".join(parts) if parts else r"$W_d$"


def speed_axis(data):
    """Scale from rad/s and the axis label: rpm when asked for."""
    if data.rpm:
        return 60.0 / (2.0 * math.pi), r"speed (rpm)"
    return 1.0, r"speed $\omega$ (rad/s)"


def searched_up_to(method):
    """The highest load a search without W_d reached, from its method ("no fold up to 2000 N ...")."""
    m = re.search(r"up to ([0-9.eE+-]+) N", method or "")
    return float(m.group(1)) if m else None


def figure_fold_curve(data, name, column, rows):
    """The fold curve of a distress_curve study as the safe operating region: W_d against
    the parameter (solid), the hot branch's recovery fold (dashed), the cusp where the two
    meet and sudden distress ends; below W_d no sudden distress, between the two folds a
    bearing that once passed W_d stays hot. A family of curves (one per value of a second
    parameter) gets a colour per curve."""
    fig, ax = new_figure("Safe operating region: distress load along the curve")
    scale, xlabel = (speed_axis(data) if column == "speed_rad_s" else (1.0, FOLD_CURVE_PARAMETERS[column]))
    # The whole range the study searched: its end searches are distress.csv's rows.
    ends = [scale * d.speed for d in data.distress] if column == "speed_rad_s" else []
    unit = re.search(r"\(([^)]*)\)$", xlabel)
    unit = " " + unit.group(1) if unit else ""
    members = sorted({r["member"] for r in rows if r["member"] is not None}, key=lambda m: m[1]) or [None]
    single = len(members) == 1
    style = Style(range(len(members)))
    for i, member in enumerate(members):
        mine = [r for r in rows if r["member"] == member]
        color = "tab:red" if single else style.colors[i]
        tag = "" if member is None else f" ({parameter_label(member)})"
        branches = {}
        for r in mine:
            if r["fold"] in ("distress", "recovery"):
                branches.setdefault(r["fold"], []).append((scale * r["p"], r["load"]))
            elif r["fold"] == "cusp":  # where both branches end: drawn into each
                for kind in ("distress", "recovery"):
                    branches.setdefault(kind, []).append((scale * r["p"], r["load"]))
        distress = np.array(sorted(branches.get("distress", [])), dtype=float).reshape(-1, 2)
        recovery = np.array(sorted(branches.get("recovery", [])), dtype=float).reshape(-1, 2)
        if len(distress):
            ax.plot(distress[:, 0], distress[:, 1], color=color, linewidth=1.8,
                    label=r"distress load $W_d$ (fold)" + tag)
            ax.fill_between(distress[:, 0], 0, distress[:, 1], color="tab:green" if single else color,
                            alpha=0.15 if single else 0.06, linewidth=0,
                            label="below $W_d$: no sudden distress" if single else None)
        if len(recovery):
            ax.plot(recovery[:, 0], recovery[:, 1], color="tab:blue" if single else color, linestyle="--",
                    linewidth=1.4, label="recovery: the hot branch's lowest load" if single else None)
        if single and len(distress) and len(recovery):
            lo, hi = max(distress[0, 0], recovery[0, 0]), min(distress[-1, 0], recovery[-1, 0])
            if hi > lo:
                x = np.linspace(lo, hi, 200)
                ax.fill_between(x, np.interp(x, recovery[:, 0], recovery[:, 1]),
                                np.interp(x, distress[:, 0], distress[:, 1]), facecolor="none",
                                edgecolor="tab:orange", hatch="//", linewidth=0,
                                label="between the folds: stays hot once past $W_d$")
        for r in mine:
            if r["fold"] not in ("cusp", "turn"):
                continue
            x = scale * r["p"]
            ax.plot([x], [r["load"]], marker="*", markersize=14, color="black" if single else color,
                    linestyle="none",
                    label=("cusp: sudden distress ends" if r["fold"] == "cusp" else "the curve turns back")
                    if single or i == 0 else None)
            if r["fold"] == "cusp":
                ax.annotate(f"cusp {x:.4g}{unit}, {r['load']:.4g} N", (x, r["load"]), textcoords="offset points",
                            xytext=(8, -14), fontsize="small", color="black" if single else color)
            if r["fold"] == "cusp" and single and len(distress):
                # The side of the cusp the curve does not reach has no fold: gradual heating.
                left = distress[:, 0].mean() > x
                xmin, xmax = ax.get_xlim()
                if ends:
                    xmin, xmax = min(xmin, min(ends)), max(xmax, max(ends))
                ax.axvspan(xmin if left else x, x if left else xmax, color="0.85", alpha=0.5, linewidth=0,
                           label="no fold: gradual heating")
                ax.set_xlim(xmin, xmax)
    if not single:
        ax.plot([], [], color="0.3", linestyle="--", label="recovery folds (dashed)")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("load (N)")
    ax.set_ylim(bottom=0)
    ax.legend(fontsize="small", framealpha=0.85, loc="lower right")
    return fig


def figure_distress_map(data):
    series = {}
    for d in data.distress:
        series.setdefault((d.parameter, d.sliding), []).append(d)
    plottable = [k for k, rows in series.items()
                 if any(r.w_d is not None or r.fold is not None for r in rows)]
    if not plottable:
        return None
    plottable.sort(key=lambda k: (k[0] is not None, "" if k[0] is None else k[0][0],
                                  -math.inf if k[0] is None or k[0][1] is None else k[0][1],
                                  k[1] or ""))
    style = Style(range(len(plottable)))
    fig, ax = new_figure(r"Distress load $W_d$ vs speed: below it, no sudden distress")
    scale, xlabel = speed_axis(data)
    any_fold = any_estimate = any_beyond = False
    for i, key in enumerate(plottable):
        rows = sorted(series[key], key=lambda r: r.speed)
        color, marker = style.colors[i], style.markers[i]
        label = series_label(key)
        found = [r for r in rows if r.w_d is not None]
        # A speed without W_d up to the highest load searched is drawn there, as "> load_end".
        beyond = [(r.speed, load) for r in rows
                  if r.w_d is None and (load := searched_up_to(r.method)) is not None]
        if beyond:
            any_beyond = True
            ax.plot([scale * b[0] for b in beyond], [b[1] for b in beyond], linestyle="none", marker="^",
                    markersize=9, markerfacecolor="none", markeredgecolor=color)
            for speed, load in beyond:
                ax.annotate(f"> {load:g} N", (scale * speed, load), textcoords="offset points", xytext=(7, -4),
                            fontsize="small", color=color)
        if found:
            x = [scale * r.speed for r in found]
            y = [r.w_d for r in found]
            if len(found) > 1:
                ax.fill_between(x, 0, y, color=color, alpha=0.08, linewidth=0)
            # A missing bracket side draws no bar; a W_d outside its bracket would be a
            # twb bug, drawn as a zero-length bar rather than hidden.
            below = [max(r.w_d - r.low, 0.0) if r.low is not None else 0.0 for r in found]
            above = [max(r.high - r.w_d, 0.0) if r.high is not None else 0.0 for r in found]
            ax.errorbar(x, y, yerr=[below, above], color=color, marker=marker, markersize=5,
                        linewidth=1.2, capsize=4, label=label)
        converged = [r for r in rows if r.extrapolated is not None and r.error is not None]
        if converged:
            any_estimate = True
            ax.errorbar([scale * r.speed for r in converged], [r.extrapolated for r in converged],
                        yerr=[r.error for r in converged], color=color, marker="s", markersize=5,
                        markerfacecolor="none", linestyle="--", linewidth=1.0, capsize=4)
        folds = [r for r in rows if r.fold is not None]
        if folds:
            any_fold = True
            ax.plot([scale * r.speed for r in folds], [r.fold for r in folds], linestyle="none",
                    marker="D", markersize=8, markerfacecolor="none", markeredgecolor=color,
                    markeredgewidth=1.2)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("load (N)")
    ax.set_ylim(bottom=0)
    handles, labels = ax.get_legend_handles_labels()
    handles.append(Line2D([], [], color="black", marker="|", linestyle="none", markersize=10))
    labels.append("bracket: settled / ran away")
    if any_beyond:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="^", markerfacecolor="none"))
        labels.append("no W_d up to the highest load searched (> load_end)")
    if any_fold:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="D",
                              markerfacecolor="none"))
        labels.append("fold of the steady branch")
    if any_estimate:
        handles.append(Line2D([], [], color="black", linestyle="--", marker="s", markerfacecolor="none"))
        labels.append("mesh-converged W_d (Richardson) ± error")
    ax.legend(handles, labels, fontsize="small", framealpha=0.85)
    return fig


def figure_trajectory(data):
    fig, axes = plt.subplots(2, 2, sharex=True, figsize=(9.6, 7.0))
    (ax_t, ax_h), (ax_c, ax_f) = axes
    several = len(data.trajectories) > 1
    style = Style(range(len(data.trajectories)))
    for i, (label, tr) in enumerate(data.trajectories):
        color = style.colors[i] if several else None
        t = tr["t_s"]
        prefix = f"{label}: " if several else ""
        ax_t.plot(t, tr["T_mean_C"], color=color or "tab:blue", linewidth=1.4,
                  label=prefix + "mean washer")
        ax_t.plot(t, tr["T_max_C"], color=color or "tab:red", linestyle="--", linewidth=1.4,
                  label=prefix + "max film")
        ax_h.plot(t, tr["hmin_over_sigma"], color=color, linewidth=1.4, label=label)
        ax_c.plot(t, tr["contact_share"], color=color, linewidth=1.4, label=label)
        ax_f.plot(t, tr["f_eff"], color=color, linewidth=1.4, label=label)
    ax_t.set_ylabel("temperature (°C)")
    ax_h.set_ylabel(HMIN_LABEL)
    ax_c.set_ylabel(CONTACT_LABEL)
    ax_f.set_ylabel(FEFF_LABEL)
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("pseudo-time t (s)")
    ax_t.legend(fontsize="small")
    if several:
        ax_h.legend(fontsize="small")
    title = "Thermal transient after a load step"
    if not several:
        title += f" ({data.trajectories[0][0]})"
    fig.suptitle(title, fontsize="medium")
    return fig


def figure_sliding(data):
    """Which film slides: friction torque and lift (the sliding film's fluid force) of
    both configurations against load, one colour per speed, the chosen configuration
    (lower torque) filled."""
    fig, (ax_t, ax_l) = plt.subplots(1, 2, figsize=(11.0, 4.8))
    films = [f for f in SLIDING_LABELS if any(r["sliding"] == f for r in data.sliding)]
    styles = {f: LINESTYLES[i] for i, f in enumerate(SLIDING_LABELS)}
    areas = {}
    for key in data.speed_style.keys:
        for film in films:
            rows = sorted((r for r in data.sliding
                           if r["sliding"] == film and speed_key(r["speed_rad_s"]) == key),
                          key=lambda r: r["load_N"])
            if not rows:
                continue
            areas[film] = rows[0]["film_area_m2"]
            color, marker = data.speed_style.colors[key], data.speed_style.markers[key]
            load = np.array([r["load_N"] for r in rows])
            chosen = np.array([r["chosen"] == 1 for r in rows])
            for ax, column in ((ax_t, "torque_Nm"), (ax_l, "fluid_force_N")):
                y = np.array([r[column] for r in rows])
                ax.plot(load, y, color=color, linestyle=styles[film], linewidth=1.2)
                ax.plot(load[chosen], y[chosen], linestyle="none", marker=marker, markersize=5,
                        color=color)
                ax.plot(load[~chosen], y[~chosen], linestyle="none", marker=marker, markersize=5,
                        markerfacecolor="none", markeredgecolor=color)
    for ax in (ax_t, ax_l):
        ax.grid(True, alpha=0.3)
        ax.set_xlabel(LOAD_LABEL)
    ax_t.set_ylabel(r"friction torque $T_{frict}$ (N·m)")
    ax_l.set_ylabel(r"lift: fluid force of the sliding film $F_{fluid}$ (N)")
    handles = [Line2D([], [], color=data.speed_style.colors[k], marker=data.speed_style.markers[k],
                      linestyle="none") for k in data.speed_style.keys
               if any(speed_key(r["speed_rad_s"]) == k for r in data.sliding)]
    labels = [speed_label(k) for k in data.speed_style.keys
              if any(speed_key(r["speed_rad_s"]) == k for r in data.sliding)]
    for film in films:
        handles.append(Line2D([], [], color="black", linestyle=styles[film]))
        labels.append(f"{SLIDING_LABELS[film]}, {areas[film] * 1e6:.1f} mm²")
    handles += [Line2D([], [], color="black", marker="o", linestyle="none"),
                Line2D([], [], color="black", marker="o", linestyle="none", markerfacecolor="none")]
    labels += ["chosen: the lower torque", "not chosen"]
    ax_t.legend(handles, labels, fontsize="small", framealpha=0.85)
    title = "Which film slides: friction torque and lift of both configurations"
    if len(areas) == 2:
        a1, a2 = areas["carrier_washer"], areas["washer_gear"]
        title += (f"\n(film 2's area is {100 * (a1 - a2) / a1:.1f} % below film 1's, film 1's "
                  f"{100 * (a1 - a2) / a2:.1f} % above film 2's; cf. the paper's 31 %)")
    fig.suptitle(title, fontsize="medium")
    return fig


# Column, scale to the plotted unit, colour-bar label, colour map.
FIELD_PANELS = (
    ("p_Pa", 1e-6, "fluid pressure $p$ (MPa)", "viridis"),
    ("h_m", 1e6, "film thickness $h$ (µm)", "cividis"),
    ("p_contact_Pa", 1e-6, "asperity contact pressure $p_c$ (MPa)", "magma"),
    ("T_film_C", 1.0, "film-node temperature $T_f$ (°C)", "inferno"),
)
FILM_NAMES = {1: "film 1 (carrier–washer)", 2: "film 2 (washer–gear)"}


def default_state(run):
    """The last state (1-based row of states.csv) with a fields file whose load lies
    below the distress load W_d of its speed, or without any W_d the last state with
    fields; None when the directory has none."""
    loads, speeds = run.states["load_N"], run.states["speed_rad_s"]
    with_fields = [k for k in range(1, loads.size + 1)
                   if os.path.isfile(fields_path(run.directory, k))]
    # Rows of a second parameter or a sliding choice are left out: they are not one
    # distress load per speed.
    limits = {speed_key(d.speed): d.w_d for d in run.distress
              if d.parameter is None and d.sliding is None and d.w_d is not None}
    below = [k for k in with_fields
             if speed_key(speeds[k - 1]) in limits and loads[k - 1] < limits[speed_key(speeds[k - 1])]]
    if below:
        return below[-1]
    return with_fields[-1] if with_fields else None


def select_fields(runs, state):
    """(run, state, fields) for every directory whose fields are to be mapped: state N
    where asked (then every directory must have it), else each directory's default."""
    selected = []
    for run in runs:
        if not run.has_fields:
            if state is not None:
                raise InputError(f"{run.directory}: no fields/ directory, so no state to map "
                                 f"(--state {state}); fields are written by a run with "
                                 f"output.fields: true")
            continue
        n = run.states["load_N"].size
        if state is not None and state > n:
            raise InputError(f"{os.path.join(run.directory, 'states.csv')}: --state {state}: "
                             f"expected a row of states.csv, 1 to {n}")
        k = state if state is not None else default_state(run)
        if k is None:
            continue
        path = fields_path(run.directory, k)
        if not os.path.isfile(path):
            raise InputError(f"{path}: no such file: state {k} has no fields")
        selected.append((run, k, read_fields(path)))
    return selected


def figure_fields(films, load, speed, caption):
    """Polar maps, one row per film (the sliding film first), one column per field."""
    order = sorted(films, key=lambda f: (not films[f]["sliding"], f))
    ncol = len(FIELD_PANELS)
    fig = plt.figure(figsize=(3.3 * ncol, 3.3 * len(order) + 0.9))
    for row, film in enumerate(order):
        f = films[film]
        r_mm = f["r"] * 1e3
        # Close the periodic seam: θ = 2π repeats θ = 0.
        theta = np.append(f["theta"], f["theta"][0] + 2 * math.pi)
        rr, tt = np.meshgrid(r_mm, theta, indexing="ij")
        for col, (column, scale, label, cmap) in enumerate(FIELD_PANELS):
            ax = fig.add_subplot(len(order), ncol, row * ncol + col + 1, projection="polar")
            values = f[column] * scale
            values = np.concatenate([values, values[:, :1]], axis=1)
            if column == "p_Pa" and not f["sliding"] and not values.any():
                ax.set_axis_off()
                ax.text(0.5, 0.5, f"no fluid pressure:\n{FILM_NAMES[film]}\ndoes not slide",
                        transform=ax.transAxes, ha="center", va="center", fontsize="small")
                continue
            ax.grid(False)  # pcolormesh over a grid is deprecated; the grid returns below
            mesh = ax.pcolormesh(tt, rr, values, shading="gouraud", cmap=cmap)
            # Circles at the film's radii (given in the film's title), unlabelled: labels
            # inside the annulus would hide the field.
            ax.set_ylim(0.0, r_mm[-1])
            ax.set_yticks([r_mm[0], r_mm[-1]])
            ax.set_yticklabels([])
            ax.tick_params(axis="x", labelsize="x-small")
            ax.grid(True, alpha=0.3)
            bar = fig.colorbar(mesh, ax=ax, shrink=0.75, pad=0.12)
            bar.set_label(label, fontsize="small")
            bar.ax.tick_params(labelsize="x-small")
            title = label.split(" (")[0]
            if col == 0 or (col == 1 and not f["sliding"]):
                title = (f"{FILM_NAMES[film]}{', sliding' if f['sliding'] else ''}\n"
                         f"r = {r_mm[0]:.4g}–{r_mm[-1]:.4g} mm: {title}")
            ax.set_title(title, fontsize="small")
    fig.suptitle(f"Fields at load $F_{{ext}}$ = {load:g} N, speed $\\omega$ = {speed:g} rad/s "
                 f"({caption})\nθ counter-clockwise from +x seen from +z; the sliding surface "
                 f"moves in +θ", fontsize="medium")
    return fig


def make_field_maps(selected, out_dir, formats, written):
    several = len(selected) > 1
    for run, state, films in selected:
        load = run.states["load_N"][state - 1]
        speed = run.states["speed_rad_s"][state - 1]
        caption = f"state {state}" + (f" of {run.name}" if several else "")
        stem = f"fields_{run.name}_state_{state:04d}" if several else f"fields_state_{state:04d}"
        save(figure_fields(films, load, speed, caption), out_dir, stem, formats, written)


def save(fig, out_dir, stem, formats, written):
    # Two-line axis labels (the Stribeck number's units) would otherwise be cut off.
    fig.tight_layout()
    for fmt in formats:
        path = os.path.join(out_dir, f"{stem}.{fmt}")
        # No date in the SVG, so that the same results give the same file.
        metadata = {"Date": None} if fmt in ("svg", "pdf") else None
        fig.savefig(path, dpi=DPI, metadata=metadata)
        written.append(path)
    plt.close(fig)


def make_figures(data, out_dir, formats):
    written = []
    if data.states["load_N"].size:
        for stem, column, ylabel, title, number, logy in (
                ("fig06_f_eff_vs_load", "f_eff", FEFF_LABEL,
                 "Effective friction coefficient vs load and speed", 6, False),
                ("fig07_mean_temperature_vs_load", "T_mean_C", "mean washer temperature (°C)",
                 "Mean bearing temperature vs load and speed", 7, False),
                ("fig08_hmin_over_sigma_vs_load", "hmin_over_sigma", HMIN_LABEL,
                 "Minimum film thickness vs load and speed", 8, False),
                ("fig09_gamma_x_ratio_vs_load", "gamma_x_ratio", r"$\gamma_x/\gamma_{tilt}$",
                 "Washer tilt about the x-axis vs load and speed", 9, False),
                ("fig10_gamma_y_ratio_vs_load", "gamma_y_ratio", r"$\gamma_y/\gamma_{tilt}$",
                 "Washer tilt about the y-axis vs load and speed", 10, False),
                ("fig11_fluid_share_vs_load", "fluid_share", r"$F_{fluid}/F_{ext}$",
                 "Load carried by the fluid film vs load and speed", 11, False),
                ("fig12_contact_share_vs_load", "contact_share", CONTACT_LABEL,
                 "Load carried by asperity contact vs load and speed", 12, True)):
            save(figure_vs_load(data, column, ylabel, title, number, logy), out_dir, stem,
                 formats, written)
        save(figure_contact_vs_hmin(data), out_dir, "fig13_contact_share_vs_hmin", formats, written)
        save(figure_stribeck(data), out_dir, "fig14_stribeck", formats, written)
        if len({f for f in data.friction if f is not None}) > 1:
            save(figure_stribeck_by_friction(data), out_dir, "fig15_stribeck_by_friction",
                 formats, written)
    else:
        print("twb_plot: note: no solved states, so no figures of states", file=sys.stderr)
    if data.distress:
        fig = figure_distress_map(data)
        if fig is None:
            print("twb_plot: note: distress.csv has neither a distress load nor a fold; "
                  "no distress map", file=sys.stderr)
        else:
            save(fig, out_dir, "distress_map", formats, written)
        for d in data.distress:
            if d.w_d is None:
                where = speed_label(speed_key(d.speed))
                if d.parameter is not None:
                    where += ", " + parameter_label(d.parameter)
                if d.sliding is not None:
                    where += ", " + SLIDING_LABELS[d.sliding]
                print(f"twb_plot: note: no distress load at {where}: {d.method}", file=sys.stderr)
    for k, (name, column, rows) in enumerate(data.fold_curves):
        stem = "fold_curve" if len(data.fold_curves) == 1 else f"fold_curve_{k + 1}_{name}"
        save(figure_fold_curve(data, name, column, rows), out_dir, stem, formats, written)
    if data.trajectories:
        save(figure_trajectory(data), out_dir, "transient_trajectory", formats, written)
    if data.sliding:
        save(figure_sliding(data), out_dir, "sliding_comparison", formats, written)
    return written


# ----------------------------------------------------------------------------- main

def parse_formats(text):
    formats = [f.strip().lower() for f in text.split(",") if f.strip()]
    bad = [f for f in formats if f not in FORMATS]
    if not formats or bad:
        raise argparse.ArgumentTypeError(
            f"expected a comma-separated list of {', '.join(FORMATS)}, got {text!r}")
    return list(dict.fromkeys(formats))


def parse_state(text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a row of states.csv, 1 or more, got {text!r}")
    return value


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="twb_plot.py",
        description="Figures of twb results directories in the layout of Jackson & Green "
                    "(2006), Figs. 6-15, plus the distress map, the transient trajectory and the "
                    "sliding comparison.")
    parser.add_argument("dirs", nargs="+", metavar="RESULTS_DIR",
                        help="a directory written by 'twb run --out'; several are merged")
    parser.add_argument("--out", metavar="FIGDIR",
                        help="where to write the figures (default: RESULTS_DIR/figures of the first)")
    parser.add_argument("--format", type=parse_formats, default=["png", "svg"], metavar="LIST",
                        help="comma-separated file formats among png, svg, pdf (default: png,svg)")
    parser.add_argument("--rpm", action="store_true",
                        help="speeds in revolutions per minute on the distress map and fold curve axes")
    parser.add_argument("--state", type=parse_state, metavar="N",
                        help="polar maps of the fields of state N (1-based row of states.csv); "
                             "default: the last state below the distress load, else the last")
    args = parser.parse_args(argv)

    # Text stays text in the SVG (editable, searchable); a fixed salt makes its ids
    # reproducible.
    plt.rcParams["svg.fonttype"] = "none"
    plt.rcParams["svg.hashsalt"] = "twb_plot"

    try:
        runs = [read_run(d) for d in args.dirs]
        maps = select_fields(runs, args.state)
    except InputError as e:
        print(f"twb_plot: error: {e}", file=sys.stderr)
        return 2
    out_dir = args.out or os.path.join(args.dirs[0], "figures")
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as e:
        print(f"twb_plot: error: {out_dir}: cannot create: {e.strerror}", file=sys.stderr)
        return 2
    data = merge(runs)
    data.rpm = args.rpm
    written = make_figures(data, out_dir, args.format)
    make_field_maps(maps, out_dir, args.format, written)
    if not written:
        print("twb_plot: error: nothing to plot", file=sys.stderr)
        return 1
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
