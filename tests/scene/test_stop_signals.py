#!/usr/bin/python3
"""Requirement (issue 43, item 2): stopping a run never loses it silently.

- SIGTERM and SIGINT sent to mpiexec (as timeout, schedulers and Ctrl-C do) while a 3D run
  on 2 ranks steps: Open MPI's mpiexec does not forward them; it sends each rank SIGCONT,
  1 s later SIGTERM, 1 s later SIGKILL (odls_base_sigkill_timeout). The coupling intervals
  here are long (a few seconds each, -couple_dt spanning 1200 wave steps) and the signal comes
  right after a checkpoint, so the next interval is out of reach: the ranks must end before
  the SIGKILL with one line saying where -restart resumes, leave no lock, and leave a
  checkpoint from which -restart finishes the run bit for bit as the run never stopped
  (energy.csv, probes.csv, every summary figure). Before: the ranks were killed without a
  word, the lock left behind. (mpiexec itself exits 1 after it was signalled: Open MPI's
  status for a job it ended, whatever the ranks return; scripts/run exits 128 + the signal.)
  The same for SIGINT to mpiexec in 2D.
- Ctrl-C (SIGINT) while the run sets up (meshing, -modes, the harmonic start): one line
  "SIGINT during <phase>", exit 130, nothing left behind (before: silent).
- A restart of a harmonic start does not redo the harmonic start's factorisation (its state is
  the checkpoint's) and finishes bit for bit as the run never stopped.
- A restart with other options names the option that differs, on both sides (before: it
  paired unrelated options, "checkpoint '-source_amplitude=1e-07', now '-periodic_tol=0.003'").

usage: test_stop_signals.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, signal, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, one_line_error
import restart_compare
from restart_compare import compare_exact, why

exe, src, mpiexec = sys.argv[1:4]
check = Checks("stop_signals")
LOCK = "vibrotherm.lock"
# A coarse block3d_small (8766 dofs) whose coupling interval is 1200 wave steps (seconds on 2 ranks).
INTERVAL = 5e-5
BOX = ["-options_file", os.path.join(src, "options/block3d_small.opts"), "-mesh_h", "0.003", "-mesh_h_crack", "0.002",
       "-source_frequency", "1.5e5", "-source_duration", "4e-4", "-final_time", "4e-4", "-couple_dt", repr(INTERVAL),
       "-checkpoint_every_s", "0.01"]  # a checkpoint at every interval's end; 7 intervals left after the first:
# Open MPI's mpiexec forwards SIGTERM a while after its SIGCONT, which a 0.3 s rest of the run outlasted on idle cores
PLATE = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.002", "-mesh_h_crack", "0.001",
         "-crack_center", "0.01,0.01", "-crack_length", "0.006", "-crack_angle", "20", "-wave_degree", "1",
         "-crack_a0", "1e-8", "-probe_points", "0.01,0.015", "-crack_probe", "0.5",
         "-petscpartitioner_type", "metis"]  # the same partition every run (bit-identical restarts)


def parallel(args):
    return [mpiexec, "-n", "2", "--oversubscribe", exe] + args


def stop_mpiexec(args, out, after, how):
    """Runs args on 2 ranks into out, sends `how` to mpiexec once a checkpoint at t >= after is on
    disk; mpiexec's exit status and stderr."""
    p = subprocess.Popen(parallel(args + ["-output_dir", out]), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    deadline = time.time() + 300
    while restart_compare.checkpoint_time(out) < after and p.poll() is None and time.time() < deadline:
        time.sleep(0.02)
    p.send_signal(how)
    stdout, err = p.communicate(timeout=120)
    return p.returncode, stdout + err


def check_stopped(label, out, code, out_text, after):
    """The ranks' SIGTERM line (on stdout when the run stopped at an interval, stderr when at once)."""
    lines = [l for l in out_text.splitlines() if l.startswith("vibrotherm: SIGTERM")]
    check(code != 0, "%s: mpiexec exits non-zero (%d)" % (label, code))
    check(len(lines) == 1 and "-restart %s resumes from its checkpoint at t = " % out in lines[0],
          "%s: one line saying where -restart resumes (%s)" % (label, err[-600:]))
    check(not os.path.exists(os.path.join(out, LOCK)), "%s: no lock left" % label)
    check(restart_compare.checkpoint_time(out) >= after * (1 - 1e-9), "%s: a checkpoint at t >= %g" % (label, after))


def restart_equals(label, ref, out, args):
    r = subprocess.run(parallel(args + ["-restart", out]), capture_output=True, text=True)
    check(r.returncode == 0, "%s: the restart finishes (%s)" % (label, why(r.stderr)))
    if r.returncode == 0:
        compare_exact(check, ref, out, label, ["energy.csv", "probes.csv"], [])
    return r


def setup_interrupted(label, args, out, phase_line, phase):
    """Ctrl-C once stdout shows phase_line: one line naming the phase, exit 130, out not left behind."""
    p = subprocess.Popen([exe] + args + ["-output_dir", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True)
    for line in p.stdout:
        if line.startswith(phase_line):
            p.send_signal(signal.SIGINT)
            break
    _, err = p.communicate(timeout=300)
    lines = [l for l in err.splitlines() if l.strip()]
    check(p.returncode == 128 + signal.SIGINT and len(lines) == 1 and lines[0].startswith("vibrotherm: SIGINT during ")
          and phase in lines[0], "%s: exit 130 and one line 'SIGINT during %s' (exit %d: %s)"
          % (label, phase, p.returncode, err[-400:]))
    check(not os.path.exists(out), "%s: nothing left behind (%s)" % (label, os.listdir(out) if os.path.exists(out) else ""))


with tempfile.TemporaryDirectory() as tmp:
    # --- SIGTERM and SIGINT to mpiexec, 3D and 2D ---------------------------------------------------
    ref = os.path.join(tmp, "box_ref")
    r = subprocess.run(parallel(BOX + ["-output_dir", ref]), capture_output=True, text=True)
    check(r.returncode == 0, "3D reference run (%s)" % why(r.stderr))
    for how in (signal.SIGTERM, signal.SIGINT):
        name = signal.Signals(how).name
        out = os.path.join(tmp, "box_" + name)
        code, err = stop_mpiexec(BOX, out, INTERVAL, how)
        check_stopped("3D, %s to mpiexec" % name, out, code, err, INTERVAL)
        restart_equals("3D, %s to mpiexec, restarted" % name, ref, out, BOX)
    # Waves for 4 ms (~3 s): mpiexec forwards its stop a while after the signal, which the waves must outlast.
    plate = PLATE + ["-source_duration", "4e-3", "-final_time", "4e-3", "-checkpoint_every_s", "0.01", "-couple_dt",
                     "5e-5"]
    ref = os.path.join(tmp, "plate_ref")
    r = subprocess.run(parallel(plate + ["-output_dir", ref]), capture_output=True, text=True)
    check(r.returncode == 0, "2D reference run (%s)" % why(r.stderr))
    out = os.path.join(tmp, "plate_SIGINT")
    code, err = stop_mpiexec(plate, out, 5e-5, signal.SIGINT)
    check_stopped("2D, SIGINT to mpiexec", out, code, err, 5e-5)
    restart_equals("2D, SIGINT to mpiexec, restarted", ref, out, plate)

    # --- Ctrl-C while the run sets up ------------------------------------------------------------------
    setup_interrupted("Ctrl-C while meshing", PLATE, os.path.join(tmp, "meshing"), "Meshing with gmsh", "meshing")
    setup_interrupted("Ctrl-C in -modes", PLATE + ["-modes"], os.path.join(tmp, "modes"), "Modes: MUMPS estimates",
                      "the natural modes")
    # 0.1 ms took 0.06 s of waves: over before a checkpoint at 30 µs was seen one time in two; 1 ms leaves time.
    harmonic = PLATE + ["-wave_start", "harmonic", "-final_time", "1e-3"]
    setup_interrupted("Ctrl-C in the harmonic start", harmonic, os.path.join(tmp, "harmonic"),
                      "Harmonic start: MUMPS estimates", "")  # the factorisation of a small plate may be over by then

    # --- a restart of a harmonic start does not factor again ---------------------------------------------
    ref = os.path.join(tmp, "harmonic_ref")
    r = subprocess.run([exe] + harmonic + ["-output_dir", ref], capture_output=True, text=True)
    check(r.returncode == 0 and "Harmonic start: MUMPS estimates" in r.stdout,
          "harmonic start: the run factors (%s)" % why(r.stderr))
    out = os.path.join(tmp, "harmonic_stopped")
    code, err = restart_compare.interrupted([exe] + harmonic + ["-output_dir", out, "-checkpoint_every_s", "0.01"],
                                            exe, out, 3e-5)
    check(code == 128 + signal.SIGUSR1, "harmonic start: stopped by SIGUSR1 (exit %d: %s)" % (code, why(err)))
    r = subprocess.run([exe] + harmonic + ["-restart", out], capture_output=True, text=True)
    check(r.returncode == 0 and "Harmonic start" not in r.stdout,
          "harmonic start: the restart does not factor again (exit %d: %s)" % (r.returncode, r.stdout[-800:]))
    if r.returncode == 0:
        compare_exact(check, ref, out, "harmonic start restarted", ["energy.csv", "probes.csv"], [])

    # --- a restart with other options names the one that differs ------------------------------------------
    out = os.path.join(tmp, "other_options")
    code, err = restart_compare.interrupted([exe] + PLATE + ["-final_time", "2e-4", "-source_amplitude", "1e-7",
                                                             "-output_dir", out, "-checkpoint_every_s", "0.01"],
                                            exe, out, 2e-5)
    base = PLATE + ["-final_time", "2e-4", "-source_amplitude", "1e-7"]
    for extra, words in [(["-periodic_tol", "0.003"], ["-periodic_tol: not given in the checkpoint, 0.003 now"]),
                         (["-source_amplitude", "2e-7"], ["-source_amplitude: 1e-07 in the checkpoint, 2e-07 now"])]:
        r = subprocess.run([exe] + base + extra + ["-restart", out], capture_output=True, text=True)
        one_line_error(check, "restart with %s" % " ".join(extra), r.returncode, r.stderr, *words)
check.finish()
