#!/usr/bin/python3
"""Requirement (issue 16): a run stopped by a signal writes a checkpoint, exits 128 + the
signal with "complete": false and only .partial outputs; -restart DIR then finishes it
bit-identical to a run never stopped (same ranks: every byte of probes.csv, energy.csv,
crack_state.csv, every dataset of fields.h5, crack_heat.h5 and camera.h5, every summary figure), and
identical to rounding on another rank count. A run killed outright (SIGKILL) restarts from
its last periodic checkpoint just as exactly (files written after it are cut back). A
restart with other options, without a checkpoint or from an older checkpoint format, is refused
with one line, exit 2.
Issue 27: a stop while the heat runs alone after the waves (SIGUSR1 there) resumes where
the waves stopped and finishes bit-identical (before: no checkpoint there, with the
default -checkpoint_every_s the restart was refused and the run lost).

usage: test_checkpoint_restart.py VIBROTHERM MPIEXEC"""
import os, signal, subprocess, sys, tempfile

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs
import restart_compare
from restart_compare import why

exe, mpiexec = sys.argv[1:3]
check = Checks("checkpoint_restart")
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = ["-options_file", os.path.join(ROOT, "options", "paper.opts"), "-final_time", "3e-4",
         "-output_times", "5e-5,2.5e-4", "-checkpoint_every_s", "0.3",
         "-camera", "-camera_fps", "10000", "-camera_integration", "5e-5"]  # frames open across the checkpoint
ACTIVE = 4e-5  # s: the shear wave has reached the crack, its faces rub (a restart must carry their memory)
TEXT = ["probes.csv", "energy.csv", "crack_state.csv"]


def command(ranks, extra):
    return [mpiexec, "-n", str(ranks), "--oversubscribe", exe] + SCENE + extra


def run(ranks, extra):
    r = subprocess.run(command(ranks, extra), capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def interrupted(out, how):
    """A 2-rank run stopped once its checkpoint is past ACTIVE (SIGUSR1, or SIGKILL: a crash)."""
    return restart_compare.interrupted(command(2, ["-output_dir", out]), exe, out, ACTIVE, how)


def compare_exact(ref, out, label):
    restart_compare.compare_exact(check, ref, out, label, TEXT, ["fields.h5", "crack_heat.h5", "camera.h5"])


def compare_rounding(ref, out, label):
    restart_compare.compare_rounding(check, ref, out, label)


with tempfile.TemporaryDirectory() as tmp:
    ref = os.path.join(tmp, "ref")
    code, _, err = run(2, ["-output_dir", ref])
    check(code == 0 and not os.path.exists(os.path.join(ref, "checkpoint.h5")),
          "uninterrupted run: exit 0, no checkpoint left (%s)" % why(err))

    out = os.path.join(tmp, "usr1")
    code, err = interrupted(out, "usr1")
    check(code == 128 + signal.SIGUSR1, "SIGUSR1: exit %d, expected %d (%s)" % (code, 128 + signal.SIGUSR1, why(err)))
    summary = outputs(out).summary
    check(summary["complete"] is False, 'SIGUSR1: summary.json "complete": false')
    check(all(not os.path.exists(os.path.join(out, n)) and os.path.exists(os.path.join(out, n + ".partial")) for n in TEXT),
          "SIGUSR1: only .partial outputs, nothing under a final name")
    code, _, err = run(2, ["-restart", out])
    check(code == 0, "restart on 2 ranks: exit 0 (%s)" % why(err))
    if code == 0:
        compare_exact(ref, out, "restart on 2 ranks")

    for label, how, ranks, compare in [("restart after SIGKILL", "kill", 2, compare_exact),
                                       ("restart on 1 rank", "usr1", 1, compare_rounding)]:
        out = os.path.join(tmp, how + str(ranks))
        code, _ = interrupted(out, how)
        check(code != 0, "%s: the interrupted run did not finish" % label)
        code, _, err = run(ranks, ["-restart", out])
        check(code == 0, "%s: exit 0 (%s)" % (label, why(err)))
        if code == 0:
            compare(ref, out, label)

    # Refused: another option, no checkpoint. One line, exit 2, nothing written.
    out = os.path.join(tmp, "refused")
    interrupted(out, "usr1")
    before = sorted(os.listdir(out))
    code, _, err = run(2, ["-restart", out, "-contact_mu", "0.5"])
    lines = [l for l in err.splitlines() if l.startswith("vibrotherm: error")]
    check(code == 2 and len(lines) == 1 and "-contact_mu" in lines[0], "other options: one line naming -contact_mu, exit 2")
    check(sorted(os.listdir(out)) == before, "other options: nothing written")
    code, _, err = run(2, ["-restart", os.path.join(tmp, "nowhere")])
    check(code == 2 and "checkpoint" in err and not os.path.exists(os.path.join(tmp, "nowhere")),
          "no checkpoint: exit 2 naming it, nothing written (%s)" % err[-300:])
    # A checkpoint of an older format (format 1: crack_state.csv had two schemas) is refused, naming it.
    with h5py.File(os.path.join(out, "checkpoint.h5"), "r+") as f:
        f.attrs["format"] = 1
    code, _, err = run(2, ["-restart", out])
    lines = [l for l in err.splitlines() if l.startswith("vibrotherm: error")]
    check(code == 2 and len(lines) == 1 and "checkpoint format 1" in lines[0] and "-restart" in lines[0],
          "an older checkpoint: one line naming -restart and its format, exit 2 (exit %d, %d lines: %s)"
          % (code, len(lines), err[-300:]))
    check(sorted(os.listdir(out)) == before, "an older checkpoint: nothing written")

    # A stop in the heat-alone phase (the waves quiet at ~0.9 ms, the heat alone to 10 s), serial.
    heat_alone = [exe, "-options_file", os.path.join(ROOT, "options", "paper.opts"), "-mesh_h", "0.004",
                  "-mesh_h_crack", "0.001", "-wave_degree", "1", "-source_duration", "1e-4", "-final_time", "10",
                  "-output_times", "1e-4,1e-2,10", "-heat_free_ts_adapt_ladder_steps", "64", "-wave_quiet_fraction",
                  "0.05"]
    ref, out = os.path.join(tmp, "heat_alone_ref"), os.path.join(tmp, "heat_alone")
    r = subprocess.run(heat_alone + ["-output_dir", ref], capture_output=True, text=True)
    check(r.returncode == 0, "heat alone, uninterrupted: exit 0 (%s)" % why(r.stderr))
    p = subprocess.Popen(heat_alone + ["-output_dir", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for line in p.stdout:
        if line.startswith("Heat alone"):
            check("resumes" in line, "heat alone: says at its start that a stop resumes: %r" % line)
            p.send_signal(signal.SIGUSR1)
            break
    _, err = p.communicate()
    check(p.returncode == 128 + signal.SIGUSR1, "heat alone, SIGUSR1: exit %d (%s)" % (p.returncode, why(err)))
    r = subprocess.run(heat_alone + ["-restart", out], capture_output=True, text=True)
    check(r.returncode == 0, "heat alone, restart: exit 0 (%s)" % why(r.stderr))
    if r.returncode == 0:
        restart_compare.compare_files(check, ref, out, "heat alone, restart", TEXT, ["fields.h5", "crack_heat.h5"])

check.finish()
