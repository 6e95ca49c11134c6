#!/usr/bin/python3
"""Requirement: thermoelastic heating (-thermoelastic one_way) gives a plane P wave the
adiabatic temperature swing ΔT = −T0 β tr(ε)/(ρ c_p), β = (3λ + 2G) α_L, with tr ε = ∂u_y/∂y
from the run's own displacements at two probes (diffusion over a period, √(α/ω) ≈ 12 µm,
is negligible): within 2 % of the swing on a 0.5 mm heat mesh, the error falling with the
heat mesh; the deposit is exact in time (1 or 3 heat steps per interval give the same
temperatures); a plane S wave (tr ε = 0) heats by less than 0.5 % of the P swing; 2 ranks
equal serial; the heat balance closes and energy.csv splits the heat by source.

usage: test_thermoelastic.py VIBROTHERM MPIEXEC"""
import csv, json, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene

exe, mpiexec = sys.argv[1:3]
check = Checks("thermoelastic")
E, nu, rho, cp, T0, alpha_L = 70e9, 0.33, 2700.0, 900.0, 293.15, 23e-6
lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
beta = (3 * lam + 2 * G) * alpha_L
box = ["-specimen_width", "0.02", "-specimen_height", "0.1", "-edge_top", "source", "-edge_bottom", "absorbing",
       "-thermoelastic", "one_way", "-final_time", "4e-5", "-source_duration", "1e-3", "-probe_points",
       "0.01,0.08,0.01,0.0805,0.01,0.0795", "-probe_every", "6", "-wave_degree", "1"]
p_wave = ["-source_component", "normal", "-edge_left", "roller", "-edge_right", "roller"]
s_wave = ["-source_component", "tangential", "-edge_left", "antisymmetric", "-edge_right", "antisymmetric"]


def run(tmp, name, extra, ranks=1):
    out = os.path.join(tmp, name)
    if not run_scene(check, exe, box + extra, out, mpiexec, ranks):
        return None
    by_time = {}
    for row in csv.DictReader(open(os.path.join(out, "probes.csv"))):
        if row["temperature"] != "nan":
            by_time.setdefault(float(row["t"]), {})[int(row["probe"])] = row
    return by_time, json.load(open(os.path.join(out, "summary.json"))), list(csv.DictReader(open(os.path.join(out, "energy.csv"))))


def swing_error(by_time):
    """Largest |run − adiabatic| and the largest adiabatic swing at the centre probe."""
    worst = peak = 0.0
    for probes in by_time.values():
        if len(probes) < 3:
            continue
        trace = (float(probes[1]["uy"]) - float(probes[2]["uy"])) / 0.001
        exact = -T0 * beta * trace / (rho * cp)
        worst = max(worst, abs(float(probes[0]["temperature"]) - T0 - exact))
        peak = max(peak, abs(exact))
    return worst, peak


with tempfile.TemporaryDirectory() as tmp:
    errors = {}
    for h in (2e-3, 1e-3, 5e-4):
        result = run(tmp, "p%g" % h, p_wave + ["-heat_mesh_h", str(h)])
        if result:
            worst, peak = swing_error(result[0])
            errors[h] = worst / peak
            print("P wave, heat mesh %g m: swing %.4g K, error %.2f %% of it" % (h, peak, 100 * errors[h]))
    if len(errors) == 3:
        check(errors[5e-4] <= 0.02, "P wave: error %.3f > 2 %% of the swing" % errors[5e-4])
        check(errors[2e-3] > errors[1e-3] > errors[5e-4], "P wave: error does not fall with the heat mesh: %s" % errors)
    fine = run(tmp, "p_fine", p_wave + ["-heat_mesh_h", "5e-4"])
    one = run(tmp, "p_one_step", p_wave + ["-heat_mesh_h", "5e-4", "-heat_substeps", "1"])
    two = run(tmp, "p_np2", p_wave + ["-heat_mesh_h", "5e-4"], ranks=2)
    if fine and one and two:
        _, peak = swing_error(fine[0])
        common = [t for t in one[0] if t in fine[0]]
        diff = max(abs(float(one[0][t][0]["temperature"]) - float(fine[0][t][0]["temperature"])) for t in common)
        check(common and diff <= 2e-3 * peak, "1 vs 3 heat steps per interval differ by %.3g K" % diff)
        diff2 = max(abs(float(two[0][t][0]["temperature"]) - float(fine[0][t][0]["temperature"])) for t in fine[0])
        check(diff2 <= 1e-9 * peak, "2 ranks differ from serial by %.3g K" % diff2)
        summary, energy = fine[1], fine[2]
        check("thermoelastic" in summary["physics_ran"], "physics_ran %s" % summary["physics_ran"])
        dep = summary["heat_deposited"]
        check(abs(summary["heat_deposited_by"].get("thermoelastic", 0) - dep) <= 1e-12 * abs(dep) + 1e-300,
              "thermoelastic share %s vs deposited %r" % (summary["heat_deposited_by"], dep))
        check(abs(summary["heat_content"] - (dep - summary["heat_boundary_loss"])) <= 1e-9 * max(abs(dep), 1e-30),
              "heat balance: content %r, deposited %r, loss %r" % (summary["heat_content"], dep, summary["heat_boundary_loss"]))
        check("heat_thermoelastic" in energy[0] and "heat_friction" in energy[0], "energy.csv lacks the split columns")
        s = run(tmp, "s_wave", s_wave + ["-heat_mesh_h", "5e-4", "-mesh_h", "1e-3"])
        if s:
            residue = max(abs(float(p[0]["temperature"]) - T0) for p in s[0].values() if 0 in p)
            print("S wave: largest rise %.3g K (%.2f %% of the P swing)" % (residue, 100 * residue / peak))
            check(residue <= 5e-3 * peak, "S wave heats by %.3g K (%.2f %% of the P swing)" % (residue, 100 * residue / peak))
check.finish()
