"""Which figures a set of results gets: each family is drawn when its results are there,
and what cannot be drawn is said on stderr, so a missing figure is never a silent one.
"""

import sys

from .calibration import figure_calibration
from .cycle import figure_cycle
from .life import figure_life
from .distress import figure_distress_grid, figure_distress_map, figure_fold_curve, grid_rows
from .reliability import figure_failure_probability
from .sensitivity import figure_tornado
from .sliding import figure_sliding
from .states import (LOAD_FIGURES, figure_contact_vs_hmin, figure_stribeck, figure_stribeck_by_friction,
                     figure_vs_load)
from .style import parameter_label, save, show_speeds_in_rpm, speed_key, speed_label
from .tables import SLIDING_LABELS
from .transient import figure_trajectory


def save_or_say(fig, out_dir, stem, formats, written, why_none):
    """A figure that may have nothing to draw: saved, or a note saying why not."""
    if fig is None:
        print(f"twb_plot: note: {why_none}", file=sys.stderr)
    else:
        save(fig, out_dir, stem, formats, written)


def make_figures(data, out_dir, formats):
    """Every figure the merged results allow, as files FIGDIR/<stem>.<format>; returns
    their paths in the order written (the field maps are make_field_maps's)."""
    written = []
    show_speeds_in_rpm(getattr(data, "rpm", False))
    if data.states["load_N"].size:
        for stem, column, ylabel, title, number, logy in LOAD_FIGURES:
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
        save_or_say(figure_distress_map(data), out_dir, "distress_map", formats, written,
                    "distress.csv has neither a distress load nor a fold; no distress map")
        # A grid (two or more axes) also gets its small multiples, one panel per speed.
        if grid_rows(data):
            save_or_say(figure_distress_grid(data), out_dir, "distress_grid", formats, written,
                        "the grid's distress.csv has no failure load and no search to draw; no distress grid")
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
    # The studies' own figures, one per run: (runs, stem, drawing, what a run without
    # anything to draw lacks).
    studies = (
        (data.sensitivities, "sensitivity", figure_tornado, "sensitivity.csv has no elasticities to draw"),
        (data.reliabilities, "reliability", figure_failure_probability,
         "reliability.csv has no probability to draw"),
        (data.calibrations, "calibration", figure_calibration,
         "calibration_points.csv has no measured value to draw"),
        (data.cycles, "duty_cycle", figure_cycle, "trajectory.csv has no step of the cycle to draw"),
        (data.lives, "life", figure_life, "life.csv has no row to draw"),
    )
    for runs, base, draw, nothing in studies:
        for k, (name, *tables) in enumerate(runs):
            fig = draw(*tables)
            stem = base if len(runs) == 1 else f"{base}_{k + 1}_{name}"
            if fig is None:
                print(f"twb_plot: note: {name}: {nothing}", file=sys.stderr)
            else:
                save(fig, out_dir, stem, formats, written)
    return written
