#!/usr/bin/env python3
"""The wear-in study's Stribeck figure (scripts/wear_in_study.sh): f_eff against Z*N/P at
545 rad/s for the paper's washer new, worn 2000 h at 150 N with and without its sliding
faces running in, and run in everywhere to three roughnesses, with the optima the paper
gives for Figs. 14 and 16; the cool branch of each up to its distress load (the jump to
the hot branch is not drawn).

    wear_in_stribeck.py DIR [FIGURE]

Reads DIR/stribeck_<case>/states.csv; writes FIGURE (default DIR/wear_in_stribeck.png).
Exit status 0; 1 where a case's states are missing or malformed.
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CASES = (("new", "new (Rq 0.515 µm)", "black", "-"),
         ("worn", "worn 2000 h at 150 N", "tab:blue", "-"),
         ("worn_run_in", "worn 2000 h at 150 N, running in to 0.2 µm", "tab:orange", "--"),
         ("run_in_0.3", "run in everywhere to Rq 0.3 µm", "tab:green", "-"),
         ("run_in_0.2", "run in everywhere to Rq 0.2 µm", "tab:red", "-"),
         ("run_in_0.1", "run in everywhere to Rq 0.1 µm", "tab:purple", "-"))
# The optima the paper states in its text (Figs. 14 and 16).
PAPER_OPTIMA = ((2.0e-6, "paper, numerical: optimum near 2.0e-6", "--"),
                (1.0e-6, "paper, experiments: optimum near 1.0e-6", ":"))


def cool_branch(path):
    """(Z*N/P, f_eff) of the states on the cool branch, in order of load."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = [r for r in csv.DictReader(f) if r["branch"] == "cool"]
    if not rows:
        raise ValueError(f"{path}: no state on the cool branch")
    rows.sort(key=lambda r: float(r["load_N"]))
    return [float(r["stribeck"]) for r in rows], [float(r["f_eff"]) for r in rows]


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 1
    directory = argv[1]
    figure = argv[2] if len(argv) == 3 else os.path.join(directory, "wear_in_stribeck.png")
    fig, ax = plt.subplots(figsize=(7.5, 5.0))
    try:
        for case, label, color, style in CASES:
            x, y = cool_branch(os.path.join(directory, f"stribeck_{case}", "states.csv"))
            ax.plot(x, y, color=color, linestyle=style, linewidth=1.4, label=label)
            least = min(range(len(y)), key=y.__getitem__)
            ax.plot(x[least], y[least], "o", color=color, markersize=4)
    except (OSError, KeyError, ValueError) as error:
        print(f"wear_in_stribeck.py: {error}", file=sys.stderr)
        return 1
    for x, label, style in PAPER_OPTIMA:
        ax.axvline(x, color="0.4", linestyle=style, linewidth=1.0, label=label)
    ax.set_xscale("log")
    ax.set_xlabel("Z·N/P (Pa·s·rev/s / Pa)")
    ax.set_ylabel("effective friction coefficient f_eff")
    ax.set_title("The paper's washer at 545 rad/s: the Stribeck curve new, worn and run in\n"
                 "(cool branch up to distress; dot: its least f_eff)", fontsize="medium")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize="small", loc="upper left")
    fig.tight_layout()
    fig.savefig(figure, dpi=130)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
