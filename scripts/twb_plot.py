#!/usr/bin/python3
"""Figures of twb results in the layout of Jackson & Green (2006), Figs. 6-15.

    twb_plot.py RESULTS_DIR [RESULTS_DIR ...] [--out FIGDIR] [--format png,svg] [--state N]

The command line of the twb.plot module (python/twb/plot/, `--help` for the options);
docs/figures.md describes each figure.
"""

import os
import sys

# The repository's python/ directory, where twb.plot lives (a symlink to this script
# still finds it).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.realpath(__file__))), "python"))
from twb.plot.cli import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
