"""The probability of failure against load, from a reliability study: FORM's probability
at the operating load, the loads inverse FORM found for the probabilities asked for, and
the importance-sampling estimate with its 95 % interval; beside it, what each input
contributes at FORM's design point (its importance α²)."""

import matplotlib.pyplot as plt
import numpy as np


def figure_failure_probability(rows, design):
    """P_f (log scale) against load, and the design point's importances. None without a
    FORM or inverse FORM row to draw."""
    form = [r for r in rows if r["method"] in ("form", "inverse_form") and r["probability"] > 0.0
            and r["converged"] == 1]
    if not form:
        return None
    form.sort(key=lambda r: r["load_N"])
    fig, (ax, bars) = plt.subplots(1, 2, figsize=(11.0, 4.2), gridspec_kw={"width_ratios": [3, 2]})
    ax.semilogy([r["load_N"] for r in form], [r["probability"] for r in form], "o-", color="tab:blue",
                label="FORM (inverse FORM at the probabilities asked for)")
    at_load = [r for r in rows if r["method"] == "form"]
    if at_load:
        ax.semilogy([at_load[0]["load_N"]], [at_load[0]["probability"]], "s", color="tab:blue", markersize=8,
                    label=f"FORM at the operating load, β = {at_load[0]['beta']:.2f}")
    for r in rows:
        if r["method"] == "monte_carlo" and r["probability"] > 0.0:
            low = max(r["low"] or 0.0, r["probability"] * 1e-3)
            ax.errorbar([r["load_N"]], [r["probability"]],
                        yerr=[[r["probability"] - low], [(r["high"] or r["probability"]) - r["probability"]]],
                        fmt="D", color="tab:red", capsize=4,
                        label=f"importance sampling, 95 % interval ({int(r['samples'] or 0)} samples)")
    ax.set_xlabel("load (N)")
    ax.set_ylabel("probability of failure")
    speed = rows[0]["speed_rad_s"]
    ax.set_title(f"Probability of failure at {speed:.4g} rad/s")
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=8)
    # The inputs' importances at FORM's design point (at the operating load).
    point = [d for d in design if d["method"] == "form"]
    if point:
        point.sort(key=lambda d: d["importance"])
        y = np.arange(len(point))
        bars.barh(y, [d["importance"] for d in point],
                  color=["tab:red" if d["alpha"] > 0 else "tab:blue" for d in point])
        bars.set_yticks(y, [d["parameter"] for d in point], fontsize=8)
        bars.set_xlim(0.0, 1.0)
        bars.set_xlabel("importance α² at the design point\n(red: failing above its median, blue: below)")
        bars.set_title("What makes it fail")
        bars.grid(axis="x", alpha=0.3)
    else:
        bars.axis("off")
    fig.tight_layout()
    return fig
