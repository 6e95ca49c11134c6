#!/usr/bin/python3
"""Requirement (issue 24): the material's damping heat (-material_damping_heat) is replayed by a
periodic continuation like the crack's friction, so a damped specimen whose damping heats it is
continued, not simulated in full. A pre-closed crack under 16 nm of shear in a specimen with
loss factor 1e-2 (its damping heat outweighs the friction 10⁴×), 1 ms of 100 kHz, against the
fully resolved run of the same scene (same quantized step, no continuation):
  - the run is continued (most of its periods);
  - the heat the damping deposits equals the energy the waves' damping took, in both runs
    (energy.csv heat_damping against damped, an account kept by the wave solver);
  - heat content, damping heat and friction within 1e-3 of the resolved run, the crack-centre
    temperature at every period end within 1 % of its peak, the energy budget closed;
  - a run stopped by a signal inside the continuation restarts and ends identical to the run
    never stopped (the damping heat's replay is in the checkpoint).

usage: test_periodic_damping_heat.py VIBROTHERM SOURCE_DIR"""
import os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
from checks import Checks, run_scene
from run_data import read_csv
import periodic_compare

exe, src = sys.argv[1:3]
check = Checks("periodic damping heat")
SCENE = ["-options_file", os.path.join(src, "options/paper.opts"), "-crack_a0", "2e-8", "-source_amplitude", "1.6e-8",
         "-crack_state_every", "0", "-probe_every", "10", "-source_duration", "1e-3", "-final_time", "1.1e-3",
         "-output_times", "1.1e-3", "-material_loss_factor", "1e-2", "-material_damping_heat"]


def last_row(out):
    e = read_csv(os.path.join(out, "energy.csv"))
    return {k: e[k][-1] for k in e}


with tempfile.TemporaryDirectory() as tmp:
    cont, ref = os.path.join(tmp, "continued"), os.path.join(tmp, "resolved")
    if run_scene(check, exe, SCENE, cont) and run_scene(check, exe, SCENE + ["-periodic_min_continued", "1000000000"], ref):
        c = periodic_compare.compare(cont, ref, crack_probe=5, period=1e-5)
        a, b = last_row(cont), last_row(ref)
        print("continued %d periods: heat content %+.2e, damping heat %+.2e, friction %+.2e, crack centre %.2e of its peak"
              % (c["continued"], c["heat_content"], a["heat_damping"] / b["heat_damping"] - 1,
                 a["heat_friction"] / b["heat_friction"] - 1, c["crack_probe"]))
        check(c["continued"] > 50, "continued with the damping heat on (%d periods)" % c["continued"])
        for name, row in (("continued", a), ("resolved", b)):
            check(abs(row["heat_damping"] / row["damped"] - 1) < 1e-9,
                  "%s: damping heat %r = the waves' damped energy %r" % (name, row["heat_damping"], row["damped"]))
        check(abs(c["heat_content"]) < 1e-3, "heat content %+.3g against the resolved run" % c["heat_content"])
        check(abs(a["heat_damping"] / b["heat_damping"] - 1) < 1e-3, "damping heat against the resolved run")
        check(abs(a["heat_friction"] / b["heat_friction"] - 1) < 1e-3, "friction heat against the resolved run")
        check(c["crack_probe_period_ends"] >= 10 and c["crack_probe"] < 1e-2,
              "crack centre at %d period ends: %.3g of its peak" % (c["crack_probe_period_ends"], c["crack_probe"]))
        check(periodic_compare.summary(cont)["max_budget_error"] < 1e-5, "energy budget through the continuation")
    # A restart inside the continuation restores the damping heat's replay (camera windows: a ladder long enough).
    camera = ["-camera", "-camera_fps", "20000", "-camera_integration", "2e-5", "-checkpoint_every_s", "0"]
    periodic_compare.check_restart_inside_continuation(check, exe, SCENE + camera, tmp)
check.finish()
