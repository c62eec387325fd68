"""Which film slides: both configurations of a sliding choice side by side, so that the
choice (the one with the lower friction torque) can be checked by eye, and the films'
areas against the paper's.
"""

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D

from .style import LINESTYLES, LOAD_LABEL, speed_key, speed_label
from .tables import SLIDING_LABELS


def figure_sliding(data):
    """Which film slides: friction torque and lift (the sliding film's fluid force) of
    both configurations against load, one colour per speed, the chosen configuration
    (lower torque) filled."""
    fig, (ax_t, ax_l) = plt.subplots(1, 2, figsize=(11.0, 4.8))
    films = [f for f in SLIDING_LABELS if any(r["sliding"] == f for r in data.sliding)]
    styles = {f: LINESTYLES[i] for i, f in enumerate(SLIDING_LABELS)}
    areas = {}
    for key in data.speed_style.keys:
        for film in films:
            rows = sorted((r for r in data.sliding
                           if r["sliding"] == film and speed_key(r["speed_rad_s"]) == key),
                          key=lambda r: r["load_N"])
            if not rows:
                continue
            areas[film] = rows[0]["film_area_m2"]
            color, marker = data.speed_style.colors[key], data.speed_style.markers[key]
            load = np.array([r["load_N"] for r in rows])
            chosen = np.array([r["chosen"] == 1 for r in rows])
            for ax, column in ((ax_t, "torque_Nm"), (ax_l, "fluid_force_N")):
                y = np.array([r[column] for r in rows])
                ax.plot(load, y, color=color, linestyle=styles[film], linewidth=1.2)
                ax.plot(load[chosen], y[chosen], linestyle="none", marker=marker, markersize=5,
                        color=color)
                ax.plot(load[~chosen], y[~chosen], linestyle="none", marker=marker, markersize=5,
                        markerfacecolor="none", markeredgecolor=color)
    for ax in (ax_t, ax_l):
        ax.grid(True, alpha=0.3)
        ax.set_xlabel(LOAD_LABEL)
    ax_t.set_ylabel(r"friction torque $T_{frict}$ (N·m)")
    ax_l.set_ylabel(r"lift: fluid force of the sliding film $F_{fluid}$ (N)")
    handles = [Line2D([], [], color=data.speed_style.colors[k], marker=data.speed_style.markers[k],
                      linestyle="none") for k in data.speed_style.keys
               if any(speed_key(r["speed_rad_s"]) == k for r in data.sliding)]
    labels = [speed_label(k) for k in data.speed_style.keys
              if any(speed_key(r["speed_rad_s"]) == k for r in data.sliding)]
    for film in films:
        handles.append(Line2D([], [], color="black", linestyle=styles[film]))
        labels.append(f"{SLIDING_LABELS[film]}, {areas[film] * 1e6:.1f} mm²")
    handles += [Line2D([], [], color="black", marker="o", linestyle="none"),
                Line2D([], [], color="black", marker="o", linestyle="none", markerfacecolor="none")]
    labels += ["chosen: the lower torque", "not chosen"]
    ax_t.legend(handles, labels, fontsize="small", framealpha=0.85)
    title = "Which film slides: friction torque and lift of both configurations"
    if len(areas) == 2:
        a1, a2 = areas["carrier_washer"], areas["washer_gear"]
        title += (f"\n(film 2's area is {100 * (a1 - a2) / a1:.1f} % below film 1's, film 1's "
                  f"{100 * (a1 - a2) / a2:.1f} % above film 2's; cf. the paper's 31 %)")
    fig.suptitle(title, fontsize="medium")
    return fig
