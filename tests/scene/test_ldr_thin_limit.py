#!/usr/bin/python3
"""Requirement (issue 38): the LDR scene's fundamental tends to thin-plate theory as the layer
thins. The layer over a delamination of length L, h under the face of a free plate
(options/ldr_delamination.opts' plate, its crack open: -modes), is a clamped-clamped beam:
f1 = 4.730²/(2π) (h/L²) √(E/(12ρ(1−ν²))). The mode of largest defect participation, for
h/L = 0.1, 0.05, 0.025 (L = 20 mm, crack cells h/3): its ratio to f1 rises toward 1 (a real
rim is not rigid: the layer's ends rotate, a correction of order h/L), the thinnest within
5 % of it, each above 0.75: the mode of largest defect participation between 0.6 and 1.1 f1
(above 0.8: the layer, not a plate mode beside it; a plate mode near it shares its
participation, as at h/L = 0.025: 0.86 and 0.69).

usage: test_ldr_thin_limit.py VIBROTHERM SOURCE_DIR"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe, src = sys.argv[1:3]
check = Checks("LDR thin-plate limit")
E, nu, rho, L = 70e9, 0.33, 2700.0, 0.02
ratios = []
with tempfile.TemporaryDirectory() as tmp:
    for h in (0.002, 0.001, 0.0005):
        f1 = 4.730 ** 2 / (2 * math.pi) * h / L ** 2 * math.sqrt(E / (12 * rho * (1 - nu ** 2)))
        out = os.path.join(tmp, "h%g" % h)
        args = [exe, "-options_file", os.path.join(src, "options/ldr_delamination.opts"), "-modes", "-modes_n", "6",
                "-modes_target_frequency", repr(f1), "-crack_length", repr(L), "-crack_center", "0.05,%r" % (0.01 - h),
                "-mesh_h_crack", repr(h / 3), "-modes_defect_radius", repr(L / 2), "-output_dir", out]
        r = subprocess.run(args, capture_output=True, text=True)
        check(r.returncode == 0, "h = %g: %s" % (h, r.stderr[-600:]))
        if r.returncode != 0:
            continue
        rows = [(float(m["frequency"]), float(m["participation"] or "nan")) for m in outputs(out).rows("modes.csv")]
        near = [m for m in rows if 0.6 * f1 < m[0] < 1.1 * f1 and not math.isnan(m[1])]
        if not near:
            check.fail("h = %g: no mode between 0.6 and 1.1 f1 = %.0f Hz: %s" % (h, f1, rows))
            continue
        f, share = max(near, key=lambda m: m[1])  # the layer's fundamental, not the plate's modes beside it
        ratios.append(f / f1)
        print("h/L = %.4f: LDR %.1f Hz = %.4f of the clamped beam's %.1f Hz (participation %.3f)" % (
            h / L, f, f / f1, f1, share))
        check(share > 0.8 and f / f1 > 0.75, "h/L = %g: the layer's mode (participation %.3f, %.3f f1)" % (
            h / L, share, f / f1))
    check(len(ratios) == 3 and ratios[0] < ratios[1] < ratios[2] < 1.01, "tends to the beam: %s" % ratios)
    check(len(ratios) == 3 and abs(ratios[2] - 1) < 0.05, "the thinnest within 5 %% (%.4f)" % ratios[-1])
check.finish()
