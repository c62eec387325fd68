#!/usr/bin/env python3
"""The path-dependence study's table and figure (scripts/path_dependence_study.sh): for
each duty cycle to the same operating point, where it ended (the last step of its
trajectory.csv) and what happened on the way (its cycle_events.csv), as DIR/summary.csv
and a Markdown table on stdout; and DIR/path_dependence.png, the hottest film temperature
and the load of every path against time.

    path_dependence_summary.py DIR

A state is on the hot branch where the asperities carry more than half the load (the cool
states of the paper's washer at 175 N carry under 1 % on them, the hot ones over 60 %).
Exit status 0; 1 where a path's results are missing or malformed.
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PATHS = (("speed_first", "speed first, then load"), ("load_first", "load first (past W_d at 400 rad/s), then speed"),
         ("brief_overload", "2 s at 205 N, past W_d"), ("long_overload", "30 s at 205 N, past W_d"))


def read_rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def summarize(directory):
    rows = []
    for name, words in PATHS:
        run = os.path.join(directory, name)
        trajectory = read_rows(os.path.join(run, "trajectory.csv"))
        events = read_rows(os.path.join(run, "cycle_events.csv"))
        if not trajectory:
            raise ValueError(f"{run}/trajectory.csv has no step")
        end = trajectory[-1]
        runaways = [float(e["t_s"]) for e in events if e["event"] == "runaway"]
        settled = [float(e["t_s"]) for e in events if e["event"] == "settled"]
        crossings = [f"{e['criterion']} at {float(e['t_s']):.1f} s" for e in events if e["event"] == "crossing"]
        rows.append({
            "path": name, "how": words, "t_end_s": float(end["t_s"]), "load_N": float(end["load_N"]),
            "speed_rad_s": float(end["speed_rad_s"]), "T_mean_C": float(end["T_mean_C"]),
            "T_max_C": float(end["T_max_C"]), "hmin_over_sigma": float(end["hmin_over_sigma"]),
            "contact_share": float(end["contact_share"]), "f_eff": float(end["f_eff"]),
            "branch": "hot" if float(end["contact_share"]) > 0.5 else "cool",
            "runaway_s": ";".join(f"{t:.2f}" for t in runaways), "settled_s": ";".join(f"{t:.2f}" for t in settled),
            "crossings": ";".join(crossings),
            "trajectory": trajectory})
    return rows


def write_summary(directory, rows):
    columns = ["path", "how", "t_end_s", "load_N", "speed_rad_s", "T_mean_C", "T_max_C", "hmin_over_sigma",
               "contact_share", "f_eff", "branch", "runaway_s", "settled_s", "crossings"]
    with open(os.path.join(directory, "summary.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    print("| path | ends at | T_mean (°C) | T_max (°C) | h_min/σ | f_eff | branch | runaway (s) | settled (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['how']} | {r['load_N']:.0f} N, {r['speed_rad_s']:.0f} rad/s | {r['T_mean_C']:.1f} | "
              f"{r['T_max_C']:.1f} | {r['hmin_over_sigma']:.2f} | {r['f_eff']:.3f} | {r['branch']} | "
              f"{r['runaway_s'] or '—'} | {r['settled_s'] or '—'} |")


def figure(directory, rows):
    fig, (ax_load, ax_temp) = plt.subplots(2, 1, sharex=True, figsize=(9.0, 7.0),
                                           gridspec_kw={"height_ratios": [1, 1.6]})
    ax_speed = ax_load.twinx()
    for r in rows:
        t = [float(s["t_s"]) for s in r["trajectory"]]
        line, = ax_temp.plot(t, [float(s["T_max_C"]) for s in r["trajectory"]], linewidth=1.4,
                             label=f"{r['how']}: ends {r['branch']}")
        ax_load.plot(t, [float(s["load_N"]) for s in r["trajectory"]], linewidth=1.2, color=line.get_color())
        ax_speed.plot(t, [float(s["speed_rad_s"]) for s in r["trajectory"]], linewidth=1.0, linestyle=":",
                      color=line.get_color())
    ax_load.set_ylabel("load (N), solid")
    ax_speed.set_ylabel("speed (rad/s), dotted")
    ax_temp.set_ylabel("hottest film temperature (°C)")
    ax_temp.set_xlabel("time t (s)")
    for ax in (ax_load, ax_temp):
        ax.grid(True, alpha=0.3)
    ax_temp.legend(fontsize="small")
    fig.suptitle("Four ways to 175 N at 545 rad/s (the paper's washer; W_d = 188 N there)", fontsize="medium")
    fig.savefig(os.path.join(directory, "path_dependence.png"), dpi=120, bbox_inches="tight")
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[0], file=sys.stderr)
        print("usage: path_dependence_summary.py DIR", file=sys.stderr)
        return 2
    try:
        rows = summarize(argv[1])
    except (OSError, ValueError, KeyError) as e:
        print(f"path_dependence_summary.py: error: {e}", file=sys.stderr)
        return 1
    write_summary(argv[1], rows)
    figure(argv[1], rows)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
