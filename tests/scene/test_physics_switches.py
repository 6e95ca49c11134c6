#!/usr/bin/python3
"""Requirement: a scene simulates only the effects it calls for. No crack → no contact
and no heat; an open crack → no contact; μ = 0 → contact but no heat TS (summary.json
and -log_view agree); friction → the heat TS runs; after a short source the wave solver
stops once the waves are quiet and the heat TS carries on alone to -final_time, with
the heat deposited equal to the energy dissipated (1e-12). A 3D box without a crack runs
its waves alone.

usage: test_physics_switches.py VIBROTHERM"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe = sys.argv[1]
check = Checks("physics switches")
scene = ("-specimen_width 0.05 -specimen_height 0.1 -mesh_h 0.004 -mesh_h_crack 0.001 -edge_top source "
         "-source_frequency 1e5 -source_amplitude 1e-7 -source_duration 3e-5 -source_ramp_cycles 1 "
         "-contact_normal_law biwa -contact_biwa_m 0.5 -contact_biwa_C 1e11 -crack_law mmd -wave_degree 1").split()
crack = "-crack_center 0.025,0.05 -crack_length 0.02 -crack_angle 20".split()


def run(tmp, name, extra, final_time="2e-5"):
    out = os.path.join(tmp, name)
    r = subprocess.run([exe] + scene + extra + ["-final_time", final_time, "-output_dir", out, "-log_view"],
                       capture_output=True, text=True)
    check(r.returncode == 0, "%s: %s" % (name, r.stderr[-1500:]))
    if r.returncode:
        return None, ""
    return outputs(out).summary, r.stdout


with tempfile.TemporaryDirectory() as tmp:
    cases = [("no crack", [], ["wave"]),
             ("open crack", crack + ["-crack_law", "open"], ["wave"]),
             ("mu = 0", crack + ["-contact_mu", "0"], ["wave", "contact"]),
             ("friction", crack + ["-contact_mu", "1"], ["wave", "contact", "heat"]),
             ("heat forced on", ["-heat", "on"], ["wave", "heat"]),
             # A 3D box without a crack (issue 26): waves only.
             ("3D box, no crack", ["-specimen_width", "0.02", "-specimen_height", "0.02", "-specimen_depth", "0.01",
                                   "-wave_degree", "2"], ["wave"])]
    for name, extra, expected in cases:
        summary, log = run(tmp, name.replace(" ", "_"), extra)
        if not summary:
            continue
        check(summary["physics_ran"] == expected, "%s: physics_ran %s, expected %s" % (name, summary["physics_ran"], expected))
        heat = "heat" in expected
        check(("Heat steps" in log) == heat, "%s: -log_view %s a Heat steps stage" % (name, "lacks" if heat else "has"))
        check((summary["steps_heat"] > 0) == heat, "%s: steps_heat %s" % (name, summary["steps_heat"]))
        check((summary["contact_cells"] > 0) == ("contact" in expected), "%s: contact cells %s" % (name, summary["contact_cells"]))
    # Short source, long run: the waves stop once quiet, heat goes on alone.
    summary, log = run(tmp, "quiet", crack + ["-contact_mu", "1", "-wave_quiet_fraction", "0.05"], final_time="2e-3")
    if summary:
        wave_end, heat_end = summary["physics_time"]["wave"][1], summary["physics_time"]["heat"][1]
        check(3e-5 < wave_end < 1.5e-3, "waves stopped at %g s (source ends at 3e-5 s, run ends at 2e-3 s)" % wave_end)
        check(abs(heat_end - 2e-3) < 1e-12, "heat ran to %g s" % heat_end)
        check(summary["wave_energy_left"] <= 0.05 * summary["dissipated_energy"],
              "mechanical energy left %g vs dissipated %g" % (summary["wave_energy_left"], summary["dissipated_energy"]))
        d, h = summary["dissipated_energy"], summary["heat_deposited"]
        check(d > 0 and abs(h - d) <= 1e-12 * d, "heat deposited %r vs dissipated %r" % (h, d))
        print("waves stopped at %.4g s; dissipated %.4g J/m; heat deposited %.4g J/m" % (wave_end, d, h))
    # Degree 2 with field output (once overflowed the vertex buffer with edge nodes).
    summary, log = run(tmp, "degree2", crack + ["-contact_mu", "1", "-wave_degree", "2", "-output_times", "1e-5,2e-5"])
    if summary:
        with outputs(tmp, "degree2").h5("fields.h5") as f:
            state = f["wave/contact_state_1"][:]
        check(set(state.ravel()) <= {-1.0, 0.0, 1.0, 2.0, 3.0} and (state >= 0).sum() >= 2,
              "degree 2: contact_state values %s" % sorted(set(state.ravel()))[:8])
check.finish()
