"""What every figure shares: labels, one colour and marker per speed, and saving.

A speed keeps its colour and marker in every figure, and the same results give the same
files, so these are decided in one place.
"""

import math
import os

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

from .tables import FOLD_CURVE_PARAMETERS, run_axes

LINESTYLES = ("-", "--", "-.", ":")
DPI = 150

LOAD_LABEL = r"load $F_{ext}$ (N)"
HMIN_LABEL = r"$h_{min}/\sigma$"
CONTACT_LABEL = r"$F_{cont}/F_{ext}$"
FEFF_LABEL = r"effective friction coefficient $f_{eff}$"
STRIBECK_LABEL = (r"Stribeck number $Z\,N\,/\,P$"
                  "\n(Z: viscosity in Pa·s, N: speed in rev/s, P: $F_{ext}$/washer area in Pa)")

PARAMETER_FORMATS = {
    "friction_coefficient": "dry friction coefficient {:g}",
    "gear_tilt_rad": r"$\gamma_{{tilt}}$ = {:g} rad",
    "roughness_Rq_m": r"$R_q$ = {:g} m",
    "groove_count": "{:g} grooves",
    "groove_width_rad": "grooves {:.3g} rad wide",
    "groove_depth_m": "grooves {:g} m deep",
    "t_h": "worn {:g} h",
}


def speed_key(speed):
    # Speeds are written with 10 significant digits; rounding keeps 545 and 545.0000000001
    # (a speed given in rpm, say) on one curve.
    return float(f"{speed:.6g}")


# Whether legends give speeds in rpm (twb_plot.py --rpm), set by make_figures for the
# figures it draws, as the speed axes are.
_speeds = {"rpm": False}


def show_speeds_in_rpm(on):
    _speeds["rpm"] = bool(on)


def speed_label(speed):
    if _speeds["rpm"]:
        return f"{speed * 60.0 / (2.0 * math.pi):.4g} rpm"
    return f"{speed:g} rad/s"


MARKERS = ("o", "s", "^", "D", "v", "<", ">", "p", "h", "*")


class Style:
    """One colour and marker per speed (or other series key), the same in every figure."""

    def __init__(self, keys):
        self.keys = sorted(set(keys))
        cmap = plt.get_cmap("tab10" if len(self.keys) <= 10 else "viridis")
        n = max(len(self.keys) - 1, 1)
        self.colors = {k: cmap(i if len(self.keys) <= 10 else i / n) for i, k in enumerate(self.keys)}
        self.markers = {k: MARKERS[i % len(MARKERS)] for i, k in enumerate(self.keys)}


def axis_label(name, value):
    """One axis of a run: its column and value, as the legends name it."""
    if value is None:
        return f"{name} not set"
    return PARAMETER_FORMATS.get(name, name + " = {:g}").format(value)


def column_label(name):
    """An axis's column as an axis label: the fold curve's wording where the package has
    one ("dry friction coefficient"), else the column itself, an input's scene path with
    its unit (geometry.gear.tilt_rad), which names it unambiguously."""
    return FOLD_CURVE_PARAMETERS.get(name, name)


def parameter_label(parameter):
    """A run's tag (tables.run_tag: one axis, or a grid's several) as a legend label,
    its axes in the scene's order."""
    return ", ".join(axis_label(name, value) for name, value in run_axes(parameter))


def finish_legend(ax, unconverged=False, distress=False, failure=False, error_bars=False, past=False):
    handles, labels = ax.get_legend_handles_labels()
    if error_bars:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="|", markersize=8))
        labels.append("mesh-converged value ± its error bar")
    if distress:
        handles.append(Line2D([], [], color="black", linestyle=":", linewidth=1.2))
        labels.append(r"distress load $W_d$")
    if failure:
        handles.append(Line2D([], [], color="black", linestyle="-.", linewidth=1.2))
        labels.append(r"failure load $W_{fail}$ (a limit crossed)")
    if unconverged:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="o",
                              markerfacecolor="none"))
        labels.append("not converged")
    if past:
        handles.append(Line2D([], [], color="black", marker="o", markersize=4, markerfacecolor="none", alpha=0.3))
        labels.append(r"past $W_{fail}$: the washer has failed")
    if handles:
        ax.legend(handles, labels, fontsize="small", framealpha=0.85)


def new_figure(title, paper_figure=None, size=(6.4, 4.8)):
    fig, ax = plt.subplots(figsize=size)
    if paper_figure is not None:
        title = f"{title}\n(cf. Jackson & Green 2006, Fig. {paper_figure})"
    ax.set_title(title, fontsize="medium")
    ax.grid(True, which="major", alpha=0.3)
    return fig, ax


# Text stays text in the SVG (editable, searchable); a fixed salt makes its ids
# reproducible.
SVG_RC = {"svg.fonttype": "none", "svg.hashsalt": "twb_plot"}


def save(fig, out_dir, stem, formats, written):
    # Two-line axis labels (the Stribeck number's units) would otherwise be cut off.
    fig.tight_layout()
    os.makedirs(out_dir, exist_ok=True)
    with plt.rc_context(SVG_RC):
        for fmt in formats:
            path = os.path.join(out_dir, f"{stem}.{fmt}")
            # No date in the SVG, so that the same results give the same file.
            metadata = {"Date": None} if fmt in ("svg", "pdf") else None
            fig.savefig(path, dpi=DPI, metadata=metadata)
            written.append(path)
    plt.close(fig)
