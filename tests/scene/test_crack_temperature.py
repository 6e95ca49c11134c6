#!/usr/bin/python3
"""Requirement: the temperature at the crack is converged where it is made. A short
run of the paper scene (waves, MMD contact, heat on its own graded mesh) gives a
crack-centre rise within 1 % of the continuum temperature of the friction power it
exchanged (crack_heat.h5 convolved with the heat kernel of the infinite plate,
scripts/lib/line_source.py, no mesh) at every output time ≥ 0.1 ms, serial and on 2
ranks; crack_heat.h5 holds exactly the energy the interface dissipated; 2 ranks = serial.
The reference itself is first checked against Carslaw & Jaeger's finite line source.

usage: test_crack_temperature.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import math, os, subprocess, sys, tempfile

import numpy as np
from scipy.integrate import quad

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe, src, mpiexec = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "scripts", "lib"))
import line_source  # noqa: E402

check = Checks("crack temperature")
rho_c, alpha = 2700 * 900.0, 237 / (2700 * 900.0)
centre = (0.025, 0.05)
times = [5e-5, 1e-4, 1.3e-4]


def reference_check():
    """A uniform, constant q on a straight crack: Carslaw & Jaeger at its centre."""
    q, L, t = 1e6, 0.004, 3e-4
    rec = line_source.CrackHeat.__new__(line_source.CrackHeat)
    rec.t_end = np.linspace(t / 7, t, 7)
    rec.t_start = np.concatenate([[0.0], rec.t_end[:-1]])
    rec.vertices = np.array([[0, 0.0, 0.0, 0.0], [0, 0.5, L / 2, 0.0], [0, 1.0, L, 0.0]])
    rec.elements = np.array([[0, 0.0, 0.5, L / 2, 2, 0, 1, 3], [0, 0.5, 1.0, L / 2, 2, 1, 2, 4]])
    rec.density = np.full((7, 5), q)
    exact = q / rho_c * quad(lambda s: math.erf(L / (4 * math.sqrt(alpha * s))) / math.sqrt(4 * math.pi * alpha * s),
                             0, t, limit=200)[0]
    got = line_source.temperature_rise(rec, (L / 2, 0.0), t, alpha, rho_c)
    check(abs(got / exact - 1) < 1e-6, "line-source reference %.8g vs Carslaw-Jaeger %.8g" % (got, exact))
    print("reference vs Carslaw-Jaeger: %.2e" % (got / exact - 1))


def run(tmp, ranks):
    out = os.path.join(tmp, "np%d" % ranks)
    cmd = [mpiexec, "-n", str(ranks), "--oversubscribe", exe, "-options_file", os.path.join(src, "options/paper.opts"),
           "-final_time", str(times[-1]), "-output_times", ",".join(map(str, times)), "-crack_state_every", "0",
           "-output_dir", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == 0, "run on %d ranks: %s" % (ranks, r.stderr[-2000:]))
    return out if r.returncode == 0 else None


def compare(out, ranks):
    summary = outputs(out).summary
    rec = line_source.CrackHeat(os.path.join(out, "crack_heat.h5"))
    # ∫ q ds over the crack is Σ w_c q_c: the weights are the elements' lumped basis integrals.
    weights = np.zeros(rec.density.shape[1])
    for e in rec.elements:
        ends = 0.5 if e[4] == 1 else 1 / 6
        for k, w in ((5, ends), (6, ends), (7, 4 / 6)):
            if e[k] >= 0 and (k < 7 or e[4] == 2):
                weights[int(e[k])] += w * e[3]
    energy = np.sum(rec.density @ weights * (rec.t_end - rec.t_start))
    check(abs(energy / summary["dissipated_energy"] - 1) < 1e-12,
          "%d ranks: crack_heat.h5 holds %.12g J/m, dissipated %.12g" % (ranks, energy, summary["dissipated_energy"]))
    probe = [k for k, v in summary["probe_labels"].items() if v.endswith("xi = 0.500000")][0]
    rises = {}
    for row in summary["output_temperature_rise"]:
        t, rise = row["t"], row[probe]
        ref = line_source.temperature_rise(rec, centre, t, alpha, rho_c)
        err = rise / ref - 1
        rises[t] = rise
        print("%d ranks: t = %.4g s  run %.6g K  continuum %.6g K  error %+.3f %%" % (ranks, t, rise, ref, 100 * err))
        if t >= 1e-4 * (1 - 1e-9):
            check(abs(err) <= 0.01, "%d ranks, t = %g: crack-centre rise off by %.2f %%" % (ranks, t, 100 * err))
    return rises


reference_check()
with tempfile.TemporaryDirectory() as tmp:
    results = {ranks: compare(out, ranks) for ranks in (1, 2) for out in [run(tmp, ranks)] if out}
    if len(results) == 2:
        for t, rise in results[1].items():
            other = results[2].get(t)
            check(other is not None and abs(other - rise) <= 1e-9 * abs(rise),
                  "t = %g: 2 ranks %r vs serial %r" % (t, other, rise))
check.finish()
