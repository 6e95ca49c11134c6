"""Shared by the restart tests (2D test_checkpoint_restart.py, 3D test_restart_3d.py): stop a
run once its checkpoint has passed a simulated time, and compare a restarted run with the run
never stopped: bit for bit on the same ranks, to rounding on another rank count."""
import json, os, signal, subprocess, time

import h5py
import numpy as np

# summary.json entries that describe the run, not its result.
NOT_FIGURES = {"wall_time_s", "stages", "date", "command_line", "restarted_from", "complete", "host", "options",
               "option_values"}


def why(err):
    """The run's own error line, or the end of what it printed."""
    lines = [l for l in err.splitlines() if l.startswith("vibrotherm: error")]
    return lines[0] if lines else err[-500:]


def checkpoint_time(out):
    """Simulated time of the latest checkpoint in out (-1: none yet)."""
    try:
        with h5py.File(os.path.join(out, "checkpoint.h5"), "r") as f:
            return float(f["wave.clock"]["values"][0])
    except (OSError, KeyError):
        return -1.0


def interrupted(cmd, exe, out, after, how="usr1"):
    """Starts cmd (writing into out), waits for a checkpoint at a simulated time >= after, then
    stops it (SIGUSR1 to mpiexec, which forwards it, or SIGKILL to the ranks); the exit status
    and stderr. The run needs -checkpoint_every_s short against its wave phase."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while checkpoint_time(out) < after and p.poll() is None and time.time() < deadline:
        time.sleep(0.05)
    if how == "usr1":
        p.send_signal(signal.SIGUSR1)
    else:  # a crash: the ranks die without a word
        time.sleep(0.5)
        # This run's ranks only (their command line starts with the executable and names
        # this output directory): other tests run the same executable at the same time.
        subprocess.run(["pkill", "-KILL", "-f", "^%s .*-output_dir %s$" % (exe, out)])
    _, err = p.communicate()
    return p.returncode, err


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out


def summary(out):
    return json.load(open(os.path.join(out, "summary.json")))


def compare_files(check, ref, out, label, text, hdf5):
    """Every byte of the text outputs, every dataset of the HDF5 outputs."""
    for name in text:
        same = open(os.path.join(ref, name), "rb").read() == open(os.path.join(out, name), "rb").read()
        check(same, "%s: %s differs from the uninterrupted run" % (label, name))
    for name in hdf5:
        a, b = datasets(os.path.join(ref, name)), datasets(os.path.join(out, name))
        check(a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a),
              "%s: %s differs from the uninterrupted run" % (label, name))


def compare_exact(check, ref, out, label, text, hdf5):
    """The files bit for bit (compare_files), every summary figure; the summary says restarted."""
    compare_files(check, ref, out, label, text, hdf5)
    sa, sb = summary(ref), summary(out)
    differ = [k for k in sa if k not in NOT_FIGURES and sa[k] != sb.get(k)]
    check(not differ, "%s: summary figures differ: %s" % (label, differ))
    check(sb["complete"] is True and "restarted_from" in sb, "%s: summary says complete, restarted from" % label)


def compare_rounding(check, ref, out, label, tolerance=1e-9):
    """probes.csv and energy.csv column by column relative to each column's largest value, the
    budget error (a small difference of large energies, as a fraction of the work) absolutely;
    the summary's dissipated and deposited energies, its largest budget error."""
    for name in ["probes.csv", "energy.csv"]:
        a = np.genfromtxt(os.path.join(ref, name), delimiter=",", names=True)
        b = np.genfromtxt(os.path.join(out, name), delimiter=",", names=True)
        for column in a.dtype.names:
            x, y = a[column], b[column]
            ok = x.shape == y.shape
            if ok and not np.all(np.isnan(x)):  # an all-NaN column (no heat probe) has nothing to compare
                scale = 1.0 if column == "budget_error" else np.nanmax(np.abs(x)) + 1e-300
                ok = np.nanmax(np.abs(x - y)) < tolerance * scale
            check(ok, "%s: %s column %s not within rounding of the uninterrupted run" % (label, name, column))
    sa, sb = summary(ref), summary(out)
    for key in ["dissipated_energy", "heat_deposited"]:
        check(abs(sa[key] - sb[key]) <= tolerance * abs(sa[key]), "%s: %s %g vs %g" % (label, key, sa[key], sb[key]))
    check(abs(sa["max_budget_error"] - sb["max_budget_error"]) <= tolerance, "%s: max_budget_error" % label)
