#!/usr/bin/python3
"""Requirement (issue 24): periodic continuation. A pre-closed crack under 16 nm of shear
(partial slip: a clean periodic state within ~20 periods), 2 ms of 100 kHz with a schedule
step at 1 ms (two steady stretches, each found periodic and continued), against the fully
resolved run of the same scene (same quantized step, no continuation):
  - dissipated energy and heat content within 0.5 %, the crack-centre temperature at every
    period end both runs record within 1 % of its peak, the energy budget closed;
  - summary.json: two continuation segments, the periods continued, when periodicity was reached;
  - 2 ranks = serial (dissipated energy, continued periods);
  - a run stopped by a signal inside a continuation's heat ladder restarts from its checkpoint
    and ends identical to the run never stopped (energy.csv, probes.csv, summary figures);
  - a tolerance nothing meets: the run is simulated fully and says how close it came.

usage: test_periodic_continuation.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
from checks import Checks, run_scene, outputs
import periodic_compare

exe, src, mpiexec = sys.argv[1:4]
check = Checks("periodic continuation")
BASE = ["-options_file", os.path.join(src, "options/paper.opts"), "-crack_a0", "2e-8", "-source_amplitude", "1.6e-8",
        "-crack_state_every", "0", "-probe_every", "10"]
SCENE = BASE + ["-source_duration", "2e-3", "-source_schedule", "1e-3,2.4e-8", "-final_time", "2.15e-3",
                "-output_times", "1e-3,2e-3"]
RESOLVED = ["-periodic_min_continued", "1000000000"]


def summary(out):
    return outputs(out).summary


with tempfile.TemporaryDirectory() as tmp:
    cont, ref, cont2 = (os.path.join(tmp, n) for n in ("continued", "resolved", "continued_np2"))
    ok = run_scene(check, exe, SCENE, cont) and run_scene(check, exe, SCENE + RESOLVED, ref)
    if ok:
        c = periodic_compare.compare(cont, ref, crack_probe=5, period=1e-5)
        s = summary(cont)
        print("continued %d periods (periodic at %.3g s), wall %.1f s against %.1f s: dissipated %+.2e, heat content "
              "%+.2e, crack centre at %d period ends %.2e" % (c["continued"], c["reached_at"], c["wall"],
                                                              c["wall_reference"], c["dissipated"], c["heat_content"],
                                                              c["crack_probe_period_ends"], c["crack_probe"]))
        check(len(s["periodic"]) == 2, "two steady stretches, two continuations: %s" % s["periodic"])
        check(c["continued"] > 100, "most of the 200 periods continued (%d)" % c["continued"])
        check(abs(c["dissipated"]) < 5e-3, "dissipated energy %+.3g against the resolved run" % c["dissipated"])
        check(abs(c["heat_content"]) < 5e-3, "heat content %+.3g against the resolved run" % c["heat_content"])
        check(c["crack_probe_period_ends"] >= 10 and c["crack_probe"] < 1e-2,
              "crack centre at %d period ends: %.3g of its peak" % (c["crack_probe_period_ends"], c["crack_probe"]))
        check(s["max_budget_error"] < 1e-5, "energy budget through the continuation: %g" % s["max_budget_error"])
        check(os.path.exists(os.path.join(cont, "periodic.csv")), "periodic.csv written")
    if ok and run_scene(check, exe, SCENE, cont2, mpiexec, 2):
        a, b = summary(cont), summary(cont2)
        check(abs(a["dissipated_energy"] / b["dissipated_energy"] - 1) < 1e-9 and
              a["derived"]["periodic_periods_continued"] == b["derived"]["periodic_periods_continued"],
              "2 ranks = serial: %r vs %r" % (b["dissipated_energy"], a["dissipated_energy"]))
    # A signal inside the heat ladder: camera windows make the ladder long enough to catch.
    camera = ["-camera", "-camera_fps", "20000", "-camera_integration", "2e-5", "-checkpoint_every_s", "0"]
    periodic_compare.check_restart_inside_continuation(check, exe, SCENE + camera, tmp)
    never = os.path.join(tmp, "never")
    if run_scene(check, exe, BASE + ["-periodic_tol", "1e-12", "-source_duration", "5e-4", "-final_time", "3e-4"],
                 never):
        s = summary(never)
        check(s["derived"]["periodic_periods_continued"] == 0 and "never periodic" in s["derived_rules"]["periodic"],
              "a tolerance nothing meets: simulated fully, said so (%s)" % s["derived_rules"]["periodic"])
        check(0 < s["derived"]["periodic_last_change"] < 1, "the change it saw: %r" % s["derived"]["periodic_last_change"])
check.finish()
