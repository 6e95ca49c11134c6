#!/usr/bin/python3
"""Requirement (issue 26, item 2: checkpoint/restart in 3D, 2 ranks = serial): a 3D run
(options/block3d_small.opts, coarsened and lengthened to stop mid-way, with two-way thermoelastic
coupling so that the thermal stress's state is restarted too) stopped by SIGUSR1 once
its crack has dissipated and a field output is written writes a checkpoint, exits 128 + the
signal, and -restart DIR then finishes it:
 - on the same ranks (serial, and 2 ranks partitioned so that the crack straddles them: both
   ranks' cells had dissipated at the stop) bit-identical to the run never stopped: every byte
   of energy.csv and probes.csv, every dataset of fields.h5, every summary figure;
 - on the other rank count (a serial checkpoint on 2 ranks, a 2-rank one serially) within
   1e-9 of it (columns relative to their largest value, as in 2D: test_checkpoint_restart.py).
The comparison can fail: the stop falls after the crack started to dissipate and before the
end, and the crack dissipates more after the stop (the restart carries its memory).

usage: test_restart_3d.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, shutil, signal, subprocess, sys, tempfile

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs
import restart_compare
from restart_compare import compare_exact, compare_rounding, summary, why

exe, src, mpiexec = sys.argv[1:4]
check = Checks("restart_3d")
FINAL = 4e-5  # s: ~1000 steps of 1 ms on this mesh, long enough to stop mid-way
SCENE = ["-options_file", os.path.join(src, "options/block3d_small.opts"),
         # 3 x 2 crack faces (15 contact cells), 8766 dofs: ~4 s a run
         "-mesh_h", "0.003", "-mesh_h_crack", "0.002", "-source_frequency", "1.5e5",
         "-source_duration", str(FINAL), "-final_time", str(FINAL), "-output_times", "1e-5,3e-5",
         "-checkpoint_every_s", "0.1",  # metis (the options file) cuts the crack between 2 ranks
         "-thermoelastic", "two_way"]  # the thermal stress's state is in the checkpoint too
ACTIVE = 1.2e-5  # s: the crack has dissipated since ~4e-6 and the first fields are written
TEXT = ["energy.csv", "probes.csv"]


def command(ranks, extra):
    parallel = [mpiexec, "-n", str(ranks), "--oversubscribe"] if ranks > 1 else []
    return parallel + [exe] + SCENE + extra


def run(ranks, extra):
    r = subprocess.run(command(ranks, extra), capture_output=True, text=True)
    return r.returncode, r.stderr


def dissipated_per_rank(out):
    """Each writing rank's dissipated energy in the checkpoint (crack/accounts: dissipated first)."""
    with h5py.File(os.path.join(out, "checkpoint.h5"), "r") as f:  # the checkpoint: not an output
        accounts = f["crack.accounts"]
        width = int(accounts["counts"][0])
        return list(accounts["values"][::width])


def check_stop(out, ranks, code):
    """The run stopped as the signal asked, after the crack's first dissipation, before its end."""
    label = "stopped on %d rank%s" % (ranks, "s" if ranks > 1 else "")
    check(code == 128 + signal.SIGUSR1, "%s: exit %d, expected %d" % (label, code, 128 + signal.SIGUSR1))
    stopped_at = restart_compare.checkpoint_time(out)
    check(ACTIVE <= stopped_at < FINAL, "%s: at t = %g, expected in [%g, %g)" % (label, stopped_at, ACTIVE, FINAL))
    check(summary(out)["complete"] is False, '%s: summary.json "complete": false' % label)
    dissipated = dissipated_per_rank(out) if stopped_at > 0 else []
    check(len(dissipated) == ranks and min(dissipated) > 0,
          "%s: every rank's crack cells dissipated before the stop (%s)" % (label, dissipated))
    return sum(dissipated)


with tempfile.TemporaryDirectory() as tmp:
    refs = {}
    for ranks in (1, 2):
        refs[ranks] = os.path.join(tmp, "ref%d" % ranks)
        code, err = run(ranks, ["-output_dir", refs[ranks]])
        check(code == 0 and not os.path.exists(os.path.join(refs[ranks], "checkpoint.h5")),
              "uninterrupted run on %d ranks: exit 0, no checkpoint left (%s)" % (ranks, why(err)))
    for ranks in (1, 2):
        out = os.path.join(tmp, "stopped%d" % ranks)
        code, _ = restart_compare.interrupted(command(ranks, ["-output_dir", out]), exe, out, ACTIVE)
        at_stop = check_stop(out, ranks, code)
        other = 3 - ranks
        shutil.copytree(out, out + "_on%d" % other)
        for restart_ranks, where in [(ranks, out), (other, out + "_on%d" % other)]:
            label = "%d-rank checkpoint restarted on %d" % (ranks, restart_ranks)
            code, err = run(restart_ranks, ["-restart", where])
            check(code == 0, "%s: exit 0 (%s)" % (label, why(err)))
            if code != 0:
                continue
            check(summary(where)["dissipated_energy"] > at_stop, "%s: the crack dissipates after the stop" % label)
            if restart_ranks == ranks:
                compare_exact(check, refs[ranks], where, label, TEXT, ["fields.h5"])
            else:  # fields written before the stop are not carried to another partition
                compare_rounding(check, refs[restart_ranks], where, label)
check.finish()
