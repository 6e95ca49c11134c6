#!/usr/bin/python3
"""Requirement (issue 26): thermoelastic coupling in a 3D box, against the plane P wave's
closed form. A 10 x 100 x 10 mm aluminium column, its four long faces on rollers, a 100 nm
normal displacement at 100 kHz on the top face and an absorbing bottom: the wave is a plane
P wave running down (u_y = f(t + y/c), tr eps = v_y/c), so the temperature swings adiabatically
by dT = -T0 beta v_y / (rho c_p c), beta = (3 lambda + 2G) alpha_L (diffusion over a period,
about 12 um, is negligible), with the run's own velocity at the probe.
  * one way: c is the isothermal P speed; every probes.csv row after the front is within 1 %
    of the swing's amplitude, and fits it better than with the adiabatic speed;
  * two way (the thermal stress acts back on the waves): the wave runs at the adiabatic speed
    c_ad^2 = (lambda + 2G + beta^2 T0/(rho c_p))/rho (1.3 % faster), and the rows fit that
    closed form within 1.5 %, better than the isothermal one: the back-coupling is there;
  * the energy budget closes to 1e-6 in both, and 2 ranks give the serial temperatures.

usage: test_thermoelastic_3d.py VIBROTHERM MPIEXEC"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene, outputs
from aluminium import T0, beta, cp, rho
from aluminium import c_P as c_isothermal, c_P_adiabatic as c_adiabatic

exe, mpiexec = sys.argv[1:3]
check = Checks("thermoelastic, 3D")
COLUMN = ["-specimen_width", "0.01", "-specimen_height", "0.1", "-specimen_depth", "0.01", "-edge_top", "source",
          "-edge_bottom", "absorbing", "-edge_left", "roller", "-edge_right", "roller", "-edge_front", "roller",
          "-edge_back", "roller", "-source_frequency", "1e5", "-source_amplitude", "1e-7", "-source_duration", "1e-3",
          "-source_component", "normal", "-heat", "on", "-final_time", "4e-5", "-probe_points", "0.005,0.07,0.005",
          "-probe_every", "1"]


def run(tmp, coupling, ranks=1):
    """The probe's rows and the summary of a run, or None."""
    out = os.path.join(tmp, "%s_np%d" % (coupling, ranks))
    if not run_scene(check, exe, COLUMN + ["-thermoelastic", coupling], out, mpiexec, ranks):
        return None
    rows = [r for r in outputs(out).rows("probes.csv") if r["probe"] == "0"]
    return rows, outputs(out).summary


def misfit(rows, speed, after=1.5e-5):
    """Largest |run - adiabatic swing at this P speed| over the rows once the wave is there,
    relative to the swing's amplitude."""
    late = [r for r in rows if float(r["t"]) >= after]
    exact = [-T0 * beta * float(r["vy"]) / (rho * cp * speed) for r in late]
    worst = max(abs(float(r["temperature"]) - T0 - e) for r, e in zip(late, exact))
    return worst / max(abs(e) for e in exact)


with tempfile.TemporaryDirectory() as tmp:
    runs = {}
    for coupling, right, wrong, bound in (("one_way", c_isothermal, c_adiabatic, 1e-2),
                                          ("two_way", c_adiabatic, c_isothermal, 1.5e-2)):
        r = run(tmp, coupling)
        if r is None:
            continue
        runs[coupling] = r
        rows, s = r
        near, far = misfit(rows, right), misfit(rows, wrong)
        print("%s: %.3f %% off its closed form, %.3f %% off the other speed's; budget %.2g"
              % (coupling, 100 * near, 100 * far, s["max_budget_error"]))
        check(near < bound, "%s: the swing within %g of the closed form (%g)" % (coupling, bound, near))
        check(near < far, "%s: fits its own P speed better (%g) than the other (%g)" % (coupling, near, far))
        check(s["max_budget_error"] < 1e-6, "%s: budget error %g" % (coupling, s["max_budget_error"]))
        check("thermoelastic" in s["physics_ran"], "%s: summary lists thermoelastic" % coupling)
    parallel = run(tmp, "two_way", 2)
    if parallel and "two_way" in runs:
        serial = runs["two_way"][0]
        scale = max(abs(float(r["temperature"]) - T0) for r in serial)
        worst = max(abs(float(a["temperature"]) - float(b["temperature"])) for a, b in zip(serial, parallel[0]))
        check(len(serial) == len(parallel[0]) and worst <= 1e-10 * scale,
              "2 ranks, two way: temperatures equal serial within 1e-10 (%g)" % (worst / scale))
check.finish()
