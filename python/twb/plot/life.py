"""A washer's life (study type life): how deep each face wore (with each face's Rq where
the faces run in) and how its failure load moved over the life (left), and the faces worn
where the life ends (right): the face at rest in the load frame over the annulus, the
turning face against the radius at every reported time."""

import math

import matplotlib.pyplot as plt
import numpy as np

# How each way a life ends is said on the figure.
ENDINGS = {
    "end": "lasts its duration",
    "wear_allowance": "a face reaches the wear allowance",
    "failure": "its failure load comes down to the operating load",
    "distress": "distress: the steady bearing is lost",
}


def _profile_at(profile, t):
    """The face at rest's depths (µm) on the (radius, angle) grid at time t, the radii,
    the angles and the turning face's depth per radius."""
    at = profile["t_h"] == t
    r, theta = profile["r_m"][at], profile["theta_rad"][at]
    radii, angles = np.unique(r), np.unique(theta)
    rest = profile["worn_rest_um"][at].reshape(radii.size, angles.size)
    turn = profile["worn_turn_um"][at].reshape(radii.size, angles.size)[:, 0]
    return radii, angles, rest, turn


def _draw_depths(ax, rows):
    t = [row["t_h"] for row in rows]
    for face, color, name in (("rest", "tab:red", "face at rest"), ("turn", "tab:blue", "turning face")):
        ax.plot(t, [row[f"worn_depth_{face}_max_um"] for row in rows], color=color, linewidth=1.5,
                label=f"{name}, deepest")
        ax.plot(t, [row[f"worn_depth_{face}_mean_um"] for row in rows], color=color, linestyle="--",
                linewidth=1.2, label=f"{name}, mean")
    ax.set_ylabel("worn depth (µm)")
    ax.legend(fontsize="small", loc="upper left")
    # Each face's Rq on its own axis, where a face runs in (a face that does not keeps its Rq).
    if any(row[f"rq_{face}_um"] != rows[0][f"rq_{face}_um"] for row in rows for face in ("rest", "turn")):
        rq_ax = ax.twinx()
        for face, color, name in (("rest", "tab:red", "face at rest"), ("turn", "tab:blue", "turning face")):
            rq_ax.plot(t, [row[f"rq_{face}_um"] for row in rows], color=color, linestyle=":", linewidth=1.2,
                       label=f"Rq, {name}")
        rq_ax.set_ylabel("Rq (µm)")
        rq_ax.set_ylim(bottom=0.0)
        rq_ax.legend(fontsize="small", loc="lower right")


def _draw_failure_load(ax, rows, load):
    t = [row["t_h"] for row in rows]
    w = [math.nan if row["W_fail_N"] is None else row["W_fail_N"] for row in rows]
    ax.plot(t, w, "o-", color="tab:green", linewidth=1.5, markersize=4, label="failure load")
    if load is not None:
        ax.axhline(load, color="black", linewidth=0.9, linestyle=":", label=f"operating load {load:.4g} N")
    last = rows[-1]
    ending = ENDINGS.get(last["event"])
    if ending:
        ax.set_title(f"the life ends at {last['t_h']:.4g} h: {ending}", fontsize="small")
    ax.set_ylabel("failure load W_fail (N)")
    ax.set_xlabel("time t (h)")
    ax.legend(fontsize="small", loc="upper left")


def _draw_rest_face(fig, spec, profile, t_end):
    radii, angles, rest, _ = _profile_at(profile, t_end)
    ax = fig.add_subplot(spec, projection="polar")
    # The angle closed round the turn, so that the map has no gap at θ = 0.
    theta = np.append(angles, 2.0 * np.pi)
    depth = np.hstack([rest, rest[:, :1]])
    mesh = ax.pcolormesh(theta, 1e3 * radii, depth, shading="gouraud", cmap="magma_r")
    ax.set_ylim(0.0, 1e3 * radii[-1])
    ax.set_yticks([1e3 * radii[0], 1e3 * radii[-1]])
    ax.set_rlabel_position(112.5)  # clear of the rim at θ = 0, where a tilted gear wears it
    ax.set_title(f"face at rest, worn at {t_end:.4g} h (r in mm)", fontsize="small")
    fig.colorbar(mesh, ax=ax, shrink=0.8, label="worn depth (µm)")


def _draw_turning_face(ax, profile):
    times = np.unique(profile["t_h"])
    colors = plt.get_cmap("viridis")(np.linspace(0.0, 1.0, times.size))
    for t, color in zip(times, colors):
        radii, _, _, turn = _profile_at(profile, t)
        ax.plot(1e3 * radii, turn, color=color, linewidth=1.2,
                label=f"{t:.4g} h" if t in (times[0], times[-1]) else None)
    ax.set_xlabel("radius r (mm)")
    ax.set_ylabel("turning face's worn depth (µm)")
    ax.legend(fontsize="small", loc="upper left", title="time")


def figure_life(rows, profile, load):
    """rows: life.csv's; profile: worn_profile.csv's columns, or None; load: the operating
    load (N), or None. None where the life has no row."""
    if not rows:
        return None
    drawn_profile = profile is not None and profile["t_h"].size > 0
    fig = plt.figure(figsize=(12.0 if drawn_profile else 7.2, 7.6))
    grid = fig.add_gridspec(2, 2 if drawn_profile else 1, width_ratios=[1.2, 1] if drawn_profile else None)
    ax_depth = fig.add_subplot(grid[0, 0])
    ax_fail = fig.add_subplot(grid[1, 0], sharex=ax_depth)
    _draw_depths(ax_depth, rows)
    _draw_failure_load(ax_fail, rows, load)
    for ax in (ax_depth, ax_fail):
        ax.grid(True, alpha=0.3)
    if drawn_profile:
        _draw_rest_face(fig, grid[0, 1], profile, rows[-1]["t_h"])
        ax_turn = fig.add_subplot(grid[1, 1])
        _draw_turning_face(ax_turn, profile)
        ax_turn.grid(True, alpha=0.3)
    fig.suptitle("Life: the worn faces and the failure load as the washer wears", fontsize="medium")
    return fig
