#!/usr/bin/python3
"""Requirement: a pre-compressed clapping crack (quadratic normal law, no
friction) makes a second harmonic in the transmitted wave that grows as the
amplitude squared at small amplitude: log-log slope 2 +- 0.2 over a decade.

The second harmonic is taken from the even part (u(A) + u(-A)) / 2 of two runs
with opposite source signs: every linear response, including the window's
spectral leakage, is odd in A and cancels; the contact nonlinearity remains.

usage: test_clapping_harmonics.py VIBROTHERM"""
import math, os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe = sys.argv[1]
check = Checks("clapping harmonics")
f, cycles, H, y_crack, y_probe = 1e6, 14, 0.05, 0.03, 0.02
cp = math.sqrt((70e9 * 0.33 / (1.33 * 0.34) + 70e9 / 1.33) / 2700.0)
h = cp / f / 25.0
harmonic2 = {}


def transmitted(tmp, A):
    """(t, u_y) at the probe below the crack for source amplitude A."""
    out = os.path.join(tmp, "A%g" % A)
    t_in = (H - y_probe) / cp
    args = [exe, "-specimen_width", "%.17g" % (10 * h), "-specimen_height", "%g" % H, "-mesh_h", "%.17g" % h,
            "-mesh_h_crack", "%.17g" % h, "-crack_center", "%.17g,%.17g" % (5 * h, y_crack), "-crack_length",
            "%.17g" % (10 * h), "-crack_angle", "0", "-crack_law", "clapping", "-crack_a0", "1e-8", "-edge_left",
            "roller", "-edge_right", "roller", "-source_component", "normal", "-source_frequency", "%g" % f,
            "-source_amplitude", "%g" % A, "-source_duration", "%g" % (cycles / f), "-source_ramp_cycles", "2",
            "-final_time", "%g" % (t_in + cycles / f), "-probe_points", "%.17g,%g" % (5 * h, y_probe),
            "-crack_state_every", "0", "-wave_degree", "1", "-output_dir", out,
            # One step for both signs: the linear response cancels in the even part
            # only on the same time grid (the default step follows the contact).
            "-wave_contact_step", "worst_case"]
    r = subprocess.run(args, capture_output=True, text=True)
    check(r.returncode == 0, "A = %g: %s" % (A, r.stderr[-1500:]))
    if r.returncode:
        return None
    rows = outputs(out).rows("probes.csv")
    return np.array([float(x["t"]) for x in rows]), np.array([float(x["uy"]) for x in rows])


with tempfile.TemporaryDirectory() as tmp:
    for A in (1e-11, 3e-11, 1e-10):
        plus, minus = transmitted(tmp, A), transmitted(tmp, -A)
        if plus is None or minus is None:
            continue
        t, even, odd = plus[0], 0.5 * (plus[1] + minus[1]), 0.5 * (plus[1] - minus[1])
        # Plateau of the transmitted burst: a whole number of cycles after the ramp.
        t0 = (H - y_probe) / cp + 3 / f
        window = (t >= t0) & (t < t0 + 8 / f)

        def amplitude(u, freq):
            return 2 * abs(np.sum(u[window] * np.exp(-2j * math.pi * freq * t[window]))) / window.sum()

        harmonic2[A] = (amplitude(odd, f), amplitude(even, 2 * f))
        print("A = %g: H1 = %.4g, H2 = %.4g" % (A, harmonic2[A][0], harmonic2[A][1]))

if len(harmonic2) == 3:
    amps = sorted(harmonic2)
    slope = math.log(harmonic2[amps[-1]][1] / harmonic2[amps[0]][1]) / math.log(amps[-1] / amps[0])
    slope1 = math.log(harmonic2[amps[-1]][0] / harmonic2[amps[0]][0]) / math.log(amps[-1] / amps[0])
    print("slope of H2: %.3f, of H1: %.3f" % (slope, slope1))
    check(abs(slope - 2.0) <= 0.2, "second harmonic slope %.3f (expected 2 +- 0.2)" % slope)
    check(abs(slope1 - 1.0) <= 0.05, "fundamental slope %.3f (expected 1)" % slope1)
    check(harmonic2[amps[-1]][1] > 1e-4 * harmonic2[amps[-1]][0], "the second harmonic is measurable")
check.finish()
