"""A duty cycle (study type duty_cycle): the inputs the schedule moved above, the
bearing's answer below, and what happened along the way marked on both: each failure
criterion crossed (and recovered from), the thermo-viscous runaway, and the cycle's worst
moment with the failure load there."""

import math

import matplotlib.pyplot as plt

from .style import HMIN_LABEL

# How each event is marked: (colour, line style, label).
EVENT_MARKS = {
    "crossing": ("tab:red", ":", "a limit crossed"),
    "recovery": ("tab:green", ":", "back within a limit"),
    "runaway": ("black", "-", "thermo-viscous runaway"),
    "settled": ("gray", "--", "the runaway over"),
    "rest": ("tab:blue", "-.", "unloaded at rest (held)"),
    "resume": ("tab:cyan", "-.", "balanced again"),
}


def _mark_events(axes, events):
    labelled = set()
    for e in events:
        mark = EVENT_MARKS.get(e["event"])
        if mark is None:
            continue
        color, style, label = mark
        for ax in axes:
            ax.axvline(e["t_s"], color=color, linestyle=style, linewidth=1.1,
                       label=None if label in labelled or ax is not axes[-1] else label)
        labelled.add(label)


def figure_cycle(cycle, events):
    """None where the trajectory has no step."""
    t = cycle["t_s"]
    if t.size == 0:
        return None
    fig, (ax_in, ax_temp, ax_margin) = plt.subplots(3, 1, sharex=True, figsize=(9.6, 8.6),
                                                    gridspec_kw={"height_ratios": [1, 1.3, 1]})
    ax_in.plot(t, cycle["load_N"], color="tab:blue", linewidth=1.4, label="load")
    ax_in.set_ylabel("load (N)", color="tab:blue")
    ax_speed = ax_in.twinx()
    ax_speed.plot(t, cycle["speed_rad_s"], color="tab:orange", linewidth=1.4, label="speed")
    ax_speed.set_ylabel("speed (rad/s)", color="tab:orange")

    ax_temp.plot(t, cycle["T_mean_C"], color="tab:blue", linewidth=1.4, label="mean washer")
    ax_temp.plot(t, cycle["T_max_C"], color="tab:red", linestyle="--", linewidth=1.4, label="max film")
    ax_temp.plot(t, cycle["ambient_C"], color="tab:gray", linestyle="-.", linewidth=1.0, label="ambient")
    ax_temp.set_ylabel("temperature (°C)")
    ax_film = ax_temp.twinx()
    ax_film.plot(t, cycle["hmin_over_sigma"], color="tab:purple", linewidth=1.0, alpha=0.7)
    ax_film.set_ylabel(HMIN_LABEL, color="tab:purple")

    ax_margin.plot(t, cycle["least_margin"], color="tab:green", linewidth=1.4, label="least margin")
    ax_margin.axhline(0.0, color="black", linewidth=0.8)
    ax_margin.set_ylabel("least margin\n(fraction of its allowance)")
    ax_margin.set_xlabel("time t (s)")
    worst = next((e for e in events if e["event"] == "worst"), None)
    if worst is not None and worst["margin"] is not None:
        text = f"worst: {worst['margin']:.2f} of {worst['criterion'].replace('_', ' ')}"
        if worst["failure_load_N"] is not None and not math.isnan(worst["failure_load_N"]):
            text += f"\nfails there at {worst['failure_load_N']:.4g} N by {worst['failure_criterion'].replace('_', ' ')}"
        ax_margin.plot([worst["t_s"]], [worst["margin"]], "v", color="black", markersize=8)
        right_half = worst["t_s"] > 0.5 * (t[0] + t[-1])
        ax_margin.annotate(text, (worst["t_s"], worst["margin"]), textcoords="offset points",
                           xytext=(-8 if right_half else 8, 8), ha="right" if right_half else "left",
                           fontsize="small")

    axes = [ax_in, ax_temp, ax_margin]
    _mark_events(axes, events)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    ax_temp.legend(fontsize="small", loc="upper left")
    if any(e["event"] in EVENT_MARKS for e in events):
        ax_margin.legend(fontsize="small", loc="lower left")
    fig.suptitle("Duty cycle: inputs, temperatures and the margin to failure", fontsize="medium")
    return fig
