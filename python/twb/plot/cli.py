"""The command line, for scripts/twb_plot.py and `python3 -m twb.plot`:

    twb_plot.py RESULTS_DIR [RESULTS_DIR ...] [--out FIGDIR] [--format png,svg] [--state N]

Reads states.csv (required), distress.csv, trajectory.csv, sliding.csv, fold_curve.csv and
run.json from each directory, merges the directories (e.g. one load sweep per speed), and
writes one file per figure and format into FIGDIR (default: RESULTS_DIR/figures of the
first directory). A directory with fields/ (output.fields) also gets polar maps of one
state's fields: state N, or by default the last state below the distress load. Prints the
files written. Exit status 1 when there is nothing to plot, 2 when an input is missing or
malformed. docs/figures.md describes each figure.
"""

import argparse
import os
import sys

from .fields import make_field_maps, select_fields
from .figures import make_figures
from .runs import merge, read_run
from .tables import InputError

FORMATS = ("png", "svg", "pdf")


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
    """The exit status: 0 figures written, 1 nothing to plot, 2 a missing or malformed
    input (argparse exits 2 itself on bad usage)."""
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
    units = parser.add_mutually_exclusive_group()
    units.add_argument("--rpm", action="store_true",
                       help="speeds in revolutions per minute (default: as the scene gave them)")
    units.add_argument("--rad-s", action="store_true",
                       help="speeds in rad/s (default: as the scene gave them)")
    parser.add_argument("--state", type=parse_state, metavar="N",
                        help="polar maps of the fields of state N (1-based row of states.csv); "
                             "default: the last state below the distress load, else the last")
    args = parser.parse_args(argv)

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
    data = merge(runs, rpm=True if args.rpm else (False if args.rad_s else None))
    written = make_figures(data, out_dir, args.format)
    make_field_maps(maps, out_dir, args.format, written)
    if not written:
        print("twb_plot: error: nothing to plot", file=sys.stderr)
        return 1
    for path in written:
        print(path)
    return 0

