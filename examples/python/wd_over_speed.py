#!/usr/bin/env python3
"""Where does the washer fail, speed by speed? Maps the distress load W_d of the paper's
bearing over sliding speed with the twb module and plots it with its Richardson error
bar (the fold found again on the mesh refined by two).

    PYTHONPATH=build/python python3 examples/python/wd_over_speed.py --out wd_over_speed.png

Options: --speeds 200,600,1000,1400 (rad/s), --mesh 9x66 (radial x circumferential
nodes), --threads N (0: one per core), --scene FILE.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import twb  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENE = os.path.join(HERE, "..", "..", "configs", "jackson_green_2006.yaml")


def distress_over_speed(scene, speeds, mesh, threads, progress=None):
    """One distress map over `speeds`: the distress table (W_d_N, W_d_extrapolated_N,
    W_d_error_N per speed) as numpy arrays."""
    radial, circumferential = mesh
    result = twb.run(scene, overrides={
        "study": {"type": "distress_map", "speeds": [f"{s} rad/s" for s in speeds],
                  "load_start": "50 N", "load_end": "2000 N"},
        "mesh.radial_nodes": radial, "mesh.circumferential_nodes": circumferential,
    }, progress=progress, threads=threads)
    if result.solver_failed:
        raise twb.SolverFailure(result.message)
    return result.distress


def plot(distress, out):
    speed = distress["speed_rad_s"]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(speed, distress["W_d_N"], "o-", label="W_d on the scene's mesh")
    extrapolated = distress["W_d_extrapolated_N"]
    if not np.all(np.isnan(extrapolated)):
        ax.errorbar(speed, extrapolated, yerr=distress["W_d_error_N"], fmt="s--", capsize=3,
                    label="mesh-converged (Richardson) ± error")
    ax.set_xlabel("sliding speed (rad/s)")
    ax.set_ylabel("distress load W_d (N)")
    ax.set_title("Where the oil film fails: W_d over speed")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--scene", default=DEFAULT_SCENE)
    p.add_argument("--speeds", default="200,400,600,800,1000,1200,1400")
    p.add_argument("--mesh", default="9x66")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--out", default="wd_over_speed.png")
    p.add_argument("-q", "--quiet", action="store_true")
    a = p.parse_args(argv)
    speeds = [float(s) for s in a.speeds.split(",")]
    mesh = tuple(int(n) for n in a.mesh.lower().split("x"))
    try:
        distress = distress_over_speed(a.scene, speeds, mesh, a.threads,
                                       progress=None if a.quiet else lambda line: print(line, file=sys.stderr))
    except twb.SceneError as e:
        print(e, file=sys.stderr)
        return 2
    for s, w, e, how in zip(distress["speed_rad_s"], distress["W_d_N"], distress["W_d_error_N"],
                            distress["method"]):
        if np.isnan(w):  # no sudden distress at this speed: the method column says what was found
            print(f"{s:8.1f} rad/s   no W_d: {how}")
        else:
            print(f"{s:8.1f} rad/s   W_d = {w:8.2f} N" + ("" if np.isnan(e) else f"   (± {e:.2f} N)"))
    plot(distress, a.out)
    print(f"figure: {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
