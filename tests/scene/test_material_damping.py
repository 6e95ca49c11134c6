#!/usr/bin/python3
"""Requirement (issue 24): material damping C = alpha M, alpha = eta 2 pi f_d (-material_loss_factor,
-material_damping_frequency). A free square without a crack is struck by a short traction burst on
its top edge and rings: every mode of a mass-proportionally damped body loses energy at the rate
alpha, so the mechanical energy decays as exp(-alpha t) (closed form), with the global step and
with local time stepping (damping in the kicks of each dof's own level); the energy budget with
its damping column closes to 1e-6 (global step); without
damping the same ring conserves its energy. With -material_damping_heat (insulated edges)
the heat deposited and the heat content equal the waves' own `damped` account to rounding
(two independent sums: the waves' per step, the heat's per heat step through the transfer),
the heat starting without a crack; refused without damping and with local time stepping.

usage: test_material_damping.py VIBROTHERM"""
import math, os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene, outputs

exe = sys.argv[1]
check = Checks("material damping")
eta, f_d = 0.02, 1e5
alpha = eta * 2 * math.pi * f_d
scene = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.002", "-wave_degree", "2",
         "-edge_top", "source", "-edge_bottom", "free", "-edge_left", "free", "-edge_right", "free",
         "-source_type", "traction", "-source_amplitude", "1e6", "-source_frequency", "1e5", "-source_duration", "3e-5",
         "-source_ramp_cycles", "1", "-final_time", "3e-4", "-energy_every", "10", "-heat", "off"]


def ring(out, extra):
    if not run_scene(check, exe, scene + extra, out):
        return None
    e = outputs(out).columns("energy.csv")
    return e, outputs(out).summary


with tempfile.TemporaryDirectory() as tmp:
    # Local time stepping needs cells of several sizes: an open crack (no contact) refines the mesh.
    graded = ["-crack_center", "0.01,0.01", "-crack_length", "0.006", "-crack_law", "open", "-mesh_h_crack", "5e-4"]
    for name, extra in (("global", []), ("lts", graded + ["-wave_lts", "on"])):
        damped = ring(os.path.join(tmp, name), ["-material_loss_factor", str(eta), "-material_damping_frequency",
                                               str(f_d)] + extra)
        if damped is None:
            continue
        e, s = damped
        check(name != "lts" or s["derived"].get("wave_lts_levels", 1) > 1, "lts: local time stepping did not run")
        mech = e["kinetic"] + e["strain"] + e["integrator_correction"]
        late = e["t"] > 6e-5  # after the burst
        slope = np.polyfit(e["t"][late], np.log(mech[late]), 1)[0]
        print("%s: decay rate %.6g 1/s, closed form %.6g (%.3f %%); damped %.4g of %.4g J/m worked; budget %.2g"
              % (name, -slope, alpha, 100 * (-slope / alpha - 1), e["damped"][-1], e["work_source"][-1],
                 s["max_budget_error"]))
        check(abs(-slope / alpha - 1) < 5e-3, "%s: energy decays at %g 1/s, alpha = %g" % (name, -slope, alpha))
        # LTS accounts only the leading part of its integrator's energy term (README): ~6e-3 on this ring undamped.
        check(s["max_budget_error"] < (1e-6 if name == "global" else 1e-2),
              "%s: budget error %g with the damping column" % (name, s["max_budget_error"]))
        check(abs(e["damped"][-1] / e["work_source"][-1] - (1 - mech[-1] / e["work_source"][-1])) < 1e-3,
              "%s: what the source did and the ring kept not split into damped energy" % name)
    free = ring(os.path.join(tmp, "undamped"), [])
    if free is not None:
        e, s = free
        mech = e["kinetic"] + e["strain"] + e["integrator_correction"]
        late = e["t"] > 6e-5
        check(np.ptp(mech[late]) < 1e-5 * mech[late].max() and e["damped"][-1] == 0.0,
              "without damping the ring keeps its energy (spread %g)" % (np.ptp(mech[late]) / mech[late].max()))
    # The damping heats the specimen: every joule the waves' account books arrives in the heat.
    heated = os.path.join(tmp, "heated")
    damping = ["-material_loss_factor", str(eta), "-material_damping_frequency", str(f_d)]
    if run_scene(check, exe, scene[:-2] + damping + ["-material_damping_heat", "-heat_bc", "insulated"], heated):
        e = outputs(heated).columns("energy.csv")
        s = outputs(heated).summary
        deposited = s["heat_deposited_by"].get("damping", 0.0)
        print("damping heat: deposited %.12g, damped %.12g, heat content %.12g J/m" %
              (deposited, e["damped"][-1], s["heat_content"]))
        check("heat" in s["physics_ran"], "the damping heat starts the heat solver without a crack")
        check(abs(deposited / e["damped"][-1] - 1) < 1e-9 and abs(e["heat_damping"][-1] / deposited - 1) < 1e-12,
              "heat deposited %r = the waves' damped energy %r" % (deposited, e["damped"][-1]))
        check(abs(s["heat_content"] / deposited - 1) < 1e-9, "insulated: heat content %r = deposited" % s["heat_content"])
    for label, extra, name in (("without damping", [], "-material_loss_factor"),
                               ("with local time stepping", damping + graded + ["-wave_lts", "on"], "-wave_lts")):
        r = subprocess.run([exe] + scene[:-2] + extra + ["-material_damping_heat", "-output_dir",
                                                         os.path.join(tmp, "refused")], capture_output=True, text=True)
        lines = r.stderr.strip().splitlines()
        check(r.returncode == 2 and len(lines) == 1 and name in lines[0],
              "-material_damping_heat %s: one line naming %s, exit 2 (%d: %s)" % (label, name, r.returncode, r.stderr))
check.finish()
