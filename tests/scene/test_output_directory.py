#!/usr/bin/python3
"""Requirement (issue 27): a user's work in an output directory is never lost.

- Two runs into one directory: the second is refused at once, in one line naming the
  first (pid and host), exit 2, and touches nothing; the first finishes complete. (Before:
  the second deleted the first's .partial files, the first renamed the second's outputs
  as its own and both exited 0.) The first run is held still with SIGSTOP while the
  second tries, so the test does not depend on timing.
- A crashed run's lock (a dead pid on this host) is taken over with a note; a lock from
  another host is refused, naming the file to remove.
- A run without -restart into a directory holding an interrupted run's checkpoint is
  refused in one line (exit 2) and deletes nothing; -restart continues it, with the
  directory spelt relative in -restart and absolute in -output_dir; -overwrite discards a
  checkpoint on purpose.
- (issue 43, item 3) A complete run's results are never deleted by the next run into the
  same directory: refused in one line naming -output_dir and -overwrite, exit 2, every file
  unchanged; -overwrite replaces them. (Before: "removed 8 outputs of an earlier run", exit 0.)
- (issue 43, item 6) Checks before expensive work: a run into a directory another run holds
  is refused before it meshes (the lock is taken before meshing: two runs started together,
  the first held still with SIGSTOP right after it took the lock, the second refused without
  a "Meshing" line); a file, or a directory that cannot be created, in place of -output_dir
  is refused before meshing; a source frequency no mesh of the requested sizes can carry is
  refused before meshing; a 3D run's output directory and lock exist before its harmonic
  start; bad input found after meshing leaves no directory behind.

usage: test_output_directory.py VIBROTHERM"""
import os, signal, socket, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, one_line_error, outputs

exe = os.path.abspath(sys.argv[1])
check = Checks("output_directory")
# A small cracked square (heat runs): a few seconds (long enough that a signal sent
# 0.2 s into the waves lands before they end).
SCENE = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.002", "-mesh_h_crack", "0.001",
         "-crack_center", "0.01,0.01", "-crack_length", "0.006", "-crack_angle", "20", "-final_time", "3e-3",
         "-wave_degree", "1"]
LOCK = "vibrotherm.lock"


def run(args, cwd=None):
    r = subprocess.run([exe] + SCENE + args, capture_output=True, text=True, cwd=cwd, timeout=300)
    return r.returncode, r.stdout, r.stderr


def one_line_refusal(label, code, err, *words):
    one_line_error(check, label, code, err, *words)


def wait_for(path, process, seconds=60):
    deadline = time.time() + seconds
    while not os.path.exists(path) and process.poll() is None and time.time() < deadline:
        time.sleep(0.01)
    return os.path.exists(path)


def complete(out):
    try:
        return outputs(out).summary["complete"] is True
    except (OSError, ValueError, KeyError):
        return False


with tempfile.TemporaryDirectory() as tmp:
    # --- two runs into one directory ---------------------------------------------------------
    out = os.path.join(tmp, "shared")
    first = subprocess.Popen([exe] + SCENE + ["-output_dir", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)
    if wait_for(os.path.join(out, LOCK), first):
        first.send_signal(signal.SIGSTOP)  # holds the directory, mid-run
        before = sorted(os.listdir(out))
        code, _, err = run(["-output_dir", out])
        one_line_refusal("second run", code, err, "pid %d" % first.pid, socket.gethostname())
        check(sorted(os.listdir(out)) == before, "second run: the directory untouched (%s -> %s)"
              % (before, sorted(os.listdir(out))))
        first.send_signal(signal.SIGCONT)
    else:
        check.fail("first run: no %s while it runs" % LOCK)
    _, err = first.communicate(timeout=300)
    check(first.returncode == 0 and complete(out), "first run: exit 0, complete (%s)" % err[-300:])
    check(not os.path.exists(os.path.join(out, LOCK)), "first run: its lock removed at the end")

    # --- a crashed run's lock: taken over; another host's: refused ------------------------------
    dead = subprocess.Popen(["true"])
    dead.wait()  # its pid is free now
    with open(os.path.join(out, LOCK), "w") as f:
        f.write("%d %s\n" % (dead.pid, socket.gethostname()))
    code, stdout, err = run(["-output_dir", out, "-overwrite"])
    check(code == 0 and complete(out), "stale lock: the run goes on (%s)" % err[-300:])
    check("no longer runs" in stdout and "taken over" in stdout, "stale lock: a note says it was taken over")
    check(not os.path.exists(os.path.join(out, LOCK)), "stale lock: no lock left after the run")
    with open(os.path.join(out, LOCK), "w") as f:
        f.write("4242 another-host.example\n")
    code, _, err = run(["-output_dir", out, "-overwrite"])
    one_line_refusal("another host's lock", code, err, "another-host.example", os.path.join(out, LOCK))
    os.remove(os.path.join(out, LOCK))

    # --- a complete run's results: never overwritten without -overwrite ---------------------------
    def files(d):
        return {n: (os.path.getsize(os.path.join(d, n)), os.path.getmtime(os.path.join(d, n))) for n in os.listdir(d)}
    before = files(out)
    code, stdout, err = run(["-output_dir", out])
    one_line_refusal("a run into a complete run's directory", code, err, "-output_dir", "complete run", "-overwrite")
    check(files(out) == before, "a complete run's results untouched (%s)" % sorted(set(before) ^ set(files(out))))
    check("Meshing" not in stdout, "a complete run's directory: refused before meshing")
    code, stdout, err = run(["-output_dir", out, "-overwrite"])
    check(code == 0 and complete(out) and "-overwrite: removed" in stdout,
          "-overwrite replaces a complete run's results (%s)" % err[-300:])

    # --- checks before meshing -------------------------------------------------------------------
    a_file = os.path.join(tmp, "a_file")
    open(a_file, "w").write("not a directory\n")
    code, stdout, err = run(["-output_dir", a_file])
    one_line_refusal("a file as -output_dir", code, err, a_file, "not a directory")
    check("Meshing" not in stdout, "a file as -output_dir: refused before meshing")
    # A directory that cannot be made (root may write anywhere but in /sys; others not under a 0555 directory).
    if os.geteuid() == 0:
        unwritable = "/sys/vibrotherm_test_output"
    else:
        locked = os.path.join(tmp, "locked")
        os.makedirs(locked)
        os.chmod(locked, 0o555)
        unwritable = os.path.join(locked, "out")
    code, stdout, err = run(["-output_dir", unwritable])
    one_line_refusal("an unwritable -output_dir", code, err, unwritable)
    check("Meshing" not in stdout, "an unwritable -output_dir: refused before meshing")
    far = os.path.join(tmp, "far")
    code, stdout, err = run(["-output_dir", far, "-source_frequency", "1e9"])
    one_line_refusal("-source_frequency 1e9", code, err, "-source_frequency")
    check("Meshing" not in stdout and not os.path.exists(far), "-source_frequency 1e9: refused before meshing, "
          "nothing written")
    # Bad input found only once meshed (a probe outside the specimen) leaves no directory behind.
    late = os.path.join(tmp, "late")
    code, stdout, err = run(["-output_dir", late, "-probe_points", "0.03,0.01"])
    one_line_refusal("a probe outside the specimen", code, err, "-probe_points")
    check(not os.path.exists(late), "bad input found after meshing: the directory made for the run removed")

    # Two runs started together: the second starts while the first meshes (held still there with
    # SIGSTOP); the lock is taken before meshing, so the second is refused before it meshes.
    together = os.path.join(tmp, "together")
    first = subprocess.Popen([exe] + SCENE + ["-output_dir", together], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
    meshing = False
    for line in first.stdout:
        if line.startswith("Meshing"):
            first.send_signal(signal.SIGSTOP)
            meshing = True
            break
    if meshing:
        code, stdout, err = run(["-output_dir", together])
        one_line_refusal("the second of two runs started together", code, err, "pid %d" % first.pid)
        check("Meshing" not in stdout, "the second of two runs started together: refused before meshing")
        first.send_signal(signal.SIGCONT)
    else:
        check.fail("two runs started together: the first never meshed")
    first.communicate(timeout=300)

    # 3D: the directory and its lock exist before the harmonic start (and before meshing).
    box = os.path.join(tmp, "box")
    p = subprocess.Popen([exe, "-specimen_width", "0.02", "-specimen_height", "0.02", "-specimen_depth", "0.01",
                          "-mesh_h", "0.004", "-crack_center", "0.01,0.01,0.005", "-crack_length", "0.006",
                          "-crack_width", "0.004", "-mesh_h_crack", "0.002", "-crack_a0", "1e-8",
                          "-wave_start", "harmonic", "-final_time", "2e-5", "-output_dir", box],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    locked_first = None
    for line in p.stdout:
        if locked_first is None and (line.startswith("Meshing") or line.startswith("Harmonic start")):
            locked_first = os.path.exists(os.path.join(box, LOCK))
    p.wait()
    check(p.returncode == 0 and locked_first is True,
          "3D harmonic start: the output directory locked before meshing and the harmonic start (exit %d, %s)"
          % (p.returncode, locked_first))

    # --- a run without -restart after an interruption ------------------------------------------
    out = os.path.join(tmp, "interrupted")
    p = subprocess.Popen([exe] + SCENE + ["-output_dir", out, "-checkpoint_every_s", "0"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    if wait_for(os.path.join(out, "energy.csv.partial"), p):
        time.sleep(0.2)  # the waves are running
        p.send_signal(signal.SIGUSR1)
    p.communicate(timeout=300)
    check(p.returncode == 128 + signal.SIGUSR1 and os.path.exists(os.path.join(out, "checkpoint.h5")),
          "interrupted run: exit %d with a checkpoint" % p.returncode)
    before = {n: os.path.getsize(os.path.join(out, n)) for n in os.listdir(out)}
    code, _, err = run(["-output_dir", out])
    one_line_refusal("run without -restart", code, err, "checkpoint", "-restart", "-overwrite")
    after = {n: os.path.getsize(os.path.join(out, n)) for n in os.listdir(out)}
    check(after == before, "run without -restart: nothing deleted or changed (%s)" % sorted(set(before) ^ set(after)))
    # The same directory spelt two ways: relative to the working directory, and absolute.
    code, _, err = run(["-restart", "interrupted", "-output_dir", os.path.abspath(out)], cwd=tmp)
    check(code == 0 and complete(out), "restart, relative and absolute spellings: exit 0, complete (%s)" % err[-300:])
    check(not os.path.exists(os.path.join(out, "checkpoint.h5")), "restart: the complete run removed its checkpoint")

    out = os.path.join(tmp, "overwritten")
    p = subprocess.Popen([exe] + SCENE + ["-output_dir", out, "-checkpoint_every_s", "0"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    if wait_for(os.path.join(out, "energy.csv.partial"), p):
        time.sleep(0.2)
        p.send_signal(signal.SIGUSR1)
    p.communicate(timeout=300)
    code, _, err = run(["-output_dir", out, "-overwrite"])
    check(code == 0 and complete(out) and not os.path.exists(os.path.join(out, "checkpoint.h5")),
          "-overwrite: the new run replaces the interrupted one (%s)" % err[-300:])

check.finish()
