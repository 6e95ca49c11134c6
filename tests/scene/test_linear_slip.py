#!/usr/bin/python3
"""Requirement: a crack across the whole width with Schoenberg's linear slip law
transmits a plane P and a plane S wave at normal incidence with amplitude
1/sqrt(1 + (omega Z / 2K)^2) (Z = rho c, K = traction per unit jump = k/2),
within 2 %, for omega Z / K = 0.3, 1 and 3 with linear elements, and for
omega Z / K = 1 with quadratic elements (mid-side node pairs of the crack).

usage: test_linear_slip.py VIBROTHERM"""
import math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe = sys.argv[1]
check = Checks("linear slip interface")
rho, E, nu = 2700.0, 70e9, 0.33
lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
speeds = {"P": math.sqrt((lam + 2 * G) / rho), "S": math.sqrt(G / rho)}
f, A, cycles, H, y_crack, y_probe = 1e6, 1e-9, 8, 0.06, 0.035, 0.025
omega = 2 * math.pi * f
with tempfile.TemporaryDirectory() as tmp:
    cases = [(wave, 1, ratio) for wave in speeds for ratio in (0.3, 1.0, 3.0)] + [(wave, 2, 1.0) for wave in speeds]
    for wave, degree, ratio in cases:
            c = speeds[wave]
            h = c / f / (30.0 / degree)  # 30 nodes per wavelength
            sides = "roller" if wave == "P" else "antisymmetric"
            K = omega * rho * c / ratio
            expected = 1.0 / math.sqrt(1.0 + (ratio / 2.0) ** 2)
            t_in = (H - y_probe) / c
            out = os.path.join(tmp, "%s%g_%d" % (wave, ratio, degree))
            args = [exe, "-specimen_width", "%.17g" % (20 * h), "-specimen_height", "%g" % H, "-mesh_h", "%g" % h,
                    "-mesh_h_crack", "%g" % h, "-crack_center", "%.17g,%.17g" % (10 * h, y_crack), "-crack_length",
                    "%.17g" % (20 * h), "-crack_angle", "0", "-crack_law", "linear", "-crack_linear_kn", "%g" % (2 * K),
                    "-crack_linear_kt", "%g" % (2 * K), "-edge_left", sides, "-edge_right", sides,
                    "-edge_bottom", "absorbing", "-source_component", "normal" if wave == "P" else "tangential",
                    "-source_frequency", "%g" % f, "-source_amplitude", "%g" % A, "-source_duration",
                    "%g" % (cycles / f), "-source_ramp_cycles", "2", "-final_time", "%g" % (t_in + cycles / f),
                    "-probe_points", "%.17g,%g" % (10 * h, y_probe), "-wave_degree", str(degree), "-output_dir", out]
            r = subprocess.run(args, capture_output=True, text=True)
            check(r.returncode == 0, "%s %g degree %d: %s" % (wave, ratio, degree, r.stderr[-1500:]))
            if r.returncode:
                continue
            col = "uy" if wave == "P" else "ux"
            rows = outputs(out).rows("probes.csv")
            # The plateau of the burst (after its 2-cycle ramp, before the ramp down).
            plateau = [abs(float(x[col])) for x in rows if t_in + 3 / f <= float(x["t"]) <= t_in + (cycles - 2) / f]
            measured = max(plateau) / A
            text = "%s wave, degree %d, omega Z/K = %g: transmission %.4f, Schoenberg %.4f" % (
                wave, degree, ratio, measured, expected)
            check(abs(measured - expected) <= 0.02 * expected, text)
            print(text)
check.finish()
