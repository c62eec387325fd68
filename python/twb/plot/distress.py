"""Where the bearing fails: the distress map (W_d against speed), a grid's failure loads
in small multiples, and the fold curve of a distress_curve study (the safe operating
region). They answer the solver's own question, which the paper's figures leave to the
reader.
"""

import math
import re

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D

from .style import Style, column_label, new_figure, parameter_label, speed_key, speed_label
from .tables import FOLD_CURVE_PARAMETERS, SLIDING_LABELS, run_axes, run_order, run_tag


def series_label(key):
    """A run of the map: its axes (one, or a grid's several) and its sliding film."""
    parameter, sliding = key
    parts = ([] if parameter is None else [parameter_label(parameter)]) + \
        ([] if sliding is None else [SLIDING_LABELS[sliding]])
    return ", ".join(parts) if parts else r"$W_d$"


def speed_axis(data):
    """Scale from rad/s and the axis label: rpm when asked for."""
    if data.rpm:
        return 60.0 / (2.0 * math.pi), r"speed (rpm)"
    return 1.0, r"speed $\omega$ (rad/s)"


def searched_up_to(method):
    """The highest load a search without W_d reached, from its method ("no fold up to 2000 N ...").
    The last such load: a note before the verdict (the start check's "the oil supply may hold
    up to 40 N") is not the search's end."""
    found = re.findall(r"up to ([0-9.eE+-]+) N", method or "")
    return float(found[-1]) if found else None


LIMIT_LABELS = {
    "oil_temperature": "oil's maximum temperature",
    "oil_peak_temperature": "oil's peak temperature",
    "material_temperature:carrier": "carrier's material temperature",
    "material_temperature:washer": "washer's material temperature",
    "material_temperature:gear": "gear's material temperature",
    "film_ratio": "least film ratio",
    "pv": "washer's PV limit",
    "scuffing": "scuffing (contact temperature)",
    "modulus_data:carrier": "carrier's modulus data",
    "modulus_data:washer": "washer's modulus data",
    "modulus_data:gear": "gear's modulus data",
}
LIMIT_STYLES = {"oil_temperature": "tab:purple", "oil_peak_temperature": "tab:orange",
                "material_temperature:carrier": "tab:brown", "material_temperature:washer": "tab:olive",
                "material_temperature:gear": "tab:cyan", "film_ratio": "tab:pink",
                "pv": "tab:gray", "scuffing": "tab:red", "modulus_data:carrier": "darkgoldenrod",
                "modulus_data:washer": "tab:green", "modulus_data:gear": "teal"}


def draw_limit_curves(ax, rows, scale, distress, single, color, tag, ends):
    """Each failure criterion's crossing along the curve, labelled by its criterion; with
    one curve the safe region: below the lowest of W_d and the limits, wherever one is
    known (a limit ends where the fold comes first)."""
    curves = {}
    for r in rows:
        if r["fold"] in LIMIT_LABELS:
            converged = r.get("W_fold_extrapolated_N")
            curves.setdefault(r["fold"], []).append(
                (scale * r["p"], r["load"], math.nan if converged is None else converged,
                 math.nan if r.get("W_fold_error_N") is None else r["W_fold_error_N"]))
    lines = [distress] if len(distress) else []
    for kind, points in curves.items():
        points = np.array(sorted(points), dtype=float).reshape(-1, 4)
        line_color = LIMIT_STYLES[kind] if single else color
        ax.plot(points[:, 0], points[:, 1], color=line_color, linestyle="-."
                if not single else "-", linewidth=1.5, label=f"{LIMIT_LABELS[kind]} crossed" + tag)
        # Its mesh-converged crossing with the bar, where the study has them; the region
        # lies below it where every point has one (the answer the study was asked for).
        if np.isfinite(points[:, 2]).any():
            ax.plot(points[:, 0], points[:, 2], color=line_color, linestyle=":", linewidth=1.2)
            ax.fill_between(points[:, 0], points[:, 2] - points[:, 3], points[:, 2] + points[:, 3],
                            color=line_color, alpha=0.12, linewidth=0)
        lines.append(points[:, [0, 2]] if np.isfinite(points[:, 2]).all() else points[:, :2])
    if not single or not curves:
        return
    xs = np.concatenate([line[:, 0] for line in lines] + ([np.array(ends)] if ends else []))
    x = np.linspace(xs.min(), xs.max(), 400)
    lowest = np.full_like(x, np.inf)
    for line in lines:
        inside = (x >= line[:, 0].min()) & (x <= line[:, 0].max())
        lowest[inside] = np.minimum(lowest[inside], np.interp(x[inside], line[:, 0], line[:, 1]))
    known = np.isfinite(lowest)
    ax.fill_between(x, 0, np.where(known, lowest, np.nan), color="tab:green", alpha=0.12, linewidth=0,
                    label="safe: below every criterion")
    top = max(float(np.nanmax(np.where(known, lowest, np.nan))) * 1.15, ax.get_ylim()[1])
    ax.fill_between(x, np.where(known, lowest, np.nan), top, color="tab:red", alpha=0.06, linewidth=0,
                    label="fails: past the lowest curve")


def figure_fold_curve(data, name, column, rows):
    """The fold curve of a distress_curve study as the safe operating region: W_d against
    the parameter (solid), its mesh-converged value with the error bar where the study has
    it (dotted, shaded), the hot branch's recovery fold (dashed), the cusp where the two
    meet and sudden distress ends; below W_d no sudden distress, between the two folds a
    bearing that once passed W_d stays hot. A family of curves (one per value of a second
    parameter) gets a colour per curve."""
    fig, ax = new_figure("Safe operating region: distress load along the curve"
                         if not any(r["fold"] in LIMIT_LABELS for r in rows)
                         else "Safe operating region: below distress and every limit")
    scale, xlabel = (speed_axis(data) if column == "speed_rad_s" else (1.0, FOLD_CURVE_PARAMETERS[column]))
    # The whole range the study searched: its end searches are distress.csv's rows.
    ends = [scale * d.speed for d in data.distress] if column == "speed_rad_s" else []
    unit = re.search(r"\(([^)]*)\)$", xlabel)
    unit = " " + unit.group(1) if unit else ""
    members = sorted({r["member"] for r in rows if r["member"] is not None}, key=lambda m: m[1]) or [None]
    single = len(members) == 1
    style = Style(range(len(members)))
    for i, member in enumerate(members):
        mine = [r for r in rows if r["member"] == member]
        color = "tab:red" if single else style.colors[i]
        tag = "" if member is None else f" ({parameter_label(member)})"
        branches = {}
        for r in mine:
            if r["fold"] in ("distress", "recovery"):
                branches.setdefault(r["fold"], []).append((scale * r["p"], r["load"]))
            elif r["fold"] == "cusp":  # where both branches end: drawn into each
                for kind in ("distress", "recovery"):
                    branches.setdefault(kind, []).append((scale * r["p"], r["load"]))
        distress = np.array(sorted(branches.get("distress", [])), dtype=float).reshape(-1, 2)
        recovery = np.array(sorted(branches.get("recovery", [])), dtype=float).reshape(-1, 2)
        if len(distress):
            ax.plot(distress[:, 0], distress[:, 1], color=color, linewidth=1.8,
                    label=r"distress load $W_d$ (fold)" + tag)
            if not (single and any(r["fold"] in LIMIT_LABELS for r in mine)):
                ax.fill_between(distress[:, 0], 0, distress[:, 1], color="tab:green" if single else color,
                                alpha=0.15 if single else 0.06, linewidth=0,
                                label="below $W_d$: no sudden distress" if single else None)
        # The mesh-converged W_d (Richardson) with its error bar, where the study has it.
        # A fold without its bar (refused, or the estimate off there) breaks the line (NaN).
        converged = np.array(sorted((scale * r["p"],
                                     math.nan if r.get("W_fold_extrapolated_N") is None else r["W_fold_extrapolated_N"],
                                     math.nan if r.get("W_fold_error_N") is None else r["W_fold_error_N"])
                                    for r in mine if r["fold"] == "distress"), dtype=float).reshape(-1, 3)
        if not np.isfinite(converged[:, 1]).any():
            converged = converged[:0]
        if len(converged):
            ax.plot(converged[:, 0], converged[:, 1], color=color, linestyle=":", linewidth=1.4,
                    label="mesh-converged, with its error bar (dotted)" + tag if single or i == 0 else None)
            ax.fill_between(converged[:, 0], converged[:, 1] - converged[:, 2], converged[:, 1] + converged[:, 2],
                            color=color, alpha=0.12, linewidth=0)
        if len(recovery):
            ax.plot(recovery[:, 0], recovery[:, 1], color="tab:blue" if single else color, linestyle="--",
                    linewidth=1.4, label="recovery: the hot branch's lowest load" if single else None)
        if single and len(distress) and len(recovery):
            lo, hi = max(distress[0, 0], recovery[0, 0]), min(distress[-1, 0], recovery[-1, 0])
            if hi > lo:
                x = np.linspace(lo, hi, 200)
                ax.fill_between(x, np.interp(x, recovery[:, 0], recovery[:, 1]),
                                np.interp(x, distress[:, 0], distress[:, 1]), facecolor="none",
                                edgecolor="tab:orange", hatch="//", linewidth=0,
                                label="between the folds: stays hot once past $W_d$")
        for r in mine:
            if r["fold"] not in ("cusp", "turn"):
                continue
            x = scale * r["p"]
            ax.plot([x], [r["load"]], marker="*", markersize=14, color="black" if single else color,
                    linestyle="none",
                    label=("cusp: sudden distress ends" if r["fold"] == "cusp" else "the curve turns back")
                    if single or i == 0 else None)
            if r["fold"] == "cusp":
                ax.annotate(f"cusp {x:.4g}{unit}, {r['load']:.4g} N", (x, r["load"]), textcoords="offset points",
                            xytext=(8, -14), fontsize="small", color="black" if single else color)
            if r["fold"] == "cusp" and single and len(distress):
                # The side of the cusp the curve does not reach has no fold: gradual heating,
                # which is safe only below the limits' curves (drawn below).
                left = distress[:, 0].mean() > x
                ax.annotate("no fold: gradual heating", (x, r["load"]), textcoords="offset points",
                            xytext=(-110 if left else 12, 14), fontsize="small", color="0.35")
        # The region below W_d mesh-converged where every fold has its value, as the limits'
        # (draw_limit_curves): one kind of value along the boundary.
        region = converged[:, :2] if len(converged) and np.isfinite(converged[:, 1]).all() else distress
        draw_limit_curves(ax, mine, scale, region, single, color, tag, ends)
    if not single:
        ax.plot([], [], color="0.3", linestyle="--", label="recovery folds (dashed)")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("load (N)")
    ax.set_ylim(bottom=0)
    limits = any(r["fold"] in LIMIT_LABELS for r in rows)
    # With the limits' curves the region's low loads are the answer: the legend goes up.
    ax.legend(fontsize="x-small" if limits else "small", framealpha=0.85,
              loc="upper right" if limits else "lower right")
    return fig


# Up to this many runs the legend finds a free corner inside the axes; more (a grid's
# combinations) would cover their own data, so the legend goes beside the axes.
RUNS_INSIDE_LEGEND = 3


def found_top(rows):
    """The highest load a map's rows found (W_d and its bracket, the fold, the failure
    load, the mesh-converged W_d and W_fail with their bars), or None where they found none."""
    loads = []
    for r in rows:
        loads += [v for v in (r.w_d, r.high, r.fold, r.failure) if v is not None]
        if r.extrapolated is not None:
            loads.append(r.extrapolated + (r.error or 0.0))
        if r.failure_converged is not None:
            loads.append(r.failure_converged + (r.failure_error or 0.0))
    return max(loads) if loads else None


def failure_value(row):
    """W_fail as the run prints it first: mesh-converged where the run has it."""
    return row.failure_converged if row.failure_converged is not None else row.failure


def limit_rows(rows):
    """The rows where a limit, not distress, sets the failure load."""
    return [r for r in rows if r.failure is not None and r.criterion not in (None, "distress")]


def run_handle(rows, color, marker, drawn):
    """A run's legend entry, drawn as what the run shows: its W_d with the bracket
    (drawn, the errorbar itself) where it has one, else its limit's crosses or its folds,
    so that a run without any W_d (failing by a limit first) is named too."""
    if drawn is not None:
        return drawn
    if limit_rows(rows):
        return Line2D([], [], color=color, marker="X", markersize=8, linestyle="-.", linewidth=1.0)
    return Line2D([], [], color=color, marker="D", markersize=8, markerfacecolor="none", linestyle="none")


def legend_place(runs):
    """Where the map's legend goes: the emptiest corner for a few runs, beside the axes
    for many; and the figure's size to leave room there."""
    if runs <= RUNS_INSIDE_LEGEND:
        return {"loc": "best"}, (6.4, 4.8)
    return {"loc": "upper left", "bbox_to_anchor": (1.02, 1.0), "borderaxespad": 0.0}, (11.0, 4.8)


def figure_distress_map(data):
    series = {}
    for d in data.distress:
        series.setdefault((d.parameter, d.sliding), []).append(d)
    plottable = [k for k, rows in series.items()
                 if any(r.w_d is not None or r.fold is not None or r.failure is not None for r in rows)]
    if not plottable:
        return None
    limited = bool(limit_rows(data.distress))
    plottable.sort(key=lambda k: (k[0] is not None, run_order(k[0]), k[1] or ""))
    style = Style(range(len(plottable)))
    place, size = legend_place(len(plottable))
    fig, ax = new_figure(r"Distress load $W_d$ vs speed: below it, no sudden distress" if not limited
                         else r"Where the washer fails: $W_{fail}$ (first criterion) and $W_d$ vs speed", size=size)
    scale, xlabel = speed_axis(data)
    any_fold = any_estimate = any_beyond = any_limit_converged = False
    # The loads the map found set the load axis; a search that found nothing up to a far
    # higher load_end is marked at the axis's top, its load in its label, not drawn there
    # (it would squash every curve to the bottom of the figure).
    top = found_top([r for key in plottable for r in series[key]])
    ceiling = None if top is None else 1.25 * top
    # One entry per run, in the runs' order, whatever the run draws.
    handles, labels = [], []
    for i, key in enumerate(plottable):
        rows = sorted(series[key], key=lambda r: r.speed)
        color, marker = style.colors[i], style.markers[i]
        drawn = None
        found = [r for r in rows if r.w_d is not None]
        # A speed without W_d up to the highest load searched is drawn there, as "> load_end".
        beyond = [(r.speed, load) for r in rows
                  if r.w_d is None and (load := searched_up_to(r.method)) is not None]
        if beyond:
            any_beyond = True
            shown = [min(load, ceiling) if ceiling is not None else load for _, load in beyond]
            ax.plot([scale * b[0] for b in beyond], shown, linestyle="none", marker="^",
                    markersize=9, markerfacecolor="none", markeredgecolor=color, clip_on=False)
            # Neighbouring speeds' labels alternate above and below their markers, and each
            # series' a little further down, so that labels at one load do not overprint.
            for j, ((speed, load), y) in enumerate(zip(beyond, shown)):
                ax.annotate(f"> {load:g} N", (scale * speed, y), textcoords="offset points",
                            xytext=(7, (6 if j % 2 else -12) - 9 * i), fontsize="x-small", color=color)
        if found:
            x = [scale * r.speed for r in found]
            y = [r.w_d for r in found]
            if len(found) > 1:
                ax.fill_between(x, 0, y, color=color, alpha=0.08, linewidth=0)
            # A missing bracket side draws no bar; a W_d outside its bracket would be a
            # twb bug, drawn as a zero-length bar rather than hidden.
            below = [max(r.w_d - r.low, 0.0) if r.low is not None else 0.0 for r in found]
            above = [max(r.high - r.w_d, 0.0) if r.high is not None else 0.0 for r in found]
            drawn = ax.errorbar(x, y, yerr=[below, above], color=color, marker=marker, markersize=5,
                                linewidth=1.2, capsize=4)
        converged = [r for r in rows if r.extrapolated is not None and r.error is not None]
        if converged:
            any_estimate = True
            ax.errorbar([scale * r.speed for r in converged], [r.extrapolated for r in converged],
                        yerr=[r.error for r in converged], color=color, marker="s", markersize=5,
                        markerfacecolor="none", linestyle="--", linewidth=1.0, capsize=4)
        # Where a limit, not distress, sets the failure load: drawn with its criterion, at
        # its mesh-converged value and bar where the run has them (what the run prints
        # first), else on the scene's mesh.
        failing = limit_rows(rows)
        if failing:
            any_limit_converged = any_limit_converged or any(r.failure_converged is not None for r in failing)
            ax.errorbar([scale * r.speed for r in failing], [failure_value(r) for r in failing],
                        yerr=[r.failure_error if r.failure_error is not None else 0.0 for r in failing],
                        color=color, marker="X", markersize=8, linestyle="-." if len(failing) > 1 else "none",
                        linewidth=1.0, capsize=3)
            # The criterion named where it starts to set W_fail along the speeds, not at
            # every speed: the names at neighbouring speeds overprinted one another.
            for j, r in enumerate(failing):
                if j > 0 and failing[j - 1].criterion == r.criterion:
                    continue
                ax.annotate(LIMIT_LABELS.get(r.criterion, r.criterion), (scale * r.speed, failure_value(r)),
                            textcoords="offset points", xytext=(7, 5 - 9 * i), fontsize="x-small", color=color)
        folds = [r for r in rows if r.fold is not None]
        if folds:
            any_fold = True
            ax.plot([scale * r.speed for r in folds], [r.fold for r in folds], linestyle="none",
                    marker="D", markersize=8, markerfacecolor="none", markeredgecolor=color,
                    markeredgewidth=1.2)
        handles.append(run_handle(rows, color, marker, drawn))
        labels.append(series_label(key))
    if "bbox_to_anchor" in place:
        # The labels right of the highest speed's markers would run under the legend.
        lo, hi = ax.get_xlim()
        ax.set_xlim(lo, hi + 0.12 * (hi - lo))
    ax.set_xlabel(xlabel)
    ax.set_ylabel("load (N)")
    if ceiling is not None:
        ax.set_ylim(0, ceiling)
    else:
        ax.set_ylim(bottom=0)
    handles.append(Line2D([], [], color="black", marker="|", linestyle="none", markersize=10))
    labels.append("bracket: settled / ran away")
    if any_beyond:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="^", markerfacecolor="none"))
        labels.append("no W_d up to the highest load searched")
    if any_fold:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="D",
                              markerfacecolor="none"))
        labels.append("fold of the steady branch")
    if any_estimate:
        handles.append(Line2D([], [], color="black", linestyle="--", marker="s", markerfacecolor="none"))
        labels.append("mesh-converged W_d (Richardson) ± error")
    if limited:
        handles.append(Line2D([], [], color="black", linestyle="none", marker="X"))
        labels.append("$W_{fail}$: a limit crossed first (criterion named)"
                      + (", mesh-converged ± error" if any_limit_converged else ""))
    # "best" for a few runs: the markers of searches without W_d sit at the top, where a
    # fixed corner would cover them.
    ax.legend(handles, labels, fontsize="small", framealpha=0.85, **place)
    return fig


# The grid's failure criteria as markers: thermo-viscous distress (a fold) a filled circle,
# each limit a cross of its own, in LIMIT_LABELS's order, so that two limits on one
# figure stay apart.
DISTRESS_MARKER = "o"
LIMIT_MARKERS = ("X", "P", "x", "+")
# Panels per row of the grid figure before a new row starts.
GRID_PANELS_PER_ROW = 4


def grid_rows(data):
    """distress.csv's rows of a grid (two or more axes), those with the first grid row's
    axes: merged directories of different grids are not one grid."""
    rows = [d for d in data.distress if len(run_axes(d.parameter)) >= 2]
    columns = [c for c, _ in run_axes(rows[0].parameter)] if rows else []
    return [d for d in rows if [c for c, _ in run_axes(d.parameter)] == columns]


def failure_of(row):
    """W_fail and its criterion, or (None, None) where no failure was found; in a
    distress.csv of before W_fail_N, W_d is the only criterion there is."""
    if row.failure is not None:
        return row.failure, row.criterion
    if row.criterion is None and row.w_d is not None:
        return row.w_d, "distress"
    return None, None


def criterion_markers(rows):
    """The marker of each criterion the rows fail by: distress's circle, a cross per limit."""
    found = {failure_of(r)[1] for r in rows} - {None}
    limits = [c for c in LIMIT_LABELS if c in found] + sorted(found - set(LIMIT_LABELS) - {"distress"})
    markers = {"distress": DISTRESS_MARKER} if "distress" in found else {}
    markers.update((c, LIMIT_MARKERS[i % len(LIMIT_MARKERS)]) for i, c in enumerate(limits))
    return markers


def criterion_label(criterion):
    if criterion == "distress":
        return "thermo-viscous distress (fold)"
    return LIMIT_LABELS.get(criterion, criterion)


def line_key(row):
    """The grid line a row lies on: the remaining axes' values (the first is the x axis)
    and its sliding film."""
    return run_tag(run_axes(row.parameter)[1:]), row.sliding


def line_label(key):
    rest, sliding = key
    return ", ".join([parameter_label(rest)] + ([] if sliding is None else [SLIDING_LABELS[sliding]]))


def draw_grid_panel(ax, rows, lines, style, markers):
    """One speed's panel: W_fail against the first axis, a line per combination of the
    others, each point marked by its criterion; a search that found no failure drawn as an
    open triangle at the highest load it searched ("not reached")."""
    any_beyond = False
    for i, key in enumerate(lines):
        mine = sorted((r for r in rows if line_key(r) == key), key=lambda r: run_axes(r.parameter)[0][1])
        if not mine:
            continue
        color = style.colors[i]
        x = np.array([run_axes(r.parameter)[0][1] for r in mine], dtype=float)
        failures = [failure_of(r) for r in mine]
        load = np.array([math.nan if w is None else w for w, _ in failures], dtype=float)
        # The line joins the failure loads found; a point not reached breaks it, its
        # triangle a lower bound, not a value.
        ax.plot(x, load, color=color, linewidth=1.2)
        for criterion, marker in markers.items():
            on = np.array([c == criterion for _, c in failures])
            filled = marker in ("o", "X", "P")
            ax.plot(x[on], load[on], linestyle="none", marker=marker, markersize=7 if filled else 8,
                    color=color, markeredgewidth=1.0 if filled else 1.6)
        beyond = [(xk, searched_up_to(r.method)) for xk, r, (w, _) in zip(x, mine, failures) if w is None]
        beyond = [(xk, top) for xk, top in beyond if top is not None]
        if beyond:
            any_beyond = True
            ax.plot([b[0] for b in beyond], [b[1] for b in beyond], linestyle="none", marker="^",
                    markersize=8, markerfacecolor="none", markeredgecolor=color)
    return any_beyond


def grid_legends(ax, lines, style, markers, any_beyond):
    """Beside the top right panel: the lines (the remaining axes' values), and beneath it
    the criteria, compact, in black (the colour is the line's)."""
    runs = ax.legend([Line2D([], [], color=style.colors[i], linewidth=1.5) for i in range(len(lines))],
                     [line_label(key) for key in lines], fontsize="x-small", framealpha=0.85,
                     loc="upper left", bbox_to_anchor=(1.04, 1.0), borderaxespad=0.0)
    ax.add_artist(runs)
    handles = [Line2D([], [], color="black", marker=m, linestyle="none",
                      markeredgewidth=1.0 if m in ("o", "X", "P") else 1.6) for m in markers.values()]
    labels = [criterion_label(c) for c in markers]
    if any_beyond:
        handles.append(Line2D([], [], color="black", marker="^", markerfacecolor="none", linestyle="none"))
        labels.append("not reached: no failure up to load_end")
    ax.legend(handles, labels, fontsize="x-small", framealpha=0.85, title="fails first by",
              title_fontsize="x-small", loc="lower left", bbox_to_anchor=(1.04, 0.0), borderaxespad=0.0)


def figure_distress_grid(data):
    """A grid's failure loads in small multiples: a panel per speed (shared load axis),
    W_fail against the grid's first axis, a line per combination of the others, marked
    by the criterion that fails first. None without a grid or without anything to draw."""
    rows = grid_rows(data)
    rows = [r for r in rows if run_axes(r.parameter)[0][1] is not None]  # no x for an axis not set
    if not any(failure_of(r)[0] is not None or searched_up_to(r.method) is not None for r in rows):
        return None
    column = run_axes(rows[0].parameter)[0][0]
    speeds = sorted({speed_key(r.speed) for r in rows})
    lines = sorted({line_key(r) for r in rows}, key=lambda k: (run_order(k[0]), k[1] or ""))
    style = Style(range(len(lines)))
    markers = criterion_markers(rows)
    ncols = min(len(speeds), GRID_PANELS_PER_ROW)
    nrows = math.ceil(len(speeds) / ncols)
    # Tall enough for both legends beside the top row, one above the other.
    entries = len(lines) + len(markers) + 3
    height = max(3.6 * nrows, 1.2 + 0.2 * entries)
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.0 * ncols + 3.2, height), sharex=True, sharey=True,
                             squeeze=False)
    values = sorted({run_axes(r.parameter)[0][1] for r in rows})
    any_beyond = False
    for k, ax in enumerate(axes.flat):
        if k >= len(speeds):
            ax.set_visible(False)
            continue
        mine = [r for r in rows if speed_key(r.speed) == speeds[k]]
        any_beyond = draw_grid_panel(ax, mine, lines, style, markers) or any_beyond
        ax.set_title(speed_label(speeds[k]), fontsize="medium")
        ax.grid(True, which="major", alpha=0.3)
        ax.set_xlabel(column_label(column))
        if len(values) <= 8:
            ax.set_xticks(values)
        if k % ncols == 0:
            ax.set_ylabel(r"failure load $W_{fail}$ (N)")
    axes[0, 0].set_ylim(bottom=0)
    grid_legends(axes[0, ncols - 1], lines, style, markers, any_beyond)
    fig.suptitle(f"Where the washer fails over the grid: $W_{{fail}}$ against {column_label(column)}, "
                 "one panel per speed", fontsize="medium")
    return fig
