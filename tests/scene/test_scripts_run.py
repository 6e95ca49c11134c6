#!/usr/bin/python3
"""Requirement (issue 43, items 2, 3, 8): scripts/run, the command a user starts with.

- Run from another directory with an options file there that includes a file beside it
  (-options_file ../base.opts): it finds both (before: the script checked the file, then
  changed to the repository's root, and an include was read relative to the working
  directory), and writes results/<stem>/ under that directory, plots included.
- Run again into the same directory: refused (exit 2, one line naming -overwrite), the first
  run's results untouched, no plots redrawn (before: "removed 8 outputs of an earlier run").
- SIGTERM to scripts/run while the run steps (timeout, a scheduler): the run writes a
  checkpoint and stops, no lock left, the script exits 128 + 15 (before: mpiexec's 1, or the
  ranks killed); -restart continues it to the end.

usage: test_scripts_run.py SOURCE_DIR BUILD_DIR"""
import json, os, signal, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs
import restart_compare

src, build = (os.path.abspath(a) for a in sys.argv[1:3])
check = Checks("scripts_run")
run_script = os.path.join(src, "scripts", "run")
environment = dict(os.environ, VIBROTHERM_BUILD_DIR=build, VIBROTHERM_RANKS="2")
BASE = """# a small plate with a crack (the shared part of a study's scenes)
-specimen_width 0.02
-specimen_height 0.02
-mesh_h 0.002
-mesh_h_crack 0.001
-crack_center 0.01,0.01
-crack_length 0.006
-crack_angle 20
-wave_degree 1
-petscpartitioner_type metis
"""


def files(d):
    return {n: (os.path.getsize(os.path.join(d, n)), os.path.getmtime(os.path.join(d, n))) for n in os.listdir(d)}


with tempfile.TemporaryDirectory() as tmp:
    study = os.path.join(tmp, "study")
    os.makedirs(os.path.join(study, "scenes"))
    open(os.path.join(study, "base.opts"), "w").write(BASE)
    open(os.path.join(study, "scenes", "plate.opts"), "w").write("-options_file ../base.opts\n-final_time 2e-4\n")

    # --- from another directory, an include beside the file -----------------------------------------
    r = subprocess.run([run_script, "scenes/plate.opts"], cwd=study, env=environment, capture_output=True, text=True)
    out = os.path.join(study, "results", "plate")
    summary = os.path.join(out, "summary.json")
    check(r.returncode == 0 and os.path.exists(summary) and json.load(open(summary))["complete"] is True,
          "scripts/run from another directory: exit 0, results/plate complete (exit %d: %s)"
          % (r.returncode, r.stderr[-600:]))
    check(os.path.exists(os.path.join(out, "energy_budget.png")), "scripts/run: the plots drawn")

    # --- again into the same directory ----------------------------------------------------------------
    before = files(out) if os.path.isdir(out) else {}
    r = subprocess.run([run_script, "scenes/plate.opts", "-source_amplitude", "2e-7"], cwd=study, env=environment,
                       capture_output=True, text=True)
    errors = [l for l in r.stderr.splitlines() if l.startswith("vibrotherm: error")]
    check(r.returncode == 2 and len(errors) == 1 and "-overwrite" in errors[0],
          "scripts/run into a finished run's directory: exit 2, one line naming -overwrite (exit %d: %s)"
          % (r.returncode, r.stderr[-600:]))
    check(files(out) == before if before else False, "scripts/run: the finished run's results untouched")

    # --- SIGTERM to the script while the run steps ------------------------------------------------------
    stopped = os.path.join(study, "stopped")
    p = subprocess.Popen([run_script, "scenes/plate.opts", "-final_time", "3e-3", "-checkpoint_every_s", "0.01",
                          "-output_dir", "stopped"], cwd=study, env=environment, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 300
    while restart_compare.checkpoint_time(stopped) < 1e-4 and p.poll() is None and time.time() < deadline:
        time.sleep(0.05)
    p.send_signal(signal.SIGTERM)
    stdout, err = p.communicate(timeout=300)
    check(p.returncode == 128 + signal.SIGTERM, "SIGTERM to scripts/run: exit 143 (exit %d: %s)"
          % (p.returncode, err[-600:]))
    check(restart_compare.checkpoint_time(stopped) >= 1e-4 and not os.path.exists(os.path.join(stopped, "vibrotherm.lock")),
          "SIGTERM to scripts/run: a checkpoint, no lock")
    check("resumes from its checkpoint" in stdout, "SIGTERM to scripts/run: the run says where it resumes")
    r = subprocess.run([run_script, "scenes/plate.opts", "-final_time", "3e-3", "-restart", "stopped"], cwd=study,
                       env=environment, capture_output=True, text=True)
    check(r.returncode == 0 and outputs(stopped).summary["complete"] is True,
          "scripts/run -restart: the run finishes (exit %d: %s)" % (r.returncode, r.stderr[-600:]))
check.finish()
