#!/usr/bin/python3
"""The table and figure of the grooved-washer study (scripts/grooved_washer_study.sh,
docs/validation.md "Grooved washers"): for every variant and speed the failure load and
its criterion, the loads of the oil's two temperature limits, and at a reference load
the washer's mean temperature, the hottest film node, the heat the oil carries and the
oil supplied.

    /usr/bin/python3 scripts/grooved_washer_summary.py DIR [--load N]

DIR holds one results directory per variant (flat, flat_convection, grooved, fed,
fed_convection; those missing are skipped). Writes DIR/summary.csv and
DIR/grooved_washers.png. Where DIR holds the maps over the grooves' count, width,
depth and a dam's radius (groove_count, groove_width, groove_depth, groove_dam),
DIR/groove_parameters.csv and DIR/groove_parameters.png: the failure load and every
criterion's load against each.
Exit status: 0 done, 2 bad usage or no variant found.
"""
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

VARIANTS = [
    ("flat", "flat"),
    ("flat_convection", "flat, convection"),
    ("grooved", "6 grooves, unfed"),
    ("fed", "6 grooves fed at 0.5 bar (JFO)"),
    ("fed_convection", "fed, convection"),
]


def at_load(states, speed, load, column):
    """The column at `load` on the cool branch of `speed`, linear between the states
    either side; empty where the branch does not reach it or twb wrote no such column."""
    if column not in states:
        return math.nan
    rows = states[(np.isclose(states["speed_rad_s"], speed)) & (states["branch"] == "cool")]
    rows = rows.sort_values("load_N")
    if rows.empty or not rows["load_N"].min() <= load <= rows["load_N"].max():
        return math.nan
    return float(np.interp(load, rows["load_N"], rows[column]))


def summarize(root, load):
    out = []
    for name, label in VARIANTS:
        d = root / name
        if not (d / "distress.csv").exists():
            continue
        distress = pd.read_csv(d / "distress.csv")
        states = pd.read_csv(d / "states.csv")
        for _, row in distress.iterrows():
            speed = row["speed_rad_s"]
            out.append({
                "variant": name,
                "label": label,
                "speed_rad_s": speed,
                "W_fail_N": row["W_fail_N"],
                "criterion": row["criterion"],
                "W_d_N": row["W_d_N"],
                "W_oil_temperature_N": row["W_oil_temperature_N"],
                "W_oil_peak_temperature_N": row["W_oil_peak_temperature_N"],
                "W_scuffing_N": row["W_scuffing_N"] if "W_scuffing_N" in row else math.nan,
                f"T_mean_C_at_{load:g}N": at_load(states, speed, load, "T_mean_C"),
                f"T_max_C_at_{load:g}N": at_load(states, speed, load, "T_max_C"),
                f"heat_carried_W_at_{load:g}N": at_load(states, speed, load, "heat_carried_W"),
                f"Q_supply_l_min_at_{load:g}N": at_load(states, speed, load, "Q_supply_l_min"),
            })
    return pd.DataFrame(out)


def figure(table, load, path):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, label in VARIANTS:
        rows = table[table["variant"] == name].sort_values("speed_rad_s")
        if rows.empty:
            continue
        line = left.plot(rows["speed_rad_s"], rows["W_fail_N"], "o-", label=label)[0]
        # The failure's criterion: a square where the oil's peak at its flash point sets it.
        flash = rows[rows["criterion"] == "oil_peak_temperature"]
        left.plot(flash["speed_rad_s"], flash["W_fail_N"], "s", color=line.get_color(), markersize=9, fillstyle="none")
        right.plot(rows["speed_rad_s"], rows[f"T_mean_C_at_{load:g}N"], "o-", color=line.get_color(), label=label)
    left.set_xlabel("speed (rad/s)")
    left.set_ylabel("failure load W_fail (N)")
    left.set_title("where it fails (open square: by the oil's peak temperature)")
    left.set_yscale("log")
    right.set_xlabel("speed (rad/s)")
    right.set_ylabel(f"washer mean temperature at {load:g} N (°C)")
    right.set_title("how hot the washer runs")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


# The maps over one property of the fed grooved washer's grooves: its results directory,
# its column in distress.csv, the axis label and the factor from the column's unit.
GROOVE_PARAMETERS = [
    ("groove_count", "groove_count", "number of grooves", 1.0),
    ("groove_width", "groove_width_rad", "groove width (deg, whole cells)", 180.0 / math.pi),
    ("groove_depth", "groove_depth_m", "groove depth (µm)", 1e6),
    ("groove_dam", "geometry.washer.grooves.closed_at_m", "dam radius (mm; grooves open at the bore)", 1e3),
]
# Every criterion's own load in distress.csv, and how the figure draws it.
CRITERIA = [
    ("W_d_N", "thermo-viscous distress (W_d; none: no fold up to load_end)", "k^-"),
    ("W_oil_temperature_N", "oil's maximum temperature", "C1s--"),
    ("W_oil_peak_temperature_N", "oil's peak temperature at its flash point", "C3v:"),
    ("W_scuffing_N", "scuffing (the asperities' contact temperature)", "C2D-."),
]


def groove_parameters(root):
    out = []
    for name, column, _, factor in GROOVE_PARAMETERS:
        path = root / name / "distress.csv"
        if not path.exists():
            continue
        distress = pd.read_csv(path)
        for _, row in distress.iterrows():
            entry = {"parameter": name, "value": row[column], "value_shown": row[column] * factor,
                     "speed_rad_s": row["speed_rad_s"], "W_fail_N": row["W_fail_N"], "criterion": row["criterion"]}
            for key, _, _ in CRITERIA:
                entry[key] = row[key] if key in row else math.nan
            out.append(entry)
    return pd.DataFrame(out)


def groove_figure(table, path):
    shown = [p for p in GROOVE_PARAMETERS if (table["parameter"] == p[0]).any()]
    fig, axes = plt.subplots(1, len(shown), figsize=(4.2 * len(shown), 4.0), squeeze=False, sharey=True)
    for ax, (name, _, label, _) in zip(axes[0], shown):
        rows = table[table["parameter"] == name].sort_values("value")
        ax.plot(rows["value_shown"], rows["W_fail_N"], "o", color="C0", markersize=8, label="W_fail", zorder=3)
        for key, criterion, style in CRITERIA:
            ax.plot(rows["value_shown"], rows[key], style, label=criterion)
        ax.set_xlabel(label)
        ax.set_yscale("log")
    axes[0][0].set_ylabel("load (N)")
    axes[0][0].legend(fontsize=7)
    fig.suptitle("the fed, oil-cooled grooved washer at 545 rad/s: where it fails against its grooves")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv):
    args = [a for a in argv[1:]]
    load = 100.0
    if "--load" in args:
        k = args.index("--load")
        if k + 1 >= len(args):
            print(__doc__.strip(), file=sys.stderr)
            return 2
        load = float(args[k + 1])
        del args[k:k + 2]
    if len(args) != 1:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    root = pathlib.Path(args[0])
    table = summarize(root, load)
    grooves = groove_parameters(root)
    if table.empty and grooves.empty:
        print(f"grooved_washer_summary.py: no variant's results in {root}", file=sys.stderr)
        return 2
    if not table.empty:
        table.to_csv(root / "summary.csv", index=False)
        figure(table, load, root / "grooved_washers.png")
        with pd.option_context("display.width", 200, "display.max_columns", 20):
            print(table.drop(columns=["label"]).to_string(index=False))
    if not grooves.empty:
        grooves.to_csv(root / "groove_parameters.csv", index=False)
        groove_figure(grooves, root / "groove_parameters.png")
        with pd.option_context("display.width", 200, "display.max_columns", 20):
            print(grooves.to_string(index=False))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
