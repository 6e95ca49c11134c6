#!/usr/bin/python3
"""Requirement: hard contact cases stay numerically stable in the paper scene
(0.1 ms): finite energies, energy budget closed within 1 %, |T| <= mu N at every
cell and step; mu = 0 dissipates nothing; a pre-closed crack dissipates orders
of magnitude less than the reference; a fully open crack never touches. Each
case with the global step and with local time stepping (-wave_lts on).

usage: test_contact_hard_cases.py VIBROTHERM SOURCE_DIR"""
import math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe, src = sys.argv[1:3]
check = Checks("contact hard cases")
# Biwa 1000x stiffer: N = (2 (1-m) C_B a)^2 scales with C_B^2 -> C_B x sqrt(1000).
cases = {
    "reference": [],
    "mu0": ["-contact_mu", "0"],
    "mu5": ["-contact_mu", "5"],
    "stiff1000": ["-contact_biwa_C", str(1e11 * math.sqrt(1000))],
    "amplitude1um": ["-source_amplitude", "1e-6"],
    "preclosed": ["-crack_a0", "2e-6"],
    "open": ["-crack_a0", "-3e-7"],
}
results = {}
with tempfile.TemporaryDirectory() as tmp:
    for stepping in ("off", "on"):
        for name, extra in cases.items():
            key = "%s/lts_%s" % (name, stepping)
            out = os.path.join(tmp, name + "_" + stepping)
            r = subprocess.run([exe, "-options_file", os.path.join(src, "options/paper.opts"), "-final_time", "1e-4",
                                "-wave_lts", stepping, "-output_dir", out] + extra, capture_output=True, text=True)
            check(r.returncode == 0, "%s: run failed: %s" % (key, r.stderr[-1500:]))
            if r.returncode:
                continue
            s = outputs(out).summary
            results[key] = s
            check(all(math.isfinite(s[k]) for k in ("dissipated_energy", "max_budget_error")), "%s: not finite" % key)
            check(s["max_budget_error"] < 1e-2, "%s: budget error %g" % (key, s["max_budget_error"]))
            check(s["max_friction_excess"] <= 1e-9, "%s: |T| exceeded mu N by %g" % (key, s["max_friction_excess"]))
            check(s["dissipated_energy"] >= 0.0, "%s: negative dissipation" % key)

for stepping in ("off", "on"):
    if not all("%s/lts_%s" % (name, stepping) in results for name in cases):
        continue
    d = {name: results["%s/lts_%s" % (name, stepping)]["dissipated_energy"] for name in cases}
    ref = d["reference"]
    tag = "lts %s: " % stepping
    check(ref > 0.0, tag + "the reference crack dissipates (%g J/m)" % ref)
    check(d["mu0"] == 0.0, tag + "mu = 0 dissipated %g" % d["mu0"])
    check(d["preclosed"] < 1e-2 * ref, tag + "pre-closed crack: %g vs reference %g" % (d["preclosed"], ref))
    check(d["open"] == 0.0, tag + "open crack dissipated %g" % d["open"])
    check(d["amplitude1um"] > ref, tag + "a larger amplitude dissipates more")
check.finish()
