#!/usr/bin/python3
"""Requirement (issue 27, item 8): a run that leaves the model's validity says so, or is
refused naming the option, instead of ending "complete" with absurd numbers.

- 1 mm of source amplitude at 100 kHz (strain ~0.2): refused, one line naming
  -source_amplitude, exit 2 (before: "complete": true with a 12 256 K rise).
- 10 um (strain ~2e-3, past the metals' yield strain): runs, with a warning in the
  output and in summary.json "warnings".
- 1 GHz on a millimetre mesh: refused naming -source_frequency and the mesh (before:
  "lower -wave_cfl").
- 1 Hz: runs (before: refused on derived heat-mesh sizes the user never set), given a whole
  cycle of excitation and a heat step within the run.
- A temperature rise beyond the constant-property range (-physics heat with a large
  crack power: ~100 K): a warning, once, and in summary.json.

usage: test_model_validity.py VIBROTHERM"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, one_line_error, outputs

exe = os.path.abspath(sys.argv[1])
check = Checks("model_validity")
SCENE = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.002", "-mesh_h_crack", "0.001",
         "-crack_center", "0.01,0.01", "-crack_length", "0.006", "-crack_angle", "20", "-final_time", "5e-6"]


def run(tmp, name, extra):
    out = os.path.join(tmp, name)
    r = subprocess.run([exe] + SCENE + extra + ["-output_dir", out], capture_output=True, text=True, timeout=300)
    summary = {}
    if os.path.exists(os.path.join(out, "summary.json")):
        summary = outputs(out).summary
    return r, summary, out


def refused(label, r, out, *words):
    one_line_error(check, label, r.returncode, r.stderr, *words)
    check(not os.path.exists(out), "%s: nothing written" % label)


with tempfile.TemporaryDirectory() as tmp:
    r, _, out = run(tmp, "mm", ["-source_amplitude", "1e-3"])
    refused("1 mm amplitude", r, out, "-source_amplitude", "small-strain")

    r, summary, _ = run(tmp, "ten_um", ["-source_amplitude", "1e-5"])
    check(r.returncode == 0, "10 um amplitude runs (%s)" % r.stderr[-300:])
    check("-source_amplitude" in r.stdout and "yield" in r.stdout, "10 um amplitude: a warning at setup")
    check(any("yield" in w for w in summary.get("warnings", [])), "10 um amplitude: summary.json warnings")

    r, _, out = run(tmp, "ghz", ["-source_frequency", "1e9"])
    refused("1 GHz", r, out, "-source_frequency", "wavelength", "-mesh_h")
    check("-wave_cfl" not in r.stderr, "1 GHz: not answered with -wave_cfl")

    # A whole cycle of excitation, a ramp that fits it and a heat step within the run (issue 43:
    # anything less is refused as useless); 5 us of it simulated.
    r, summary, _ = run(tmp, "one_hz", ["-source_frequency", "1", "-source_duration", "1", "-source_ramp_cycles", "0.5",
                                        "-couple_dt", "1e-6"])
    check(r.returncode == 0 and summary.get("complete") is True, "1 Hz runs (%s)" % r.stderr[-300:])

    r, summary, _ = run(tmp, "hot", ["-physics", "heat", "-heat_crack_power", "1e8", "-final_time", "1e-3"])
    check(r.returncode == 0, "a 100 K rise runs (%s)" % r.stderr[-300:])
    check(summary.get("field_max_temperature_rise", 0) > 10, "the scene heats beyond 10 K: %s"
          % summary.get("field_max_temperature_rise"))
    check(r.stdout.count("material properties constant") == 1, "a rise beyond 10 K: one warning")
    check(any("constant" in w for w in summary.get("warnings", [])), "a rise beyond 10 K: summary.json warnings")
    r, summary, _ = run(tmp, "mild", ["-physics", "heat", "-heat_crack_power", "1e5", "-final_time", "1e-3"])
    check(r.returncode == 0 and summary.get("warnings") == [] and "warning" not in r.stdout,
          "a mild run has no warnings: %s" % summary.get("warnings"))

check.finish()
