#!/usr/bin/python3
"""Requirement (issue 38): -modes_crack contact adds the crack's contact linearised at its initial
state (as the harmonic start) to the modes, so a pre-closed crack's modes are those its small
vibrations resonate at. Checked by its limits on the LDR plate (a 2 mm layer over a 30 mm
delamination, options/ldr_delamination.opts' geometry) with the linear crack law of stiffness k:
  - k = 1 Pa/m: the open crack's modes (the default, -modes_crack open), to 1e-6;
  - k = 1e17 Pa/m: the intact plate's modes (the same specimen without a crack), to 3e-3 (the
    meshes differ: the cracked one is graded to the crack);
  - k = 1e10 Pa/m: the LDR rides on the springs: above the open LDR, below the intact plate's
    nearest mode, and the thin-plate estimate f² ≈ f_open² + k / (4π² ρ h) within 15 %.

usage: test_modes_contact.py VIBROTHERM"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe = sys.argv[1]
check = Checks("modes with the crack's contact")
PLATE = ("-specimen_width 0.1 -specimen_height 0.01 -mesh_h 0.003 -mesh_h_crack 0.0007 -mesh_cell quad "
         "-edge_top free -edge_bottom free -edge_left free -edge_right free -material_density 2700 "
         "-material_E 70e9 -material_nu 0.33 -modes -modes_n 8 -modes_target_frequency 12000").split()
CRACK = "-crack_center 0.05,0.008 -crack_length 0.03 -crack_angle 0 -modes_defect_radius 0.004".split()


def modes(tmp, name, extra):
    out = os.path.join(tmp, name)
    r = subprocess.run([exe] + PLATE + extra + ["-output_dir", out], capture_output=True, text=True)
    check(r.returncode == 0, "%s: %s" % (name, r.stderr[-800:]))
    if r.returncode != 0:
        return []
    rows = [(float(row["frequency"]), float(row["participation"] or "nan")) for row in outputs(out).rows("modes.csv")]
    return [(f, p) for f, p in rows if f > 100.0]


def linear(k):
    return CRACK + ["-crack_law", "linear", "-crack_linear_kn", repr(k), "-crack_linear_kt", repr(k),
                    "-modes_crack", "contact"]


with tempfile.TemporaryDirectory() as tmp:
    opened = modes(tmp, "open", CRACK)
    soft = modes(tmp, "soft", linear(1.0))
    stiff = modes(tmp, "stiff", linear(1e17))
    intact = modes(tmp, "intact", [])
    springs = modes(tmp, "springs", linear(1e10))
    if opened and soft and stiff and intact and springs:
        check(max(abs(a[0] / b[0] - 1) for a, b in zip(soft, opened)) < 1e-6, "k = 1 Pa/m: the open crack's modes")
        worst = max(abs(a[0] / b[0] - 1) for a, b in zip(stiff[:5], intact[:5]))
        check(worst < 3e-3, "k = 1e17 Pa/m: the intact plate's modes (%.2g)" % worst)
        ldr = max(opened, key=lambda m: m[1])[0]
        lifted = max(springs, key=lambda m: m[1])[0]
        estimate = math.sqrt(ldr ** 2 + 1e10 / (4 * math.pi ** 2 * 2700 * 0.002))
        print("LDR: open %.1f Hz, on 1e10 Pa/m springs %.1f Hz (estimate %.1f Hz)" % (ldr, lifted, estimate))
        check(ldr < lifted, "the springs lift the LDR (%.1f -> %.1f Hz)" % (ldr, lifted))
        check(abs(lifted / estimate - 1) < 0.15, "the spring-supported layer's estimate (%.3g)" % (lifted / estimate))
check.finish()
