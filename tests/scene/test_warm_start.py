#!/usr/bin/python3
"""Requirement (issue 38): a run saves its steady wave state where the periodic continuation
suspends the waves (-periodic_save_state FILE), and another run of the scene at the same
frequency begins in it (-wave_start state -wave_start_state FILE), scaled to its own source
amplitude. The free, damped square of test_harmonic_start (loss factor 0.05, a traction at
100 kHz, no crack: linear, so the scaled state is exactly the steady state of the new drive):
  - a run at 1 MPa saves its state (harmonic start, continued once periodic);
  - a run at 2.5 MPa started in that state repeats from its first period (within 1e-3 of the
    amplitude period to period: the saved state is velocity Verlet's own steady state), and is
    the state a harmonic start at 2.5 MPa gives (within 5e-3 of the amplitude: the frequency-
    domain solve against Verlet's steady state, test_harmonic_start); a 1 MPa run from the same
    state, times 2.5, is it too (linear), and is itself 60 % off it (the test can tell);
  - its energy budget closes (the initial energy is booked as the source's work);
  - a clapping crack (options/ldr_delamination.opts on a coarse mesh, at the layer's LDR): a run at
    1.25x the saver's drive starts in its state with the crack's memory taken there, the way
    there no heat of this run (no friction energy at t = 0) and the budget closed as well as
    after a harmonic start (measured: 1.0e-3 and 9.5e-4 of the work; with the stuck springs'
    energy booked instead of the contact's, the full scene at 6 kHz was off by 0.92 at t = 0); on 2 ranks (the state
    read on another partition) its first 50 us of energies are the serial run's;
  - refused in one line naming the option: a state of another frequency, of another mesh, of
    another kind of source, a missing file, -wave_start state without its file, the file
    without -wave_start state.

usage: test_warm_start.py VIBROTHERM MPIEXEC"""
import os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, one_line_error, outputs, run_scene

exe, mpiexec = sys.argv[1], sys.argv[2]
check = Checks("warm start")
P = 1e-5
scene = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.002", "-wave_degree", "2",
         "-edge_top", "source", "-edge_bottom", "free", "-edge_left", "free", "-edge_right", "free",
         "-source_type", "traction", "-source_frequency", "1e5", "-source_duration", "1e-3",
         "-heat", "off", "-material_loss_factor", "0.05", "-probe_points", "0.01,0.005,0.003,0.015", "-probe_every", "1"]


def probes(out):
    a = outputs(out).columns("probes.csv")
    return [(a["t"][a["probe"] == p], np.c_[a["ux"][a["probe"] == p], a["uy"][a["probe"] == p]]) for p in (0, 1)]


def period_to_period(t, u, periods=4):
    """Largest change of the motion from one period to the next over the first periods, of its amplitude."""
    early = t <= periods * P
    later = np.c_[np.interp(t[early] + P, t, u[:, 0]), np.interp(t[early] + P, t, u[:, 1])]
    return np.abs(later - u[early]).max() / np.abs(u).max()


def without_mean(u):
    return u - u.mean(axis=0)  # a free body keeps a rigid offset, its mean over whole periods


def compare(tmp, state):
    warm, harmonic, unscaled = (os.path.join(tmp, name) for name in ("warm", "harmonic", "unscaled"))
    five = ["-final_time", repr(5 * P), "-source_amplitude", "2.5e6"]
    ok = run_scene(check, exe, scene + five + ["-wave_start", "state", "-wave_start_state", state], warm)
    ok = run_scene(check, exe, scene + five + ["-wave_start", "harmonic"], harmonic) and ok
    ok = run_scene(check, exe, scene + ["-final_time", repr(5 * P), "-source_amplitude", "1e6", "-wave_start", "state",
                                        "-wave_start_state", state], unscaled) and ok
    if not ok:
        return
    for p, (w, h, u) in enumerate(zip(probes(warm), probes(harmonic), probes(unscaled))):
        amplitude = np.abs(h[1]).max()
        whole = h[0] <= 5 * P * (1 - 1e-9)
        against = np.abs(without_mean(w[1][whole]) - without_mean(h[1][whole])).max() / amplitude
        off = np.abs(2.5 * without_mean(u[1][whole]) - without_mean(h[1][whole])).max() / amplitude
        same_drive = np.abs(without_mean(u[1][whole]) - without_mean(h[1][whole])).max() / amplitude
        print("probe %d: warm start period to period %.2e; against the harmonic start %.2e; the 1 MPa run from the "
              "same state x 2.5 %.2e, unscaled %.2e" % (p, period_to_period(*w), against, off, same_drive))
        check(period_to_period(*w) < 1e-3, "probe %d: the warm start repeats from its first period" % p)
        check(against < 5e-3, "probe %d: the warm start is the harmonic start's steady state" % p)
        check(off < 5e-3, "probe %d: linear: the state at 1 MPa is that at 2.5 MPa over 2.5" % p)
        check(same_drive > 0.3, "probe %d: the unscaled state is far from it (the test can tell)" % p)
    s = outputs(warm).summary
    check(s["max_budget_error"] < 1e-5, "warm start: budget error %g" % s["max_budget_error"])


def refusals(tmp, state):
    cases = [
        (["-wave_start", "state", "-wave_start_state", state, "-source_frequency", "1.01e5"],
         ["-wave_start_state", "-source_frequency"]),
        (["-wave_start", "state", "-wave_start_state", state, "-mesh_h", "0.004"], ["-wave_start_state", "mesh"]),
        (["-wave_start", "state", "-wave_start_state", state, "-source_type", "displacement",
          "-source_amplitude", "1e-8"], ["-wave_start_state", "-source_type"]),
        (["-wave_start", "state", "-wave_start_state", os.path.join(tmp, "none.h5")], ["-wave_start_state", "none.h5"]),
        (["-wave_start", "state"], ["-wave_start state", "-wave_start_state"]),
        (["-wave_start_state", state], ["-wave_start_state", "-wave_start state"]),
    ]
    for i, (extra, words) in enumerate(cases):
        r = subprocess.run([exe] + scene + ["-final_time", repr(P)] + extra + ["-output_dir", os.path.join(tmp, "bad%d" % i)],
                           capture_output=True, text=True)
        one_line_error(check, " ".join(extra), r.returncode, r.stderr, *words)


def clapping(tmp, mpiexec):
    ldr = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "options", "ldr_delamination.opts")
    base = ["-options_file", ldr, "-mesh_h", "0.006", "-mesh_h_crack", "0.0015", "-source_frequency", "11045.27",
            "-probe_every", "100"]
    state = os.path.join(tmp, "clapping.h5")
    if not run_scene(check, exe, base + ["-source_duration", "0.03", "-final_time", "0.03", "-output_times", "0.03",
                                         "-periodic_save_state", state], os.path.join(tmp, "clapping_saver")):
        return
    check(os.path.exists(state), "the clapping saver was continued and saved its state")
    short = ["-source_amplitude", "1.25e-6", "-source_duration", "0.005", "-final_time", "0.005", "-output_times",
             "0.005", "-periodic", "off", "-energy_every", "1"]
    runs = {}
    for name, extra, ranks in (("warm", ["-wave_start", "state", "-wave_start_state", state], 1),
                               ("harmonic", [], 1),
                               ("warm_np2", ["-wave_start", "state", "-wave_start_state", state], 2)):
        out = os.path.join(tmp, "clapping_" + name)
        if run_scene(check, exe, base + short + extra, out, mpiexec=mpiexec, ranks=ranks):
            runs[name] = outputs(out)
    if "warm" not in runs:
        return
    warm = runs["warm"].columns("energy.csv")
    check(warm["dissipated"][0] == 0.0 and warm["dissipated"][-1] > 0,
          "clapping warm start: no friction energy at t = 0 (%g), some after (%g)" % (warm["dissipated"][0],
                                                                                    warm["dissipated"][-1]))
    errors = {name: run.summary["max_budget_error"] for name, run in runs.items()}
    print("clapping crack: budget errors %s" % errors)
    check(errors["warm"] < 5e-3, "clapping warm start: the budget closes (%g of the work)" % errors["warm"])
    if "harmonic" in errors:
        check(errors["warm"] < 3 * errors["harmonic"] + 1e-4, "as well as after a harmonic start (%g)" % errors["harmonic"])
    if "warm_np2" in runs:
        two = runs["warm_np2"].columns("energy.csv")
        early = warm["t"] <= 5e-5
        for column in ("work_source", "kinetic"):
            worst = np.abs(two[column][:early.sum()] - warm[column][early]).max() / np.abs(warm[column][early]).max()
            check(worst < 1e-6, "2 ranks = serial over the first 50 us: %s within %.1e" % (column, worst))


with tempfile.TemporaryDirectory() as tmp:
    saver, state = os.path.join(tmp, "saver"), os.path.join(tmp, "state.h5")
    # Continued once periodic (-periodic on: no heat runs here); the state saved where the waves stop.
    if run_scene(check, exe, scene + ["-source_amplitude", "1e6", "-wave_start", "harmonic", "-final_time", repr(100 * P),
                                      "-periodic", "on", "-periodic_save_state", state], saver):
        continued = outputs(saver).summary["derived"].get("periodic_periods_continued", 0)
        check(continued > 0 and os.path.exists(state), "the saver was continued (%g periods) and saved %s" % (
            continued, state))
        check(not os.path.exists(state + ".partial"), "no partial state file left")
        if os.path.exists(state):
            compare(tmp, state)
            refusals(tmp, state)
    clapping(tmp, mpiexec)
check.finish()
