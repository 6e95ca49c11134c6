#!/usr/bin/python3
"""Requirement (issues 24 and 26): material damping and its heat in a 3D box.

A 10 x 10 x 6 mm aluminium box without a crack, held at its bottom face (fixed: C = alpha M would
also brake a free box's rigid drift, at 2 alpha), is struck by a short traction burst on its top
face and rings. With C = alpha M (alpha = eta 2 pi f_d) every mode loses energy at the rate alpha, so
the mechanical energy decays as exp(-alpha t) (closed form, fitted after the burst), and the energy
budget with its damping column closes to 1e-6. With -material_damping_heat (insulated faces) the
heat deposited equals the waves' own `damped` account (two independent sums: the waves' per step,
the heat's per heat step through the wave-to-heat transfer, whose columns each sum to one) and the
heat content equals what was deposited; the heat is deposited where the waves were damped, so it
is not uniform (the box's top, struck, heats more than its bottom). Two ranks give the serial
heat content and temperatures within 1e-10.

usage: test_material_damping_3d.py VIBROTHERM MPIEXEC"""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene, outputs

exe, mpiexec = sys.argv[1], sys.argv[2]
check = Checks("material damping, 3D")
eta, f_d = 0.02, 1e5
alpha = eta * 2 * math.pi * f_d
DAMPING = ["-material_loss_factor", str(eta), "-material_damping_frequency", str(f_d)]
PROBES = [0.005, 0.009, 0.003, 0.005, 0.001, 0.003]  # near the struck top face, near the bottom
BOX = ["-specimen_width", "0.01", "-specimen_height", "0.01", "-specimen_depth", "0.006", "-mesh_h", "0.002",
       "-wave_degree", "2", "-edge_top", "source", "-edge_bottom", "fixed", "-edge_left", "free", "-edge_right", "free",
       "-edge_front", "free", "-edge_back", "free", "-source_type", "traction", "-source_amplitude", "1e6",
       "-source_frequency", "1e5", "-source_duration", "3e-5", "-source_ramp_cycles", "1", "-final_time", "2e-4",
       "-energy_every", "10", "-wave_quiet_fraction", "0", "-probe_points", ",".join(map(str, PROBES)), "-probe_every", "10"]


def decay(out):
    """The ring's decay rate fitted after the burst, and the run's summary."""
    e = outputs(out).columns("energy.csv")
    s = outputs(out).summary
    mech = e["kinetic"] + e["strain"] + e["integrator_correction"]
    late = e["t"] > 6e-5
    return -np.polyfit(e["t"][late], np.log(mech[late]), 1)[0], e, s


def probe_rise(out):
    """Each probe's temperature rows (t, rise) after the waves."""
    p = outputs(out).columns("probes.csv")
    rows = {}
    for k in (0, 1):
        keep = (p["probe"] == k) & np.isfinite(p["temperature"].astype(float))
        rows[k] = (p["t"][keep].astype(float), p["temperature"][keep].astype(float) - 293.15)
    return rows


with tempfile.TemporaryDirectory() as tmp:
    ring = os.path.join(tmp, "ring")
    if run_scene(check, exe, BOX + DAMPING + ["-heat", "off"], ring):
        rate, e, s = decay(ring)
        print("3D ring: decay rate %.6g 1/s, closed form %.6g (%.3f %%); budget %.2g"
              % (rate, alpha, 100 * (rate / alpha - 1), s["max_budget_error"]))
        check(abs(rate / alpha - 1) < 5e-3, "the 3D ring decays at %g 1/s, alpha = %g" % (rate, alpha))
        check(s["max_budget_error"] < 1e-6, "budget error %g with the damping column" % s["max_budget_error"])
    heated = {}
    for ranks in (1, 2):
        out = os.path.join(tmp, "heated_np%d" % ranks)
        if not run_scene(check, exe, BOX + DAMPING + ["-material_damping_heat", "-heat_bc", "insulated",
                                                      "-final_time", "3e-4"], out, mpiexec, ranks):
            continue
        e = outputs(out).columns("energy.csv")
        s = outputs(out).summary
        heated[ranks] = (s, probe_rise(out))
        deposited = s["heat_deposited_by"].get("damping", 0.0)
        print("%d rank(s): damping heat deposited %.12g J, damped %.12g J, heat content %.12g J"
              % (ranks, deposited, e["damped"][-1], s["heat_content"]))
        check("heat" in s["physics_ran"], "%d rank(s): the damping heat starts the 3D heat without a crack" % ranks)
        check(deposited > 0 and abs(deposited / e["damped"][-1] - 1) < 1e-9,
              "%d rank(s): heat deposited %r = the waves' damped energy %r" % (ranks, deposited, e["damped"][-1]))
        check(abs(s["heat_content"] / deposited - 1) < 1e-9,
              "%d rank(s): insulated, heat content %r = deposited %r" % (ranks, s["heat_content"], deposited))
        top, bottom = heated[ranks][1][0][1][-1], heated[ranks][1][1][1][-1]
        check(top > bottom > 0, "%d rank(s): the struck top heats more than the bottom (%g, %g K)" % (ranks, top, bottom))
    if len(heated) == 2:
        (s1, p1), (s2, p2) = heated[1], heated[2]
        check(abs(s2["heat_content"] / s1["heat_content"] - 1) < 1e-10,
              "2 ranks: heat content %r against serial %r" % (s2["heat_content"], s1["heat_content"]))
        for k in (0, 1):
            scale = np.abs(p1[k][1]).max()
            same = len(p1[k][1]) == len(p2[k][1]) and np.abs(p1[k][1] - p2[k][1]).max() <= 1e-10 * scale
            check(same, "2 ranks: probe %d's temperature equals the serial one within 1e-10" % k)
check.finish()
