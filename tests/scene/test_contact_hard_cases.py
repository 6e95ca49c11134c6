#!/usr/bin/python3
"""Requirement: hard contact cases stay numerically stable in the paper scene
(0.1 ms): finite energies, energy budget closed within 1 %, |T| <= mu N at every
cell and step; mu = 0 dissipates nothing; a pre-closed crack dissipates orders
of magnitude less than the reference; a fully open crack never touches.

usage: test_contact_hard_cases.py VIBROTHERM SOURCE_DIR"""
import json, math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks

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
    for name, extra in cases.items():
        out = os.path.join(tmp, name)
        r = subprocess.run([exe, "-options_file", os.path.join(src, "options/paper.opts"), "-final_time", "1e-4",
                            "-output_dir", out] + extra, capture_output=True, text=True)
        check(r.returncode == 0, "%s: run failed: %s" % (name, r.stderr[-1500:]))
        if r.returncode:
            continue
        s = json.load(open(os.path.join(out, "summary.json")))
        results[name] = s
        check(all(math.isfinite(s[k]) for k in ("dissipated_energy", "max_budget_error")), "%s: not finite" % name)
        check(s["max_budget_error"] < 1e-2, "%s: budget error %g" % (name, s["max_budget_error"]))
        check(s["max_friction_excess"] <= 1e-9, "%s: |T| exceeded mu N by %g" % (name, s["max_friction_excess"]))
        check(s["dissipated_energy"] >= 0.0, "%s: negative dissipation" % name)

if len(results) == len(cases):
    ref = results["reference"]["dissipated_energy"]
    check(ref > 0.0, "the reference crack dissipates (%g J/m)" % ref)
    check(results["mu0"]["dissipated_energy"] == 0.0, "mu = 0 dissipated %g" % results["mu0"]["dissipated_energy"])
    check(results["preclosed"]["dissipated_energy"] < 1e-2 * ref,
          "pre-closed crack: %g vs reference %g" % (results["preclosed"]["dissipated_energy"], ref))
    check(results["open"]["dissipated_energy"] == 0.0, "open crack dissipated %g" % results["open"]["dissipated_energy"])
    check(results["amplitude1um"]["dissipated_energy"] > ref, "a larger amplitude dissipates more")
check.finish()
