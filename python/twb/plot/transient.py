"""The thermal transient after a load step, in pseudo-time: the runaway (or the settling)
that each distress load rests on, shown rather than only reported.
"""

import matplotlib.pyplot as plt

from .style import CONTACT_LABEL, FEFF_LABEL, HMIN_LABEL, Style


def figure_trajectory(data):
    fig, axes = plt.subplots(2, 2, sharex=True, figsize=(9.6, 7.0))
    (ax_t, ax_h), (ax_c, ax_f) = axes
    several = len(data.trajectories) > 1
    style = Style(range(len(data.trajectories)))
    for i, (label, tr) in enumerate(data.trajectories):
        color = style.colors[i] if several else None
        t = tr["t_s"]
        prefix = f"{label}: " if several else ""
        ax_t.plot(t, tr["T_mean_C"], color=color or "tab:blue", linewidth=1.4,
                  label=prefix + "mean washer")
        ax_t.plot(t, tr["T_max_C"], color=color or "tab:red", linestyle="--", linewidth=1.4,
                  label=prefix + "max film")
        ax_h.plot(t, tr["hmin_over_sigma"], color=color, linewidth=1.4, label=label)
        ax_c.plot(t, tr["contact_share"], color=color, linewidth=1.4, label=label)
        ax_f.plot(t, tr["f_eff"], color=color, linewidth=1.4, label=label)
    ax_t.set_ylabel("temperature (°C)")
    ax_h.set_ylabel(HMIN_LABEL)
    ax_c.set_ylabel(CONTACT_LABEL)
    ax_f.set_ylabel(FEFF_LABEL)
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("pseudo-time t (s)")
    ax_t.legend(fontsize="small")
    if several:
        ax_h.legend(fontsize="small")
    title = "Thermal transient after a load step"
    if not several:
        title += f" ({data.trajectories[0][0]})"
    fig.suptitle(title, fontsize="medium")
    return fig
