"""How well a calibration study's fit reproduces the measurements: for each measured
quantity, the predictions at the fit (and at the start) against the measured values,
so that a point the fit cannot reach stands off the diagonal; with it the fitted inputs
and their standard deviations, the answer the study is run for."""

import math

import matplotlib.pyplot as plt

from .style import FEFF_LABEL
from .tables import CALIBRATION_QUANTITIES

# The axis labels of the quantities a calibration fits, in the order drawn (a quantity
# twb adds later is drawn by its name).
QUANTITY_LABELS = dict(zip(CALIBRATION_QUANTITIES, (
    "friction torque (N m)", FEFF_LABEL, "mean washer temperature (°C)", "maximum film temperature (°C)")))


def _quantities(points):
    """The quantities measured, the known ones in QUANTITY_LABELS's order, then the rest."""
    present = list(dict.fromkeys(p["quantity"] for p in points))
    return [q for q in QUANTITY_LABELS if q in present] + [q for q in present if q not in QUANTITY_LABELS]


def input_line(row):
    """A fitted input as "path = value ± sd unit", its bound named where the fit rests on
    it (the sd left out where the data do not determine it; a unit "1" left out)."""
    text = f"{row['parameter']} = {row['fitted']:.6g}"
    if row["sd"] is not None:
        text += f" ± {row['sd']:.2g}"
    if row["parameter_unit"] not in ("", "1"):
        text += f" {row['parameter_unit']}"
    text += f"   (start {row['start']:.4g}, bounds {row['lower']:.4g} to {row['upper']:.4g})"
    if row["at_bound"]:
        text += f", at its {row['at_bound']} bound"
    return text


def _parity(ax, quantity, points):
    """One quantity: fitted (filled) and at-start (hollow) predictions against the measured
    values, ±sd on the measured where the readings have one, and the line fitted = measured."""
    label = QUANTITY_LABELS.get(quantity, quantity)
    measured = [p["measured"] for p in points]
    bars = [p for p in points if p["sd"] is not None]
    if bars:
        ax.errorbar([p["measured"] for p in bars], [p["fitted"] for p in bars], xerr=[p["sd"] for p in bars],
                    fmt="none", ecolor="tab:blue", alpha=0.6, capsize=3, label="measured ± its sd")
    ax.plot(measured, [p["at_start"] for p in points], "o", color="tab:gray", markerfacecolor="none",
            label="at the start")
    ax.plot(measured, [p["fitted"] for p in points], "o", color="tab:blue", label="at the fit")
    values = measured + [p[c] for p in points for c in ("at_start", "fitted")]
    values += [p["measured"] + s * p["sd"] for p in bars for s in (-1, 1)]
    low, high = min(values), max(values)
    pad = 0.05 * (high - low) or 0.05 * abs(high) or 1.0
    limits = (low - pad, high + pad)
    ax.plot(limits, limits, "--", color="black", linewidth=0.8, label="predicted = measured")
    ax.set_xlim(limits)
    ax.set_ylim(limits)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(f"measured: {label}")
    ax.set_ylabel(f"predicted: {label}")
    # The residuals as the fit weighs them: in the readings' sd, or relative to the
    # readings where they have none.
    rms = math.sqrt(sum(p["residual"] ** 2 for p in points) / len(points))
    residual = f"rms residual {rms:.3g} sd" if bars else f"rms relative residual {rms:.3g}"
    ax.set_title(f"{quantity}: {len(points)} value{'s' if len(points) != 1 else ''}, {residual}",
                 fontsize="medium")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")


def figure_calibration(calibration, points):
    """A parity plot per measured quantity and the fitted inputs beneath. None without a
    measured value to draw."""
    if not points:
        return None
    quantities = _quantities(points)
    lines = [input_line(r) for r in calibration]
    fig = plt.figure(figsize=(4.6 * len(quantities) + 0.6, 5.0 + 0.22 * len(lines)))
    grid = fig.add_gridspec(2, len(quantities), height_ratios=[4.6, 0.4 + 0.22 * len(lines)])
    for k, q in enumerate(quantities):
        _parity(fig.add_subplot(grid[0, k]), q, [p for p in points if p["quantity"] == q])
    text = fig.add_subplot(grid[1, :])
    text.axis("off")
    if lines:
        text.text(0.0, 1.0, "Fitted:\n" + "\n".join(lines), va="top", ha="left", fontsize="small",
                  transform=text.transAxes)
    measured_points = len({p["point"] for p in points})
    fig.suptitle(f"Calibration: {len(calibration)} input{'s' if len(calibration) != 1 else ''} fitted to "
                 f"{len(points)} measured value{'s' if len(points) != 1 else ''} at {measured_points} "
                 f"point{'s' if measured_points != 1 else ''}", fontsize="medium")
    return fig
