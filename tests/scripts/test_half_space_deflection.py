"""scripts/half_space_deflection.py: the thick bodies' deflection under a state's film pressures.

    MPLBACKEND=Agg /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import importlib.util
import math
import os
import subprocess
import sys
import tempfile
import unittest

from result_files import write

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "half_space_deflection.py")
HEADER = "film,sliding,r_m,theta_rad,h_m,p_Pa,p_contact_Pa,T_film_C,T_surfaces_C,viscosity_Pa_s\n"


def load_script():
    spec = importlib.util.spec_from_file_location("half_space_deflection", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def annulus_rows(pressure, nr=9, nt=48, inner=5e-3, outer=10e-3):
    rows = []
    for i in range(nr):
        r = inner + i * (outer - inner) / (nr - 1)
        for j in range(nt):
            theta = 2 * math.pi * j / nt
            rows.append({"film": "1", "r_m": str(r), "theta_rad": str(theta), "h_m": "1e-6",
                         "p_Pa": str(pressure(r, theta)), "p_contact_Pa": "0"})
    return rows


class HalfSpaceDeflection(unittest.TestCase):
    def test_a_uniform_pressure_presses_the_annulus_axisymmetrically_and_linearly(self):
        """Boussinesq's deflection is linear in the pressure and in 1/E; a uniform pressure on
        an annulus deflects it the same round each radius, so that nothing of it lies beyond
        a plane but its radial shape, and its load is p times the annulus's area."""
        hsd = load_script()
        rows = annulus_rows(lambda r, t: 1e6)
        load, u, beyond, least = hsd.deflection(rows, 2e11, 0.3)
        self.assertAlmostEqual(load, 1e6 * math.pi * (10e-3 ** 2 - 5e-3 ** 2), delta=1e-9 * load)
        _, u2, beyond2, _ = hsd.deflection(annulus_rows(lambda r, t: 2e6), 1e11, 0.3)
        for a, b in zip(u, u2):
            self.assertAlmostEqual(b, 4 * a, delta=1e-12 * abs(a))
        # (the same at every angle of a radius: the plane fit keeps its mean tilt at zero)
        by_radius = {}
        for row, v in zip(rows, u):
            by_radius.setdefault(row["r_m"], []).append(v)
        for values in by_radius.values():
            self.assertLess(max(values) - min(values), 1e-9 * max(values))
        self.assertEqual(least, 1e-6)

    def test_a_missing_file_is_an_error(self):
        result = subprocess.run([sys.executable, SCRIPT, "/no/such/fields.csv"], capture_output=True, text=True)
        self.assertEqual(result.returncode, 1)
        self.assertIn("half_space_deflection.py", result.stderr)

    def test_it_prints_each_film(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "state.csv")
            lines = [HEADER] + [f"{x['film']},1,{x['r_m']},{x['theta_rad']},1e-6,{x['p_Pa']},0,30,30,0.03\n"
                                for x in annulus_rows(lambda r, t: 1e6 * (1 + math.cos(t)))]
            write(path, "".join(lines))
            result = subprocess.run([sys.executable, SCRIPT, path], capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("film 1:", result.stdout)
            self.assertIn("beyond a plane", result.stdout)


if __name__ == "__main__":
    unittest.main()
