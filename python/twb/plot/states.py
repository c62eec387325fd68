"""The figures of the solved states: the paper's Figs. 6-15 (quantities against load,
contact against film thickness, the Stribeck curve), in its layout, so that they can be
laid beside Jackson & Green (2006).
"""

import numpy as np

from .style import (CONTACT_LABEL, FEFF_LABEL, HMIN_LABEL, LINESTYLES, LOAD_LABEL, STRIBECK_LABEL,
                    Style, finish_legend, new_figure, parameter_label, speed_key, speed_label)
from .tables import run_order

# Figs. 6-12: (file stem, states.csv column, axis label, title, the paper's figure, log axis).
LOAD_FIGURES = (
    ("fig06_f_eff_vs_load", "f_eff", FEFF_LABEL,
     "Effective friction coefficient vs load and speed", 6, False),
    ("fig07_mean_temperature_vs_load", "T_mean_C", "mean washer temperature (°C)",
     "Mean bearing temperature vs load and speed", 7, False),
    ("fig08_hmin_over_sigma_vs_load", "hmin_over_sigma", HMIN_LABEL,
     "Minimum film thickness vs load and speed", 8, False),
    ("fig09_gamma_x_ratio_vs_load", "gamma_x_ratio", r"$\gamma_x/\gamma_{tilt}$",
     "Washer tilt about the x-axis vs load and speed", 9, False),
    ("fig10_gamma_y_ratio_vs_load", "gamma_y_ratio", r"$\gamma_y/\gamma_{tilt}$",
     "Washer tilt about the y-axis vs load and speed", 10, False),
    ("fig11_fluid_share_vs_load", "fluid_share", r"$F_{fluid}/F_{ext}$",
     "Load carried by the fluid film vs load and speed", 11, False),
    ("fig12_contact_share_vs_load", "contact_share", CONTACT_LABEL,
     "Load carried by asperity contact vs load and speed", 12, True))


def parameter_order(parameters):
    """The distinct runs (tags: one axis's (column, value) or a grid's tuple of them) of
    the merged states, sorted axis by axis; None left out."""
    found = {p for p in parameters if p is not None}
    return sorted(found, key=run_order)


def _positive(values):
    """Non-positive values as NaN, so that a log axis leaves a gap instead of a plunge."""
    out = np.array(values, dtype=float)
    out[out <= 0] = np.nan
    return out


def draw_error_bars(ax, data, xcol, ycol, idx, color):
    """The states' mesh-converged values with their error bars (states.csv's
    <ycol>_extrapolated and <ycol>_error), where the states have them; whether any."""
    s = data.states
    if f"{ycol}_error" not in s:
        return False
    value, bar = s[f"{ycol}_extrapolated"][idx], s[f"{ycol}_error"][idx]
    has = np.isfinite(value) & np.isfinite(bar)
    if not has.any():
        return False
    ax.errorbar(s[xcol][idx][has], value[has], yerr=bar[has], fmt="none", ecolor=color, elinewidth=0.8,
                capsize=2.5, alpha=0.8)
    return True


def draw_by_speed(ax, data, xcol, ycol, logx=False, logy=False):
    """One curve per speed (and per run of a study's axes, one value or a grid's
    combination, in its own line style), points joined in order of load, and the states'
    error bars where they have them; the states past the run's failure load W_fail (the
    washer has failed there: a hot branch at hundreds of degrees) faded, so that they do
    not read as operating states. Returns (whether any point had not converged, whether
    any bar was drawn, whether any state was past W_fail)."""
    s = data.states
    speeds = np.array([speed_key(v) for v in s["speed_rad_s"]])
    runs = parameter_order(data.parameters)
    styles = {p: LINESTYLES[i % len(LINESTYLES)] for i, p in enumerate(runs)}
    jumps = {(speed, parameter): w_d for speed, parameter, w_d in distress_lines(data)}
    failures = {(speed_key(d.speed), d.parameter): d.failure for d in data.distress
                if d.sliding is None and d.failure is not None}
    any_unconverged = any_bar = any_past = False
    for key in data.speed_style.keys:
        for run in [None] + runs:
            idx = np.flatnonzero((speeds == key) & np.array([p == run for p in data.parameters],
                                                            dtype=bool))
            if idx.size == 0:
                continue
            # Several directories may hold the same speed (e.g. one point run per load);
            # a stable sort keeps the solver's order among equal loads.
            idx = idx[np.argsort(s["load_N"][idx], kind="stable")]
            x, y = s[xcol][idx], s[ycol][idx]
            if logx:
                x = _positive(x)
            if logy:
                y = _positive(y)
            ok = s["converged"][idx] == 1
            color, marker = data.speed_style.colors[key], data.speed_style.markers[key]
            label = speed_label(key) + ("" if run is None else ", " + parameter_label(run))
            # Past W_d the state jumps to the hot branch: no line through the jump, an
            # arrow across it.
            w_d = jumps.get((key, run))
            loads = s["load_N"][idx]
            cut = np.flatnonzero((loads[:-1] <= w_d) & (loads[1:] > w_d)) if w_d is not None else []
            xs, ys = x[ok].astype(float), y[ok].astype(float)
            at = loads[ok].astype(float)
            if len(cut) and ok[cut[0]] and ok[cut[0] + 1]:
                k = int(np.count_nonzero(ok[:cut[0] + 1]))
                # (an end off a log axis, a zero share, gets the break without the arrow)
                if np.isfinite([xs[k], ys[k], xs[k - 1], ys[k - 1]]).all():
                    ax.annotate("", xy=(xs[k], ys[k]), xytext=(xs[k - 1], ys[k - 1]),
                                arrowprops=dict(arrowstyle="->", color=color, linestyle=":", linewidth=1.0))
                xs, ys, at = np.insert(xs, k, np.nan), np.insert(ys, k, np.nan), np.insert(at, k, np.nan)
            w_fail = failures.get((key, run))
            past = at > w_fail if w_fail is not None else np.zeros(len(at), dtype=bool)
            ax.plot(xs, np.where(past, np.nan, ys), color=color, marker=marker, markersize=4, linewidth=1.2,
                    linestyle=styles.get(run, "-"), label=label)
            if past.any():
                any_past = True
                # From the last operating state on, so that the curve stays one line.
                joined = past | np.append(past[1:], False)
                ax.plot(xs, np.where(joined, ys, np.nan), color=color, marker=marker, markersize=4, linewidth=1.0,
                        linestyle=styles.get(run, "-"), alpha=0.3, markerfacecolor="none")
            if not logx and not logy:
                any_bar = draw_error_bars(ax, data, xcol, ycol, idx, color) or any_bar
            if not ok.all():
                any_unconverged = True
                ax.plot(x[~ok], y[~ok], linestyle="none", marker=marker, markersize=6,
                        markerfacecolor="none", markeredgecolor=color)
    if logx:
        ax.set_xscale("log")
    if logy:
        ax.set_yscale("log")
    return any_unconverged, any_bar, any_past


def distress_lines(data):
    """(speed, parameter, W_d) for the vertical distress marks on load axes.

    A sliding choice's rows are left out: its states are the chosen configuration at
    each load, which may change along the sweep."""
    return [(speed_key(d.speed), d.parameter, d.w_d) for d in data.distress
            if d.sliding is None and d.w_d is not None]


def failure_lines(data):
    """(speed, W_fail) where a limit, not distress, sets the failure load: the washer
    fails there although the branch goes on."""
    return [(speed_key(d.speed), d.failure) for d in data.distress
            if d.sliding is None and d.failure is not None and d.criterion not in (None, "distress")]


def figure_vs_load(data, column, ylabel, title, paper_figure, logy=False):
    fig, ax = new_figure(title, paper_figure)
    unconverged, bars, past = draw_by_speed(ax, data, "load_N", column, logy=logy)
    marks = distress_lines(data)
    for key, _, w_d in marks:
        ax.axvline(w_d, color=data.speed_style.colors[key], linestyle=":", linewidth=1.2)
    fails = failure_lines(data)
    for key, w_fail in fails:
        ax.axvline(w_fail, color=data.speed_style.colors[key], linestyle="-.", linewidth=1.2)
    ax.set_xlabel(LOAD_LABEL)
    ax.set_ylabel(ylabel)
    finish_legend(ax, unconverged, distress=bool(marks), failure=bool(fails), error_bars=bars, past=past)
    return fig


def figure_contact_vs_hmin(data):
    fig, ax = new_figure("Contact share vs minimum film thickness", 13)
    unconverged, _, past = draw_by_speed(ax, data, "hmin_over_sigma", "contact_share")
    # The paper reads its figure against this customary threshold of significant contact.
    ax.axvline(3.0, color="grey", linestyle="--", linewidth=0.8)
    ax.set_xlabel(HMIN_LABEL)
    ax.set_ylabel(CONTACT_LABEL)
    finish_legend(ax, unconverged, past=past)
    return fig


# Where the paper puts the optimum (the Stribeck curve's minimum) in its text on Figs. 14
# and 16: its simulation at Z N / P of about 2.0e-6, its experiments at about 1.0e-6.
PAPER_STRIBECK_OPTIMA = ((2.0e-6, "paper, numerical: optimum near 2.0e-6", "--"),
                         (1.0e-6, "paper, experiments: optimum near 1.0e-6", ":"))


def figure_stribeck(data):
    fig, ax = new_figure("Stribeck curve", 14)
    unconverged, _, past = draw_by_speed(ax, data, "stribeck", "f_eff", logx=True)
    for x, label, style in PAPER_STRIBECK_OPTIMA:
        ax.axvline(x, color="0.4", linestyle=style, linewidth=1.0, label=label)
    ax.set_xlabel(STRIBECK_LABEL)
    ax.set_ylabel(FEFF_LABEL)
    finish_legend(ax, unconverged, past=past)
    return fig


def figure_stribeck_by_friction(data):
    """Fig. 15: one colour per friction law across the merged runs, one curve per
    (law, speed, run): a grid's other axes (a tilt beside the coefficient) are curves
    of their own, not points of one."""
    settings = sorted({f for f in data.friction if f is not None})
    style = Style(settings)
    s = data.states
    fig, ax = new_figure("Stribeck curve for several dry friction coefficients", 15)
    friction = np.array([f if f is not None else "" for f in data.friction], dtype=object)
    speeds = np.array([speed_key(v) for v in s["speed_rad_s"]])
    runs = {run: np.array([p == run for p in data.parameters], dtype=bool)
            for run in [None] + parameter_order(data.parameters)}
    for setting in settings:
        labelled = False
        for key, mine in ((key, mine) for key in data.speed_style.keys for mine in runs.values()):
            idx = np.flatnonzero((friction == setting) & (speeds == key) & mine & (s["converged"] == 1))
            if idx.size == 0:
                continue
            idx = idx[np.argsort(s["load_N"][idx], kind="stable")]
            ax.plot(_positive(s["stribeck"][idx]), s["f_eff"][idx], color=style.colors[setting],
                    marker=style.markers[setting], markersize=4, linewidth=1.2,
                    label=None if labelled else setting)
            labelled = True
    ax.set_xscale("log")
    ax.set_xlabel(STRIBECK_LABEL)
    ax.set_ylabel(FEFF_LABEL)
    finish_legend(ax)
    return fig
