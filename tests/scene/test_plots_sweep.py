#!/usr/bin/python3
"""Requirement: scripts/plot never crashes and covers what ran; scripts/sweep reports
a failed case in its row.
  * a run shorter than the source (-final_time 2e-4 of the paper scene, coarse) plots
    without error: exit 0, the PNGs of what it produced, "skipped <name>.png: <why>"
    for the others (no fields within the run, no -modes); no traceback;
  * a two-crack scene (meshes/plate_two_cracks.msh) covers both cracks under the
    mesh's names (crack_a, crack_b) and draws its temperature maps;
  * a -modes run draws modes.png and skips the rest;
  * a 3D run (block3d_small with an elliptical crack) draws its traction loop (the centre
    cell's strike component), its energy budget and crack_maps.png (W, friction power,
    contact and temperature on the crack plane) and skips the 2D crack plots;
  * (issue 27) temperature_maps.png shows, below each map, the rise across the crack
    through its hottest point, zoomed to the heated band (a band of µm to mm is
    invisible at the crack's scale); an interrupted run's plots say it is incomplete
    (and draw what its .partial files hold); the two-crack scene runs with paper.opts
    without -allow_unknown;
  * a sweep of 2 tiny cases, one with a bad value: exit 1, sweep.csv has one row per
    case, a column per option, and the failed case's row holds vibrotherm's error line.

usage: test_plots_sweep.py VIBROTHERM SOURCE_DIR"""
import csv, importlib.machinery, importlib.util, os, signal, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe, src = sys.argv[1:3]
check = Checks("plots and sweep")
plot_script, sweep_script = os.path.join(src, "scripts", "plot"), os.path.join(src, "scripts", "sweep")
paper = ["-options_file", os.path.join(src, "options", "paper.opts")]
coarse = ["-mesh_h", "0.004", "-mesh_h_crack", "0.001", "-wave_degree", "1"]


def run(args, out):
    r = subprocess.run([exe] + args + ["-output_dir", out], capture_output=True, text=True)
    check(r.returncode == 0, "run %s: %s" % (os.path.basename(out), r.stderr[-800:]))


def plot(out, expected, skipped):
    r = subprocess.run(["/usr/bin/python3", plot_script, out], capture_output=True, text=True)
    name = os.path.basename(out)
    check(r.returncode == 0 and "Traceback" not in r.stderr, "plot %s: exit %d, %s" % (name, r.returncode,
                                                                                      r.stderr[-1500:]))
    pngs = sorted(f[:-4] for f in os.listdir(out) if f.endswith(".png"))
    check(pngs == sorted(expected), "plot %s: made %s, expected %s" % (name, pngs, sorted(expected)))
    for s in skipped:
        check("skipped %s.png: " % s in r.stdout, "plot %s: no 'skipped %s.png' message in %r" % (name, s, r.stdout))
    return r


with tempfile.TemporaryDirectory() as tmp:
    short = os.path.join(tmp, "short")
    run(paper + coarse + ["-final_time", "2e-4"], short)
    plot(short, ["traction_loop", "crack_temperature", "energy_budget", "crack_spacetime", "source_power"],
         ["temperature_maps", "modes", "crack_maps"])

    two = os.path.join(tmp, "two")
    run(paper + ["-mesh_file", os.path.join(src, "meshes", "plate_two_cracks.msh"), "-wave_degree",
                 "1", "-final_time", "1e-4", "-source_duration", "1e-4", "-output_times", "5e-5,1e-4",
                 "-crack_probe_crack", "2"], two)
    plot(two, ["traction_loop", "crack_temperature", "temperature_maps", "energy_budget", "crack_spacetime",
               "source_power"],
         ["modes", "crack_maps"])
    loader = importlib.machinery.SourceFileLoader("plot_script", plot_script)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader("plot_script", loader))
    loader.exec_module(module)
    r2 = module.Run(two)
    check(r2.crack_names == ["crack_a", "crack_b"], "crack names %s" % r2.crack_names)
    series = module.centre_series(r2)
    check(sorted(series) == [1, 2], "traction loops of cracks %s, expected 1 and 2" % sorted(series))
    check(sorted(module.crack_polylines(r2)) == [1, 2], "temperature maps draw cracks %s"
          % sorted(module.crack_polylines(r2)))
    figure = module.plot_temperature_maps(r2)
    profiles = [ax for ax in figure.axes if ax.get_xlabel().startswith("distance across the crack")]
    check(len(profiles) == 2, "temperature maps: a profile across the crack below each map (%d)" % len(profiles))
    for ax in profiles:  # the crack is 12 mm long: the heated band of 0.1 ms is ~0.1 mm thick
        low, high = ax.get_xlim()
        span = (high - low) * (1e-6 if "[µm]" in ax.get_xlabel() else 1e-3)
        check(span < 2e-3, "the profile zooms to the heated band: %s from %g to %g" % (ax.get_xlabel(), low, high))

    interrupted = os.path.join(tmp, "interrupted")
    # The source on for all of it: with the paper's 1 ms, the run could end within the 1 s wait below.
    p = subprocess.Popen([exe] + paper + coarse + ["-final_time", "5e-3", "-source_duration", "5e-3", "-checkpoint_every_s", "0",
                                                  "-output_dir", interrupted], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while not os.path.exists(os.path.join(interrupted, "crack_state.csv.partial")) and time.time() < deadline:
        time.sleep(0.05)
    time.sleep(1.0)  # a few periods of rubbing
    p.send_signal(signal.SIGUSR1)
    p.communicate()
    r = subprocess.run(["/usr/bin/python3", plot_script, interrupted], capture_output=True, text=True)
    check(r.returncode == 0 and "INCOMPLETE RUN" in r.stdout and "-restart" in r.stdout,
          "plot of an interrupted run: says it is incomplete (exit %d, %r)" % (r.returncode, r.stdout[-500:]))
    check(os.path.exists(os.path.join(interrupted, "energy_budget.png")),
          "plot of an interrupted run: draws what its .partial files hold")

    modes = os.path.join(tmp, "modes")
    run(paper + coarse + ["-modes", "-modes_n", "4"], modes)
    plot(modes, ["modes"], ["traction_loop", "crack_temperature", "temperature_maps", "energy_budget",
                            "crack_spacetime", "crack_maps", "source_power"])

    box = os.path.join(tmp, "box")
    run(["-options_file", os.path.join(src, "options", "block3d_small.opts"), "-crack_shape", "ellipse",
         "-output_times", "2e-5"], box)
    plot(box, ["traction_loop", "energy_budget", "crack_maps", "source_power"],
         ["crack_temperature", "temperature_maps", "crack_spacetime", "modes"])

    sweep = os.path.join(tmp, "sweep")
    r = subprocess.run(["/usr/bin/python3", sweep_script, "--no-build", "--output", sweep, "--set", "final_time=1e-5",
                        "--set", "mesh_h=0.004", "--set", "mesh_h_crack=0.001", "--set", "wave_degree=1",
                        "--vary", "source_amplitude=1e-7,abc"],
                       capture_output=True, text=True, env=dict(os.environ, VIBROTHERM_BUILD_DIR=os.path.dirname(exe)))
    check(r.returncode == 1, "sweep with a bad case: exit %d (expected 1), %s" % (r.returncode, r.stderr[-800:]))
    check("case 2/2" in r.stdout and "ETA" in r.stdout, "sweep progress: %r" % r.stdout[-600:])
    rows = list(csv.DictReader(open(os.path.join(sweep, "sweep.csv")))) if os.path.exists(
        os.path.join(sweep, "sweep.csv")) else []
    check(len(rows) == 2, "sweep.csv: %d rows" % len(rows))
    if len(rows) == 2:
        good, bad = rows
        check(good["status"] == "ok" and good["error"] == "" and float(good["dofs_wave"]) > 0,
              "good case: %s" % good)
        check(good["source_amplitude"] == "1e-7" and bad["source_amplitude"] == "abc" and good["mesh_h"] == "0.004",
              "option columns: %s" % good)
        check(bad["status"].startswith("failed") and "-source_amplitude: expected a number, got 'abc'" in bad["error"],
              "bad case's row: %s" % bad)
        for column in ("field_max_temperature_rise", "camera_peak_snr"):
            check(column in good, "sweep.csv has no %s column" % column)
check.finish()
