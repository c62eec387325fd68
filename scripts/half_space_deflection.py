#!/usr/bin/env python3
"""How far the thick bodies (carrier, gear) deflect under a state's film pressures, as
elastic half-spaces (docs/physics.md section 21, "The thick bodies"): Boussinesq's
u(x) = (1 − ν²)/(π·E)·∫ p(x')/|x − x'| dA' over each film's nodes, each node's pressure
(fluid and contact) over its control volume, its own volume's part by the closed form of a
uniformly loaded rectangle at its centre. Prints, per film, the deflection's mean, range
and largest departure from a plane (a plane only moves and tilts the body, which the
rigid unknowns take up), against the film's least gap.

    half_space_deflection.py FIELDS_CSV [--modulus PA] [--poisson NU]

FIELDS_CSV: a state's fields (twb run with output.fields: true: DIR/fields/state_NNNN.csv).
Exit status 0; 1 where the file is missing or malformed.
"""

import argparse
import csv
import math
import sys

import numpy as np


def deflection(rows, modulus, poisson):
    r = np.array([float(x["r_m"]) for x in rows])
    theta = np.array([float(x["theta_rad"]) for x in rows])
    p = np.array([float(x["p_Pa"]) + float(x["p_contact_Pa"]) for x in rows])
    h = np.array([float(x["h_m"]) for x in rows])
    radii = np.unique(r)
    dr, dtheta = radii[1] - radii[0], 2.0 * math.pi / np.unique(theta).size
    lo, hi = np.maximum(radii[0], r - dr / 2), np.minimum(radii[-1], r + dr / 2)
    area = 0.5 * (hi ** 2 - lo ** 2) * dtheta
    x, y = r * np.cos(theta), r * np.sin(theta)
    distance = np.hypot(x[:, None] - x[None, :], y[:, None] - y[None, :])
    np.fill_diagonal(distance, 1.0)
    kernel = area[None, :] / distance
    # a uniformly loaded a × b rectangle at its centre: a·ln((b + c)/a) + b·ln((a + c)/b)
    a, b = hi - lo, r * dtheta
    c = np.sqrt(a * a + b * b)
    np.fill_diagonal(kernel, a * np.log((b + c) / a) + b * np.log((a + c) / b))
    u = (1.0 - poisson ** 2) / (math.pi * modulus) * kernel.dot(p)
    plane = np.vstack([np.ones_like(x), x, y]).T
    fit, *_ = np.linalg.lstsq(plane, u, rcond=None)
    return float(np.sum(p * area)), u, float(np.abs(u - plane.dot(fit)).max()), float(h.min())


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fields")
    parser.add_argument("--modulus", type=float, default=2.0e11, help="the thick body's Young's modulus (Pa)")
    parser.add_argument("--poisson", type=float, default=0.3, help="its Poisson's ratio")
    args = parser.parse_args(argv[1:])
    try:
        with open(args.fields, newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        for film in sorted({x["film"] for x in rows}):
            load, u, beyond, least = deflection([x for x in rows if x["film"] == film], args.modulus, args.poisson)
            print(f"film {film}: {load:.1f} N; deflection mean {1e6 * u.mean():.4f} um, range "
                  f"{1e6 * (u.max() - u.min()):.4f} um, beyond a plane {1e6 * beyond:.4f} um "
                  f"({100 * beyond / least:.2g} % of the least gap, {1e6 * least:.3f} um)")
    except (OSError, KeyError, ValueError, IndexError) as error:
        print(f"half_space_deflection.py: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
