#!/usr/bin/python3
"""Requirement: `vibrotherm -modes` finds the specimen's natural frequencies. Checked
against closed forms: a plate with roller (sliding) edges on all sides has the modes
f = c/2 · sqrt((m/W)² + (n/H)²) with c = c_P (m + n ≥ 1) and c = c_S (m, n ≥ 1):
the lowest 10 within 1 % for Q1 and 0.1 % for Q2; a free plate with H = 2W has
Lamé's pure-shear mode f = c_S / (√2 W) (0.1 %, Q2). 2 ranks give the serial
frequencies; the defect participation is a share in [0, 1] that reaches 1 when the
radius covers the specimen; modes.csv, modes.h5 and modes.xmf are written.

usage: test_modes.py VIBROTHERM MPIEXEC"""
import math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe, mpiexec = sys.argv[1], sys.argv[2]
check = Checks("modes")
W, H, E, nu, rho = 0.05, 0.1, 70e9, 0.33, 2700.0
lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
cp, cs = math.sqrt((lam + 2 * G) / rho), math.sqrt(G / rho)
plate = ("-specimen_width %g -specimen_height %g -mesh_h 0.002 -mesh_cell quad -material_E %g -material_nu %g "
         "-material_density %g -modes -wave_degree 1" % (W, H, E, nu, rho)).split()
rollers = "-edge_top roller -edge_bottom roller -edge_left roller -edge_right roller".split()


def roller_frequencies(count):
    f = []
    for m in range(8):
        for n in range(8):
            k = math.hypot(m / W, n / H) / 2
            if m + n >= 1:
                f.append(cp * k)
            if m >= 1 and n >= 1:
                f.append(cs * k)
    return sorted(f)[:count]


def run(tmp, name, extra, ranks=1):
    out = os.path.join(tmp, name)
    command = ([mpiexec, "-n", str(ranks), "--oversubscribe"] if ranks > 1 else []) + [exe] + plate + extra
    r = subprocess.run(command + ["-output_dir", out], capture_output=True, text=True)
    check(r.returncode == 0, "%s: exit %d: %s" % (name, r.returncode, r.stderr[-1500:]))
    if r.returncode:
        return None, None
    rows = outputs(out).rows("modes.csv")
    return rows, out


with tempfile.TemporaryDirectory() as tmp:
    exact = roller_frequencies(10)
    for degree, tolerance in (("1", 1e-2), ("2", 1e-3)):
        rows, out = run(tmp, "roller_q" + degree, rollers + ["-wave_degree", degree, "-modes_n", "10",
                                                             "-modes_target_frequency", "1000"])
        if rows:
            found = [float(r["frequency"]) for r in rows]
            worst = max(abs(f / e - 1) for f, e in zip(found, exact))
            print("roller plate Q%s: worst relative error %.2e over %d modes" % (degree, worst, len(found)))
            check(len(found) == 10 and worst < tolerance,
                  "roller plate Q%s: %s vs exact %s (worst %.2e)" % (degree, found, exact, worst))
            check(all(float(r["error"]) < 1e-8 for r in rows), "roller plate Q%s: SLEPc residuals" % degree)
            for name in ("modes.h5", "modes.xmf", "summary.json"):
                check(os.path.exists(os.path.join(out, name)), "roller plate Q%s: %s missing" % (degree, name))
            summary = outputs(out).summary
            check(summary["physics_ran"] == ["modes"] and len(summary["modes"]) == 10,
                  "roller plate: summary.json physics_ran/modes")
    # Two ranks: the same frequencies.
    serial, _ = run(tmp, "serial", rollers + ["-modes_n", "6", "-modes_target_frequency", "5e4"])
    parallel, _ = run(tmp, "parallel", rollers + ["-modes_n", "6", "-modes_target_frequency", "5e4",
                                                  "-petscpartitioner_type", "simple"], ranks=2)
    if serial and parallel:
        worst = max(abs(float(a["frequency"]) / float(b["frequency"]) - 1) for a, b in zip(serial, parallel))
        check(len(serial) == len(parallel) and worst < 1e-9, "2 ranks vs serial: worst %.1e" % worst)
    # Free plate (absorbing edges are free for modes): Lamé's mode.
    lame = cs / (math.sqrt(2) * W)
    rows, _ = run(tmp, "free", ["-edge_top", "absorbing", "-wave_degree", "2", "-modes_n", "4",
                                "-modes_target_frequency", "%g" % lame])
    if rows:
        nearest = min((float(r["frequency"]) for r in rows), key=lambda f: abs(f - lame))
        print("free plate: Lamé mode %.2f Hz, exact %.2f Hz" % (nearest, lame))
        check(abs(nearest / lame - 1) < 1e-3, "free plate Lamé mode %.2f Hz vs %.2f Hz" % (nearest, lame))
    # Cracked specimen: participation is a share; a radius covering everything gives 1.
    crack = ["-crack_center", "0.025,0.05", "-crack_length", "0.02", "-crack_angle", "20", "-mesh_h_crack", "0.001",
             "-modes_n", "4", "-modes_target_frequency", "1e5"]
    for radius, expect_all in (("0.01", False), ("1", True)):
        rows, _ = run(tmp, "crack_r" + radius, crack + ["-modes_defect_radius", radius])
        if rows:
            shares = [float(r["participation"]) for r in rows]
            check(all(0 <= s <= 1 + 1e-12 for s in shares), "crack, radius %s: shares %s" % (radius, shares))
            if expect_all:
                check(all(abs(s - 1) < 1e-12 for s in shares), "crack, radius 1 m: shares %s, expected 1" % shares)
check.finish()
