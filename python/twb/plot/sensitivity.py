"""What the answer hangs on: a tornado of the elasticities of one quantity of a
sensitivity study (W_fail where the study located a failure load, else W_d, else the
friction torque), the inputs ranked by how much a relative change of each moves it."""

import matplotlib.pyplot as plt
import numpy as np

# The quantity a tornado shows, by preference: the failure load, then the friction torque.
HEADLINES = ("W_fail_N", "W_d_N", "torque_Nm")
LABELS = {"W_fail_N": "W_fail", "W_d_N": "W_d", "torque_Nm": "friction torque"}


def headline(rows):
    """The quantity to draw: the first of HEADLINES with an elasticity, None without."""
    for q in HEADLINES:
        if any(r["quantity"] == q and r["elasticity"] is not None for r in rows):
            return q
    return None


def figure_tornado(rows, shown=15):
    """The `shown` largest elasticities of the headline quantity, largest on top, their
    signs coloured: how many per cent it moves per per cent of each input."""
    q = headline(rows)
    if q is None:
        return None
    ranked = sorted((r for r in rows if r["quantity"] == q and r["elasticity"] is not None),
                    key=lambda r: abs(r["elasticity"]), reverse=True)[:shown]
    ranked.reverse()
    e = np.array([r["elasticity"] for r in ranked])
    fig, ax = plt.subplots(figsize=(8.0, 0.35 * len(ranked) + 1.6))
    ax.barh(np.arange(len(ranked)), e, color=np.where(e >= 0, "tab:blue", "tab:red"))
    ax.set_yticks(np.arange(len(ranked)), [r["parameter"] for r in ranked], fontsize=8)
    ax.axvline(0.0, color="black", linewidth=0.8)
    value = ranked[-1]["value"]
    ax.set_xlabel(f"elasticity of {LABELS[q]}: % change per % change of the input")
    ax.set_title(f"What {LABELS[q]} ({value:.4g}{' N m' if q == 'torque_Nm' else ' N'}) hangs on")
    ax.grid(axis="x", alpha=0.3)
    fig.tight_layout()
    return fig
