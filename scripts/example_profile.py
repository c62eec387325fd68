#!/usr/bin/python3
"""Writes configs/profiles/ground_steel_combined.csv, the example roughness profile.

It is synthetic, not measured: a Gaussian random profile with a band-limited power-law
spectrum (wavelengths 6 to 100 um, PSD ~ k^-3.5), scaled to the paper's combined Rq
(sqrt(2) x 0.515 um), sampled every 0.5 um over 4 mm. Its McCool estimate (docs/physics.md
section 13) lies near the model's default summits: R about 21 um, eta R sigma_s about
0.055, bandwidth alpha about 8. The seed is fixed, so the file is reproducible:
    /usr/bin/python3 scripts/example_profile.py
"""
import pathlib

import numpy as np

SAMPLES = 8192
SPACING = 0.5e-6                     # m
SHORTEST, LONGEST = 6e-6, 100e-6     # m, the band's wavelengths
SLOPE = 3.5                          # PSD ~ k^-SLOPE inside the band
RQ = 2**0.5 * 0.515e-6               # m, combined Rq of the paper's two faces


def profile(seed=2006):
    rng = np.random.default_rng(seed)
    k = 2 * np.pi * np.fft.rfftfreq(SAMPLES, SPACING)
    band = (k >= 2 * np.pi / LONGEST) & (k <= 2 * np.pi / SHORTEST)
    amplitude = np.zeros_like(k)
    amplitude[band] = k[band] ** (-SLOPE / 2)
    spectrum = amplitude * (rng.normal(size=k.size) + 1j * rng.normal(size=k.size))
    z = np.fft.irfft(spectrum, SAMPLES)
    return z * RQ / z.std()


def main():
    z = profile()
    out = pathlib.Path(__file__).resolve().parent.parent / "configs" / "profiles" / "ground_steel_combined.csv"
    lines = [
        "# Example roughness profile of the combined surface of a film (twb, docs/physics.md section 13).",
        "# SYNTHETIC, not measured: written by scripts/example_profile.py (Gaussian, band 6-100 um,",
        f"# PSD ~ k^-{SLOPE}, Rq {RQ * 1e6:.3f} um, {SAMPLES} heights every {SPACING * 1e6} um, no filter).",
        "x [um], z [um]",
    ]
    lines += [f"{i * SPACING * 1e6:.1f}, {h * 1e6:.5f}" for i, h in enumerate(z)]
    out.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
