"""`python3 -m twb.plot RESULTS_DIR ...`: the same command line as scripts/twb_plot.py."""

import sys

from .cli import main

sys.exit(main())
