#!/usr/bin/python3
"""Requirement: a short run of the paper scene (waves, MMD contact, heat) writes probes.csv,
energy.csv, fields.h5/fields_<grid>.xmf and summary.json; the 2-rank probe series (displacements,
crack tractions, temperatures) equal the serial ones to 1e-10 of their amplitude; the
energy budget closes (velocity Verlet); the heat deposited equals the energy the
interface dissipated to 1e-12 and the heat content equals deposited minus boundary
loss to 1e-3; the summary says which physics ran.

usage: test_wave_scene.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("wave scene")
probes = "0.025,0.099,0.025,0.03,0.01,0.05,0.04,0.07"
runs = {}
with tempfile.TemporaryDirectory() as tmp:
    for ranks in (1, 2):
        out = os.path.join(tmp, "np%d" % ranks)
        cmd = [mpiexec, "-n", str(ranks), "--oversubscribe", exe, "-options_file", os.path.join(src, "options/paper.opts"),
               "-final_time", "3e-5", "-output_times", "1e-5,3e-5", "-probe_points", probes, "-probe_every", "10", "-crack_probe", "0.5,0.2",
               "-output_dir", out]
        r = subprocess.run(cmd, capture_output=True, text=True)
        check(r.returncode == 0, "run on %d ranks: %s" % (ranks, r.stderr[-2000:]))
        if r.returncode:
            continue
        rows = outputs(out).rows("probes.csv")
        energy = outputs(out).rows("energy.csv")
        summary = outputs(out).summary
        runs[ranks] = (rows, energy, summary)
        check(summary["physics_ran"] == ["wave", "contact", "heat"], "physics_ran %s" % summary["physics_ran"])
        dissipated, deposited = summary["dissipated_energy"], summary["heat_deposited"]
        check(dissipated > 0 and abs(deposited - dissipated) <= 1e-12 * dissipated,
              "heat deposited %r vs dissipated %r" % (deposited, dissipated))
        for e in energy:
            dep, content, loss = (float(e[k]) for k in ("heat_deposited", "heat_content", "heat_boundary_loss"))
            if dep > 1e-3 * deposited:
                check(abs(content - (dep - loss)) <= 1e-3 * dep, "t=%s: heat content %g vs deposited-loss %g"
                      % (e["t"], content, dep - loss))
        check(all(float(e["heat_deposited"]) <= float(e["dissipated"]) * (1 + 1e-12) for e in energy),
              "heat is never deposited before it is dissipated")
        check(max(float(r["temperature"]) for r in rows if r["probe"] == "4") > 293.15, "crack centre heats")
        for name in ("fields.h5", "fields_wave.xmf", "fields_heat.xmf", "fields_cracks.xmf"):
            check(os.path.exists(os.path.join(out, name)), name + " written")
        # A buried crack of F facets has F − 1 interior vertex pairs, plus F edge-node pairs with Q2.
        facets = summary["mesh"]["cracks"][0]["facets"]
        degree = int(summary["options"].split("-wave_degree ")[1].split()[0])
        expected = facets - 1 + (facets if degree == 2 else 0)
        check(summary["contact_cells"] == expected, "contact cells %s, expected %d" % (summary["contact_cells"], expected))
        check(summary["steps_wave"] > 100, "steps_wave %s" % summary["steps_wave"])
        # budget_error divides by the work done so far: ill-conditioned in the first
        # steps (work ~1e-9 J/m); 1 % overall (issue 7), 1e-3 once 2 % of the run is done.
        check(summary["max_budget_error"] < 1e-2, "budget error %s" % summary["max_budget_error"])
        late = [abs(float(e["budget_error"])) for e in energy if float(e["t"]) > 0.02 * 3e-5]
        check(max(late) < 1e-3, "budget error after the start %s" % max(late))
        check(float(energy[-1]["work_source"]) > 0, "the source did work")
        check(len(rows) == 6 * (summary["steps_wave"] // 10), "probe rows %d" % len(rows))
        check(os.path.exists(os.path.join(out, "crack_state.csv")), "crack_state.csv written")

# The summary's budget error is a property of the run, not of how often energy
# rows are written (rows every step vs every 50 steps, waves alone).
with tempfile.TemporaryDirectory() as tmp:
    errors = {}
    for every in (1, 50):
        out = os.path.join(tmp, "every%d" % every)
        r = subprocess.run([exe, "-options_file", os.path.join(src, "options/paper.opts"), "-final_time", "3e-5",
                            "-heat", "off", "-crack_state_every", "0", "-energy_every", str(every), "-output_dir", out],
                           capture_output=True, text=True)
        check(r.returncode == 0, "energy rows every %d steps: %s" % (every, r.stderr[-2000:]))
        if r.returncode == 0:
            errors[every] = outputs(out).summary["max_budget_error"]
    if len(errors) == 2:
        check(errors[1] < 1e-5 and abs(errors[1] - errors[50]) <= 0.1 * errors[1],
              "budget error with rows every step %g vs every 50 steps %g" % (errors[1], errors[50]))

if 1 in runs and 2 in runs:
    a, b = runs[1][0], runs[2][0]
    check(len(a) == len(b), "row counts differ: %d vs %d" % (len(a), len(b)))
    point = [(x, y) for x, y in zip(a, b) if int(x["probe"]) < 4]
    crack = [(x, y) for x, y in zip(a, b) if int(x["probe"]) >= 4]
    for col in ("ux", "uy", "vx", "vy", "temperature"):
        base = 293.15 if col == "temperature" else 0.0
        pairs = list(zip(a, b)) if base else point
        scale = max(abs(float(x[col]) - base) for x, _ in pairs) or 1.0
        worst = max(abs(float(x[col]) - float(y[col])) for x, y in pairs) / scale
        check(worst <= 1e-10, "%s: 2 ranks differ from serial by %.3g of the amplitude" % (col, worst))
    check(len(crack) > 0, "crack probe rows")
    for col in ("a", "b", "N", "T", "W"):
        scale = max(abs(float(x[col])) for x, _ in crack) or 1.0
        worst = max(abs(float(x[col]) - float(y[col])) for x, y in crack) / scale
        check(worst <= 1e-9, "crack %s: 2 ranks differ from serial by %.3g of its amplitude" % (col, worst))
    check(all(x["state"] == y["state"] for x, y in crack), "crack states differ between 1 and 2 ranks")
    check(all(float(x["t"]) == float(y["t"]) for x, y in zip(a, b)), "probe times differ")
check.finish()
