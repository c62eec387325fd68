"""Polar maps of one state's fields (fluid pressure, film thickness, contact pressure,
film temperature, and the washer's deflection where it bends), to see where on the
washer the load is carried and the heat is made.
"""

import math
import os

import matplotlib.pyplot as plt
import numpy as np

from .style import save, speed_key
from .tables import InputError, fields_path, read_fields

FIELD_PANELS = (
    ("p_Pa", 1e-6, "fluid pressure $p$ (MPa)", "viridis"),
    ("h_m", 1e6, "film thickness $h$ (µm)", "cividis"),
    ("p_contact_Pa", 1e-6, "asperity contact pressure $p_c$ (MPa)", "magma"),
    ("T_film_C", 1.0, "film-node temperature $T_f$ (°C)", "inferno"),
)
# Fields only some runs write: a panel where the state's films have them.
OPTIONAL_PANELS = (
    ("washer_deflection_m", 1e6, "washer deflection $w$ (µm)", "coolwarm"),
)
SIGNED_FIELDS = ("washer_deflection_m",)
FILM_NAMES = {1: "film 1 (carrier–washer)", 2: "film 2 (washer–gear)"}


def default_state(run):
    """The last state (1-based row of states.csv) with a fields file whose load lies
    below the distress load W_d of its speed, or without any W_d the last state with
    fields; None when the directory has none."""
    loads, speeds = run.states["load_N"], run.states["speed_rad_s"]
    with_fields = [k for k in range(1, loads.size + 1)
                   if os.path.isfile(fields_path(run.directory, k))]
    # Rows of a study's axes (one, or a grid's several) or of a sliding choice are left
    # out: they are not one distress load per speed.
    limits = {speed_key(d.speed): d.w_d for d in run.distress
              if d.parameter is None and d.sliding is None and d.w_d is not None}
    below = [k for k in with_fields
             if speed_key(speeds[k - 1]) in limits and loads[k - 1] < limits[speed_key(speeds[k - 1])]]
    if below:
        return below[-1]
    return with_fields[-1] if with_fields else None


def select_fields(runs, state):
    """(run, state, fields) for every directory whose fields are to be mapped: state N
    where asked (then every directory must have it), else each directory's default."""
    selected = []
    for run in runs:
        if not run.has_fields:
            if state is not None:
                raise InputError(f"{run.directory}: no fields/ directory, so no state to map "
                                 f"(--state {state}); fields are written by a run with "
                                 f"output.fields: true")
            continue
        n = run.states["load_N"].size
        if state is not None and state > n:
            raise InputError(f"{os.path.join(run.directory, 'states.csv')}: --state {state}: "
                             f"expected a row of states.csv, 1 to {n}")
        k = state if state is not None else default_state(run)
        if k is None:
            continue
        path = fields_path(run.directory, k)
        if not os.path.isfile(path):
            raise InputError(f"{path}: no such file: state {k} has no fields")
        selected.append((run, k, read_fields(path)))
    return selected


def figure_fields(films, load, speed, caption):
    """Polar maps, one row per film (the sliding film first), one column per field."""
    order = sorted(films, key=lambda f: (not films[f]["sliding"], f))
    panels = FIELD_PANELS + tuple(p for p in OPTIONAL_PANELS if all(p[0] in films[f] for f in order))
    ncol = len(panels)
    fig = plt.figure(figsize=(3.3 * ncol, 3.3 * len(order) + 0.9))
    for row, film in enumerate(order):
        f = films[film]
        r_mm = f["r"] * 1e3
        # Close the periodic seam: θ = 2π repeats θ = 0.
        theta = np.append(f["theta"], f["theta"][0] + 2 * math.pi)
        rr, tt = np.meshgrid(r_mm, theta, indexing="ij")
        for col, (column, scale, label, cmap) in enumerate(panels):
            ax = fig.add_subplot(len(order), ncol, row * ncol + col + 1, projection="polar")
            values = f[column] * scale
            values = np.concatenate([values, values[:, :1]], axis=1)
            if column == "p_Pa" and not f["sliding"] and not values.any():
                ax.set_axis_off()
                ax.text(0.5, 0.5, f"no fluid pressure:\n{FILM_NAMES[film]}\ndoes not slide",
                        transform=ax.transAxes, ha="center", va="center", fontsize="small")
                continue
            ax.grid(False)  # pcolormesh over a grid is deprecated; the grid returns below
            # A signed field (the deflection) is centred on zero: white is no deflection.
            signed = column in SIGNED_FIELDS
            reach = float(np.nanmax(np.abs(values))) or 1.0
            limits = dict(vmin=-reach, vmax=reach) if signed else {}
            mesh = ax.pcolormesh(tt, rr, values, shading="gouraud", cmap=cmap, **limits)
            # Circles at the film's radii (given in the film's title), unlabelled: labels
            # inside the annulus would hide the field.
            ax.set_ylim(0.0, r_mm[-1])
            ax.set_yticks([r_mm[0], r_mm[-1]])
            ax.set_yticklabels([])
            ax.tick_params(axis="x", labelsize="x-small")
            ax.grid(True, alpha=0.3)
            bar = fig.colorbar(mesh, ax=ax, shrink=0.75, pad=0.12)
            bar.set_label(label, fontsize="small")
            bar.ax.tick_params(labelsize="x-small")
            title = label.split(" (")[0]
            if col == 0 or (col == 1 and not f["sliding"]):
                title = (f"{FILM_NAMES[film]}{', sliding' if f['sliding'] else ''}\n"
                         f"r = {r_mm[0]:.4g}–{r_mm[-1]:.4g} mm: {title}")
            ax.set_title(title, fontsize="small")
    fig.suptitle(f"Fields at load $F_{{ext}}$ = {load:g} N, speed $\\omega$ = {speed:g} rad/s "
                 f"({caption})\nθ counter-clockwise from +x seen from +z; the sliding surface "
                 f"moves in +θ", fontsize="medium")
    return fig


def make_field_maps(selected, out_dir, formats, written):
    several = len(selected) > 1
    for run, state, films in selected:
        load = run.states["load_N"][state - 1]
        speed = run.states["speed_rad_s"][state - 1]
        caption = f"state {state}" + (f" of {run.name}" if several else "")
        stem = f"fields_{run.name}_state_{state:04d}" if several else f"fields_state_{state:04d}"
        save(figure_fields(films, load, speed, caption), out_dir, stem, formats, written)
