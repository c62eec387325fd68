#!/usr/bin/env python3
"""What accuracy costs: the error of one state's reported quantities against CPU time.

Reads the CSV of benchmarks/work_precision (one row per mesh and solver tolerance),
takes as reference the Richardson extrapolation of the two finest meshes at the tightest
tolerance (second order, as the discretization is: docs/model.md; the observed order
from the three finest meshes is printed beside it), and writes

  - a figure: relative error of f_eff, h_min/sigma, mean washer temperature and fluid
    share against CPU seconds, log-log, one line per solver tolerance through the meshes;
  - markdown tables on standard output: per mesh at the tightest tolerance, and per
    tolerance on the paper's 9x66 mesh.

With a second pair of arguments, the same for W_d (benchmarks/work_precision
--distress): the error of W_d on each mesh, and of the Richardson extrapolation of each
pair of neighbouring meshes (its cost the pair's), against CPU time, per speed.

usage: work_precision.py STATE.csv FIGURE.png [DISTRESS.csv DISTRESS_FIGURE.png]
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

QUANTITIES = [
    ("f_eff", "f_eff"),
    ("hmin_over_sigma", "h_min/σ"),
    ("T_mean_C", "mean washer temperature (°C)"),
    ("fluid_share", "fluid share"),
]


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["nr"] = int(r["radial_nodes"])
        r["nt"] = int(r["circumferential_nodes"])
        r["tol"] = float(r["residual_tolerance"])
        r["cpu"] = float(r["cpu_s"])
        for key, _ in QUANTITIES:
            r[key] = float(r[key])
    return [r for r in rows if r["converged"] == "1"]


def reference(rows):
    """Richardson from the two finest meshes at the tightest tolerance; the observed order."""
    tight = min(r["tol"] for r in rows)
    ladder = sorted((r for r in rows if r["tol"] == tight), key=lambda r: r["nr"])
    if len(ladder) < 2:
        raise SystemExit("work_precision.py: the reference needs at least two meshes at the tightest tolerance")
    coarse, fine = ladder[-2], ladder[-1]
    ref, order = {}, {}
    for key, _ in QUANTITIES:
        ref[key] = fine[key] + (fine[key] - coarse[key]) / 3.0
        order[key] = float("nan")
        if len(ladder) >= 3:
            a, b, c = ladder[-3][key], coarse[key], fine[key]
            if (b - a) != 0 and (c - b) != 0 and (b - a) / (c - b) > 0:
                order[key] = math.log2((b - a) / (c - b))
    return ref, order, tight


def relative_error(value, ref):
    return abs(value - ref) / abs(ref) if ref != 0 else abs(value)


def distress(path, figure):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["W_d_N"]]
    for r in rows:
        r["nr"], r["nt"] = int(r["radial_nodes"]), int(r["circumferential_nodes"])
        r["cpu"], r["wd"] = float(r["cpu_s"]), float(r["W_d_N"])
    speeds = sorted({r["speed_rad_s"] for r in rows}, key=float)
    fig, ax = plt.subplots(figsize=(7, 5))
    print("W_d against its mesh-converged value (Richardson from the two finest meshes of each speed):")
    print()
    print("| speed | mesh | W_d (N) | error | CPU s | extrapolated with the next coarser | its error | the pair's CPU s |")
    print("|---|---|---|---|---|---|---|---|")
    for speed in speeds:
        ladder = sorted((r for r in rows if r["speed_rad_s"] == speed), key=lambda r: r["nr"])
        if len(ladder) < 2:
            continue
        ref = ladder[-1]["wd"] + (ladder[-1]["wd"] - ladder[-2]["wd"]) / 3.0
        order = float("nan")
        if len(ladder) >= 3:
            a, b, c = (r["wd"] for r in ladder[-3:])
            if (b - a) * (c - b) > 0:
                order = math.log2((b - a) / (c - b))
        line = ax.loglog([r["cpu"] for r in ladder], [max(relative_error(r["wd"], ref), 1e-16) for r in ladder],
                         marker="o", label=f"{speed} rad/s, one mesh (order {order:.2f})")
        pairs = []
        for coarse, fine in zip(ladder, ladder[1:]):
            extrapolated = fine["wd"] + (fine["wd"] - coarse["wd"]) / 3.0
            pairs.append((coarse["cpu"] + fine["cpu"], relative_error(extrapolated, ref), extrapolated))
        ax.loglog([p[0] for p in pairs[:-1]], [max(p[1], 1e-16) for p in pairs[:-1]], marker="x", linestyle="--",
                  color=line[0].get_color(), label=f"{speed} rad/s, Richardson of a pair")
        for i, r in enumerate(ladder):
            pair = (f"{pairs[i - 1][2]:.2f} N | {100 * pairs[i - 1][1]:.2g} % | {pairs[i - 1][0]:.3g}"
                    if i > 0 and i < len(ladder) - 1 else " | | ")
            print(f"| {speed} | {r['nr']}×{r['nt']} | {r['wd']:.2f} | {100 * relative_error(r['wd'], ref):.2g} % | "
                  f"{r['cpu']:.3g} | {pair} |")
        print(f"| {speed} | reference | {ref:.2f} | (observed order {order:.2f}) | | | | |")
    ax.axhline(0.01, color="grey", linewidth=0.8, linestyle=":")
    ax.set_xlabel("CPU time of the fold search(es) (s)")
    ax.set_ylabel("relative error of W_d")
    ax.set_title("W_d: error against cost, one mesh or a pair extrapolated")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(figure, dpi=120)


def main():
    if len(sys.argv) not in (3, 5):
        raise SystemExit(__doc__)
    rows = read(sys.argv[1])
    ref, order, tight = reference(rows)

    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    tolerances = sorted({r["tol"] for r in rows}, reverse=True)
    for ax, (key, label) in zip(axes.flat, QUANTITIES):
        for tol in tolerances:
            line = sorted((r for r in rows if r["tol"] == tol), key=lambda r: r["nr"])
            ax.loglog([r["cpu"] for r in line], [max(relative_error(r[key], ref[key]), 1e-16) for r in line],
                      marker="o", label=f"tolerance {tol:g}")
        for r in (r for r in rows if r["tol"] == tight):
            ax.annotate(f"{r['nr']}×{r['nt']}", (r["cpu"], max(relative_error(r[key], ref[key]), 1e-16)),
                        textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_xlabel("CPU time of the state (s)")
        ax.set_ylabel("relative error")
        ax.set_title(f"{label} (observed order {order[key]:.2f})")
        ax.grid(True, which="both", alpha=0.3)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("One state, 545 rad/s, 150 N, from the cold start: error against the mesh-converged value")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)

    print(f"Reference: Richardson from the two finest meshes at tolerance {tight:g}:")
    print(", ".join(f"{label} = {ref[key]:.6g} (observed order {order[key]:.2f})" for key, label in QUANTITIES))
    print()
    print("| mesh | unknowns | CPU s | f_eff | h_min/σ | T_mean | fluid share |")
    print("|---|---|---|---|---|---|---|")
    for r in sorted((r for r in rows if r["tol"] == tight), key=lambda r: r["nr"]):
        errors = " | ".join(f"{100 * relative_error(r[key], ref[key]):.2g} %" for key, _ in QUANTITIES)
        print(f"| {r['nr']}×{r['nt']} | {r['unknowns']} | {r['cpu']:.3g} | {errors} |")
    print()
    paper = [r for r in rows if r["nr"] == 9 and r["nt"] == 66]
    if paper:
        base = min(paper, key=lambda r: r["tol"])
        print("On 9×66, by solver tolerance (change against the tightest; CPU s, Newton iterations):")
        print()
        print("| tolerance | CPU s | iterations | f_eff | h_min/σ | T_mean | fluid share |")
        print("|---|---|---|---|---|---|---|")
        for r in sorted(paper, key=lambda r: -r["tol"]):
            changes = " | ".join(f"{relative_error(r[key], base[key]):.1e}" for key, _ in QUANTITIES)
            print(f"| {r['tol']:g} | {r['cpu']:.3g} | {r['newton_iterations']} | {changes} |")
    if len(sys.argv) == 5:
        print()
        distress(sys.argv[3], sys.argv[4])


if __name__ == "__main__":
    main()
