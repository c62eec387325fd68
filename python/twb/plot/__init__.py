"""Figures of twb results in the layout of Jackson & Green (2006), Figs. 6-15, and of the
solver's own: the distress map (and a grid's small multiples), the fold curve, the
transient, the sliding choice, the studies' sensitivity, reliability, calibration, duty
cycle and life, and
polar maps of a state's fields (docs/figures.md).

The plotting part of the twb Python module. It reads results directories only, with
numpy and matplotlib, and never the compiled extension, so that results can be drawn
wherever they are copied to.

    import twb.plot as tp
    runs = [tp.read_run(d) for d in ("results/a", "results/b")]
    written = tp.make_figures(tp.merge(runs), "figures", ["png", "svg"])

scripts/twb_plot.py and `python3 -m twb.plot` are its command line (cli.main).
"""

import matplotlib

# Figures only ever go to files, and the machines that make them usually have no display.
# Chosen before any submodule imports pyplot.
matplotlib.use("Agg")

from .cli import main  # noqa: E402
from .fields import default_state, make_field_maps, select_fields  # noqa: E402
from .figures import make_figures  # noqa: E402
from .runs import Data, Run, merge, read_run  # noqa: E402
from .tables import (DistressRow, InputError, fields_path, read_calibration,  # noqa: E402
                     read_calibration_correlation, read_calibration_points, read_cycle, read_cycle_events,
                     read_design_point, read_distress,
                     read_fields, read_fold_curve, read_life, read_reliability, read_sensitivity, read_sliding,
                     read_states, read_trajectory, read_worn_profile)

__all__ = [
    "Data", "DistressRow", "InputError", "Run", "default_state", "fields_path", "main",
    "make_field_maps", "make_figures", "merge", "read_calibration", "read_calibration_correlation",
    "read_calibration_points", "read_cycle", "read_cycle_events", "read_design_point", "read_distress", "read_fields",
    "read_fold_curve", "read_life", "read_reliability", "read_run", "read_sensitivity", "read_sliding", "read_states", "read_trajectory", "read_worn_profile", "select_fields",
]
