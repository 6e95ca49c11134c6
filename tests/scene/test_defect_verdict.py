#!/usr/bin/python3
"""Requirement (issues 38 and 43): the camera's verdict is about the defect, and every run with a
source says what power it put in and how much of it the crack turned into heat.

The thermosonic scene (options/thermosonic.opts: a free specimen, a pre-closed crack, a
transducer patch, Q = 100 here so that the damping heat is a strong background), 2 ms of
excitation from its harmonic start, resolved (no continuation, the waves run to the end):
  - superposition: with -material_damping_heat the camera's defect frames (defect_k, the
    friction heat alone, stepped beside the field) equal the frames of the same run without
    damping heat (where the friction is all the heat), to 1e-8 of their peak; the defect's SNR
    is the same in both; without a background the contrast is null, with it finite and the
    hottest pixel is the damping's;
  - a damping-only run (an open crack, the careless user's -crack_law open -material_damping_heat
    at 2 µm of drive) whose frames are far above the noise is NOT detectable, says nothing heats
    at the crack, and warns that the response strains the specimen beyond the elastic range
    (its source alone would not);
  - the source's power over the last steady periods closes on its losses: input = friction +
    damping + radiated within 1 % (a steady state stores nothing more), the efficiency is
    friction / input, and source_power.csv has a row per source period; a traction source
    reports its power too; the rows go on through the ring-down (no input, efficiency nan).

usage: test_defect_verdict.py VIBROTHERM SOURCE_DIR"""
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
from checks import Checks, run_scene, outputs
from run_data import read_csv

exe, src = sys.argv[1:3]
check = Checks("defect verdict")
SCENE = ["-options_file", os.path.join(src, "options/thermosonic.opts"), "-source_duration", "2e-3",
         "-final_time", "2.5e-3", "-output_times", "2.5e-3", "-periodic", "off", "-wave_quiet_fraction", "0",
         "-material_loss_factor", "1e-2", "-camera_fps", "2000", "-camera_integration", "5e-4", "-probe_every", "200"]


def summary(out):
    return outputs(out).summary


def frames(out, kind):
    with outputs(out).h5("camera.h5") as f:
        g = f["camera"]
        return [g["%s_%d" % (kind, k)][:] for k in range(len(g["time"]))]


with tempfile.TemporaryDirectory() as tmp:
    both, friction_only = os.path.join(tmp, "both"), os.path.join(tmp, "friction")
    if run_scene(check, exe, SCENE + ["-material_damping_heat"], both) and run_scene(check, exe, SCENE, friction_only):
        a, b = summary(both), summary(friction_only)
        defect, alone = frames(both, "defect"), frames(friction_only, "clean")
        peak = max(f.max() for f in alone)
        error = max(np.abs(d - c).max() for d, c in zip(defect, alone))
        print("defect frames with damping heat against the friction-only run: %.3g of their peak %.3g K" % (
            error / peak, peak))
        check(len(defect) == len(alone) >= 4 and peak > 0, "camera frames in both runs (%d)" % len(alone))
        check(error <= 1e-8 * peak, "superposition: defect_k = the friction-only run's frames (%.3g)" % (error / peak))
        check(a["camera"]["defect_share"] == "partial" and b["camera"]["defect_share"] == "whole",
              "defect share partial with damping heat, whole without")
        check(abs(a["camera_peak_snr"] / b["camera_peak_snr"] - 1) < 1e-8, "the defect's SNR: the same in both")
        check(b["camera_defect_contrast"] is None, "no background: contrast null")
        total = frames(both, "clean")
        background = max((t - d).max() for t, d in zip(total, defect))
        check(a["camera_defect_contrast"] is not None and background > 0,
              "with damping heat: a finite contrast (%r)" % a["camera_defect_contrast"])
        check(not a["camera"]["peak_on_defect"] and a["camera"]["peak_rise"] > a["camera"]["defect_peak_rise"],
              "the hottest pixel is the damping's (%.3g K against the defect's %.3g K)" % (
                  a["camera"]["peak_rise"], a["camera"]["defect_peak_rise"]))
        # The source's power over its last steady periods: what went in came out.
        for name, s in (("with damping heat", a), ("friction only", b)):
            p = s["source_power"][-1]
            losses = p["friction_power"] + p["damping_power"] + p["radiated_power"]
            check(p["steady"] and abs(losses / p["input_power"] - 1) < 1e-2,
                  "%s: input %.4g = friction + damping + radiated %.4g" % (name, p["input_power"], losses))
            check(abs(s["thermosonic_efficiency"] - s["friction_power"] / s["input_power"]) < 1e-12,
                  "%s: efficiency = friction / input" % name)
        rows = read_csv(os.path.join(friction_only, "source_power.csv"))
        f = float(a["option_values"]["-source_frequency"]["value"])
        driven = rows["amplitude"] > 0
        # A row per period to the end (the ring-down after the switch-off too: input 0, efficiency nan).
        check(abs(len(rows["t_start"]) - 2.5e-3 * f) <= 2 and abs(driven.sum() - 2e-3 * f) <= 2,
              "source_power.csv: a row per period (%d for %.0f, %d driven for %.0f)" % (
                  len(rows["t_start"]), 2.5e-3 * f, driven.sum(), 2e-3 * f))
        check(np.isnan(rows["efficiency"][rows["input_power"] == 0]).all() and
              np.isfinite(rows["efficiency"][rows["input_power"] > 0]).all(),
              "source_power.csv: the efficiency where something is put in, nan where nothing is")
        e = read_csv(os.path.join(friction_only, "energy.csv"))
        w = b["source_power"][-1]
        at = lambda t: np.interp(t, e["t"], e["dissipated"])  # noqa: E731
        slope = (at(w["t_end"]) - at(w["t_start"])) / (w["t_end"] - w["t_start"])
        check(abs(slope / w["friction_power"] - 1) < 1e-9, "friction power = the slope of energy.csv's dissipated")

    # The careless user's damping-only run: hot, but nothing of it is the crack's.
    damping = os.path.join(tmp, "damping_only")
    args = SCENE + ["-crack_law", "open", "-material_damping_heat", "-source_amplitude", "2e-6", "-wave_start", "rest",
                    "-camera_netd", "1e-3"]
    if run_scene(check, exe, args, damping):
        s = summary(damping)
        c = s["camera"]
        print("damping only: hottest pixel %.3g K (SNR %.3g), defect's %r, detectable %r" % (
            c["peak_rise"], c["total_peak_snr"], c["defect_peak_rise"], s["camera_detectable"]))
        check(c["total_peak_snr"] >= 5, "the frames are far above the noise (SNR %.3g)" % c["total_peak_snr"])
        check(s["camera_detectable"] is False and s["camera_peak_snr"] == 0 and c["defect_share"] == "none",
              "damping heat alone: the defect is not detectable")
        check(not c["peak_on_defect"], "the hottest pixel is not the defect's")
        check(any("the response strains the specimen" in w for w in s["warnings"]),
              "the response's strain is warned about: %s" % s["warnings"])
        check(s["friction_power"] == 0 and s["input_power"] > 0, "an open crack takes no power, the source puts some in")

    # A traction source reports its power too.
    traction = os.path.join(tmp, "traction")
    if run_scene(check, exe, SCENE + ["-source_type", "traction", "-source_amplitude", "1e5", "-camera", "0"], traction):
        s = summary(traction)
        p = s["source_power"][-1]
        check(s["input_power"] > 0 and abs((p["friction_power"] + p["damping_power"]) / p["input_power"] - 1) < 1e-2,
              "traction source: input %.4g closes on its losses" % s["input_power"])
check.finish()
