#!/usr/bin/python3
"""Requirement (issue 24): -wave_start harmonic begins the waves in the steady response of
the linearized specimen. A free, damped square (loss factor 0.05: transients' amplitudes decay as
exp(-alpha t / 2), by 8e-5 in 60 periods) driven by a traction at 100 kHz:
  - started harmonic, the motion repeats from the first period on (two probes, both
    components: within 5e-3 of the amplitude period to period), where the same scene
    started at rest is still 5 % or more away from periodic;
  - it is the state the rest start reaches after its transients: against the rest start
    60 periods later (same phase), within 5e-3 of the amplitude (the frequency-domain solve
    against velocity Verlet's own steady state: 1.9e-3 at the default step, 2.7e-4 at a
    third of it, second order), each without its mean
    over the periods compared (a free body keeps the rigid offset its switch-on left);
  - the energy budget closes (the initial energy is booked as the source's work);
  - (issue 26) the same in 3D: a free 20 x 20 x 10 mm box driven on its top face, with an
    open (traction-free) buried crack, the same checks and tolerances; the run prints MUMPS's
    estimate of its factorisation's memory and refuses one above -wave_harmonic_memory_limit.
  - (issue 40) -wave_harmonic_solver krylov (GMRES, multigrid on each part), and the default
    auto once the factor is over the limit, give the direct solve's state (2D and 3D: the
    probes' motion over 5 periods within 1e-6 of the amplitude; GMRES stops at 1e-8).

usage: test_harmonic_start.py VIBROTHERM"""
import os, re, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, one_line_error, run_scene, outputs

exe = sys.argv[1]
check = Checks("harmonic start")
P = 1e-5
scene = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.002", "-wave_degree", "2",
         "-edge_top", "source", "-edge_bottom", "free", "-edge_left", "free", "-edge_right", "free",
         "-source_type", "traction", "-source_amplitude", "1e6", "-source_frequency", "1e5", "-source_duration", "1e-3",
         "-heat", "off", "-material_loss_factor", "0.05", "-probe_points", "0.01,0.005,0.003,0.015", "-probe_every", "1"]


def probes(out):
    a = outputs(out).columns("probes.csv")
    return [(a["t"][a["probe"] == p], np.c_[a["ux"][a["probe"] == p], a["uy"][a["probe"] == p]]) for p in (0, 1)]


def shifted(t, u, shift, at):
    """u at the times at + shift, interpolated per component."""
    return np.c_[np.interp(at + shift, t, u[:, 0]), np.interp(at + shift, t, u[:, 1])]


def not_periodic(trace, periods=4):
    """Largest change of the motion from one period to the next over the first periods, of its amplitude."""
    t, u = trace
    early = t <= periods * P
    return np.abs(shifted(t, u, P, t[early]) - u[early]).max() / np.abs(u).max()


# A 3D box holds one crack: an open one (traction-free, so the problem stays linear).
BOX = ["-specimen_depth", "0.01", "-edge_front", "free", "-edge_back", "free", "-crack_center", "0.01,0.01,0.005",
       "-crack_length", "0.006", "-crack_width", "0.004", "-crack_angle", "20", "-mesh_h", "0.004", "-mesh_h_crack", "0.002",
       "-crack_law", "open", "-probe_points", "0.01,0.005,0.005,0.003,0.015,0.002"]


def compare(tmp, name, args):
    harmonic, rest = os.path.join(tmp, name + "_harmonic"), os.path.join(tmp, name + "_rest")
    ok = run_scene(check, exe, args + ["-wave_start", "harmonic", "-final_time", repr(5 * P)], harmonic)
    ok = run_scene(check, exe, args + ["-final_time", repr(65 * P)], rest) and ok
    if ok:
        for p, (h, r) in enumerate(zip(probes(harmonic), probes(rest))):
            amplitude = np.abs(h[1]).max()
            whole = h[0] <= 5 * P * (1 - 1e-9)  # whole periods: their mean is the rigid offset
            ours, theirs = h[1][whole], shifted(r[0], r[1], 60 * P, h[0][whole])
            late = np.abs((theirs - theirs.mean(axis=0)) - (ours - ours.mean(axis=0))).max() / amplitude
            print("%s, probe %d: period to period, harmonic start %.2e, rest start %.2e; against the rest start 60 "
                  "periods on %.2e of the amplitude" % (name, p, not_periodic(h), not_periodic(r), late))
            check(not_periodic(h) < 5e-3, "%s, probe %d: the harmonic start repeats from the first period" % (name, p))
            check(not_periodic(r) > 5e-2, "%s, probe %d: the rest start does not (the test can tell)" % (name, p))
            check(late < 5e-3, "%s, probe %d: the harmonic start is the steady state the rest start reaches" % (name, p))
        s = outputs(harmonic).summary
        check(s["max_budget_error"] < 1e-5, "%s, harmonic start: budget error %g" % (name, s["max_budget_error"]))


def iterative(tmp, name, args, extra):
    """The harmonic start by GMRES (extra selects it) against the direct one compare() ran."""
    out, direct = os.path.join(tmp, name + "_krylov"), os.path.join(tmp, name + "_harmonic")
    r = subprocess.run([exe] + args + ["-wave_start", "harmonic", "-final_time", repr(5 * P), "-output_dir", out] + extra,
                       capture_output=True, text=True)
    converged = re.search(r"gmres converged in (\d+) iterations", r.stdout)
    check(r.returncode == 0 and converged is not None, "%s: the GMRES start runs and says it converged: %s"
          % (name, (r.stdout + r.stderr)[-600:]))
    if r.returncode != 0 or not os.path.exists(os.path.join(direct, "probes.csv")):
        return
    for p, (k, d) in enumerate(zip(probes(out), probes(direct))):
        error = np.abs(k[1] - d[1]).max() / np.abs(d[1]).max()
        print("%s, probe %d: GMRES (%s iterations) against MUMPS %.2e of the amplitude" % (name, p, converged.group(1), error))
        check(error < 1e-6, "%s, probe %d: the GMRES start is the direct start's state" % (name, p))


def memory_guard(tmp):
    """The 3D harmonic start prints MUMPS's estimate of its factorisation and refuses, naming
    -wave_harmonic_memory_limit, one above that limit (nothing factored, nothing written)."""
    out = os.path.join(tmp, "limit")
    r = subprocess.run([exe] + scene + BOX + ["-wave_start", "harmonic", "-final_time", repr(P),
                                              "-wave_harmonic_solver", "direct",
                                              "-wave_harmonic_memory_limit", "1e-6", "-output_dir", out],
                       capture_output=True, text=True)
    estimate = re.search(r"Harmonic start: MUMPS estimates (\S+) GB", r.stdout)
    check(estimate is not None and float(estimate.group(1)) > 0, "the estimate is printed: %s" % r.stdout[-600:])
    one_line_error(check, "-wave_harmonic_memory_limit 1e-6", r.returncode, r.stderr, "-wave_harmonic_memory_limit",
                   "MUMPS")


with tempfile.TemporaryDirectory() as tmp:
    compare(tmp, "2D", scene)
    compare(tmp, "3D", scene + BOX)
    memory_guard(tmp)
    iterative(tmp, "2D", scene, ["-wave_harmonic_solver", "krylov"])
    iterative(tmp, "3D", scene + BOX, ["-wave_harmonic_memory_limit", "1e-6"])  # auto: over the limit, GMRES
check.finish()
