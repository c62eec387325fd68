"""A results directory read whole, and several merged into one set of curves.

The figures compare runs made apart (one directory per speed, per friction law or per
load), so every figure draws from the merged Data, never from one directory's files.
"""

import json
import os
from dataclasses import dataclass, field

import numpy as np

from .style import Style, axis_label, parameter_label, show_speeds_in_rpm, speed_key, speed_label
from .tables import (SLIDING_LABELS, STATE_COLUMNS, InputError, read_calibration, read_calibration_correlation,
                     read_calibration_points, read_cycle, read_cycle_events, read_design_point, read_distress,
                     read_fold_curve, read_life, read_worn_profile,
                     read_reliability, read_sensitivity, read_sliding, read_states, read_trajectory,
                     run_axes, STATE_ERROR_COLUMNS)


def run_record(path):
    """run.json as a dict, or None where it cannot be read: it is only used for labels, so
    an unreadable one is ignored, not an error."""
    try:
        with open(path, encoding="utf-8") as f:
            record = json.load(f)
    except (OSError, ValueError):
        return None
    return record if isinstance(record, dict) else None


def friction_setting(record):
    """The boundary friction law of run.json's resolved scene, as a legend label."""
    try:
        friction = record["scene"]["friction"]
        law = friction["law"]
    except (KeyError, TypeError):
        return None
    if law == "constant":
        return f"dry friction coefficient {friction.get('coefficient', '?')}"
    if law == "empirical":
        return "empirical friction law (eq. 18)"
    return str(law)


def state_friction(parameter, law):
    """A state's friction setting as a label: a state of a run with a friction coefficient
    axis (alone or in a grid) has its own coefficient; otherwise the run's friction law
    (run.json) labels it."""
    axis = next((a for a in run_axes(parameter) if a[0] == "friction_coefficient"), None)
    return law if axis is None else axis_label(*axis)


@dataclass
class Run:
    directory: str
    name: str
    states: dict
    tags: list = field(default_factory=list)  # per state: (run tag, sliding) (tables.run_tag)
    distress: list = field(default_factory=list)
    trajectory: object = None
    trajectory_tags: list = field(default_factory=list)
    sliding: list = field(default_factory=list)
    friction: object = None
    speed_unit: object = None  # run.json's: "rpm" where the scene gave its speeds so
    has_fields: bool = False
    fold_curve: object = None  # (parameter column, rows) of fold_curve.csv
    sensitivity: list = field(default_factory=list)  # rows of sensitivity.csv
    reliability: list = field(default_factory=list)  # rows of reliability.csv
    design_point: list = field(default_factory=list)  # rows of design_point.csv
    calibration: list = field(default_factory=list)  # rows of calibration.csv
    calibration_correlation: list = field(default_factory=list)  # rows of calibration_correlation.csv
    calibration_points: list = field(default_factory=list)  # rows of calibration_points.csv
    cycle: object = None  # a duty cycle's trajectory.csv columns
    cycle_events: list = field(default_factory=list)  # rows of cycle_events.csv
    life: list = field(default_factory=list)  # rows of life.csv
    worn_profile: object = None  # worn_profile.csv's columns


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
    events_path = os.path.join(directory, "cycle_events.csv")
    if os.path.isfile(events_path):
        # A duty cycle: its trajectory in real time, with what happened along it.
        run.cycle_events = read_cycle_events(events_path)
        if os.path.isfile(trajectory_path):
            run.cycle = read_cycle(trajectory_path)
    elif os.path.isfile(trajectory_path):
        run.trajectory, run.trajectory_tags = read_trajectory(trajectory_path)
    life_path = os.path.join(directory, "life.csv")
    if os.path.isfile(life_path):
        run.life = read_life(life_path)
        profile_path = os.path.join(directory, "worn_profile.csv")
        if os.path.isfile(profile_path):
            run.worn_profile = read_worn_profile(profile_path)
    sliding_path = os.path.join(directory, "sliding.csv")
    if os.path.isfile(sliding_path):
        run.sliding = read_sliding(sliding_path)
    fold_curve_path = os.path.join(directory, "fold_curve.csv")
    if os.path.isfile(fold_curve_path):
        run.fold_curve = read_fold_curve(fold_curve_path)
    sensitivity_path = os.path.join(directory, "sensitivity.csv")
    if os.path.isfile(sensitivity_path):
        run.sensitivity = read_sensitivity(sensitivity_path)
    reliability_path = os.path.join(directory, "reliability.csv")
    if os.path.isfile(reliability_path):
        run.reliability = read_reliability(reliability_path)
        design_path = os.path.join(directory, "design_point.csv")
        if os.path.isfile(design_path):
            run.design_point = read_design_point(design_path)
    _read_calibration(run, directory)
    record = run_record(os.path.join(directory, "run.json"))
    run.friction = friction_setting(record)
    run.speed_unit = speed_unit(record)
    run.has_fields = os.path.isdir(os.path.join(directory, "fields"))
    return run


def _read_calibration(run, directory):
    """A calibration study's three tables, each where present (the correlations are
    header-only when the fit has no covariance)."""
    for attribute, name, reader in (("calibration", "calibration.csv", read_calibration),
                                    ("calibration_correlation", "calibration_correlation.csv",
                                     read_calibration_correlation),
                                    ("calibration_points", "calibration_points.csv", read_calibration_points)):
        path = os.path.join(directory, name)
        if os.path.isfile(path):
            setattr(run, attribute, reader(path))


@dataclass
class Data:
    """All directories merged: one array per states.csv column, plus the rest."""
    states: dict
    friction: list          # per state: its friction setting as a label (or None)
    parameters: list        # per state: its run's tag: (column, value), a grid's tuple of them, or None
    distress: list
    trajectories: list      # (label, columns)
    sliding: list           # rows of sliding.csv
    speed_style: Style
    fold_curves: list = field(default_factory=list)  # (run name, parameter column, rows)
    sensitivities: list = field(default_factory=list)  # (run name, rows of sensitivity.csv)
    # (run name, rows of reliability.csv, rows of design_point.csv)
    reliabilities: list = field(default_factory=list)
    # (run name, rows of calibration.csv, rows of calibration_points.csv)
    calibrations: list = field(default_factory=list)
    cycles: list = field(default_factory=list)  # (run name, trajectory columns, rows of cycle_events.csv)
    # (run name, rows of life.csv, worn_profile.csv's columns or None, the operating load or None)
    lives: list = field(default_factory=list)
    rpm: bool = False       # speeds drawn in rpm


def _split_trajectory(columns, tags):
    """A trajectory.csv of several runs (speeds, axes' values, sliding films) as one
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


def speed_unit(record):
    """The unit run.json says the scene gave its speeds in ("rpm" or "rad/s"); None where
    it does not say (an older run)."""
    unit = record.get("speed_unit") if record is not None else None
    return unit if unit in ("rpm", "rad/s") else None


def merge(runs, rpm=None):
    """rpm: speeds drawn in rpm (True), rad/s (False), or as the scenes gave them (None:
    rpm where every run's scene gave rpm)."""
    if rpm is None:
        rpm = bool(runs) and all(r.speed_unit == "rpm" for r in runs)
    # Before the labels below are made.
    show_speeds_in_rpm(rpm)
    states = {c: np.concatenate([r.states[c] for r in runs]) for c in STATE_COLUMNS}
    # A state's error bar where its run has one, NaN elsewhere.
    for c in STATE_ERROR_COLUMNS:
        if any(c in r.states for r in runs):
            states[c] = np.concatenate([r.states.get(c, np.full(len(r.states["load_N"]), np.nan)) for r in runs])
    parameters = [tag[0] for r in runs for tag in r.tags]
    friction = [state_friction(tag[0], r.friction) for r in runs for tag in r.tags]
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
    data.sensitivities = [(r.name, r.sensitivity) for r in runs if r.sensitivity]
    data.reliabilities = [(r.name, r.reliability, r.design_point) for r in runs if r.reliability]
    data.calibrations = [(r.name, r.calibration, r.calibration_points) for r in runs
                         if r.calibration or r.calibration_points]
    data.cycles = [(r.name, r.cycle, r.cycle_events) for r in runs if r.cycle is not None]
    # (a life's states are the bearing at its operating load)
    data.lives = [(r.name, r.life, r.worn_profile, r.states["load_N"][0] if r.states["load_N"].size else None)
                  for r in runs if r.life]
    data.rpm = rpm
    return data
