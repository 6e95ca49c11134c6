#!/usr/bin/python3
"""Requirement: the heat solver alone (-physics heat -heat_crack_power q) reproduces
Carslaw & Jaeger's continuous finite line source, ΔT(t) = q/(ρc) ∫0^t erf(L/(4√(αs)))/√(4παs) ds
at the crack centre from 1e-6 s to 1e-2 s on a heat mesh with a first layer of 4 µm,
within 1 % with a consistent mass and 3 % with the default lumped mass (whose error sits in
the first microseconds), and the error falls under refinement of the heat mesh (first
layer 16, 8, 4 µm, along the crack 400, 200, 100 µm); the heat balance closes
(content = deposited − boundary loss, 1e-3) with sink, insulated and convective edges.

usage: test_heat_line_source.py VIBROTHERM"""
import math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

exe = sys.argv[1]
check = Checks("heat line source")
q, L, rho_c, alpha = 1e6, 0.004, 2700 * 900.0, 237 / (2700 * 900.0)


def carslaw_jaeger(t, n=2000):
    """Centre temperature rise; s = u² removes the 1/√s singularity, Simpson in u."""
    b = math.sqrt(t)
    h = b / n
    g = lambda u: (1.0 if u == 0 else math.erf(L / (4 * math.sqrt(alpha) * u))) / math.sqrt(4 * math.pi * alpha)
    s = g(0) + g(b) + sum((4 if i % 2 else 2) * g(i * h) for i in range(1, n))
    return q / rho_c * 2 * s * h / 3


def run(tmp, name, extra):
    out = os.path.join(tmp, name)
    cmd = [exe, "-physics", "heat", "-heat_crack_power", str(q), "-specimen_width", "0.04", "-specimen_height", "0.04",
           "-crack_center", "0.02,0.02", "-crack_length", str(L), "-crack_angle", "0", "-mesh_h", "0.002",
           "-mesh_grading", "0.3", "-crack_probe", "0.5", "-output_dir", out] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == 0, "%s: %s" % (name, r.stderr[-1500:]))
    if r.returncode:
        return None, None, None
    rows = [x for x in outputs(out).rows("probes.csv") if x["probe"] == "0"]
    energy = outputs(out).rows("energy.csv")
    return rows, energy, outputs(out).summary


def max_error(rows, t0, t1):
    errs = [abs((float(x["temperature"]) - 293.15) / carslaw_jaeger(float(x["t"])) - 1)
            for x in rows if t0 <= float(x["t"]) <= t1]
    return max(errs) if errs else float("inf")


def balance(name, energy, summary, loss_expected):
    dep = summary["heat_deposited"]
    check(abs(summary["heat_content"] - (dep - summary["heat_boundary_loss"])) <= 1e-3 * dep,
          "%s: content %g vs deposited - loss %g" % (name, summary["heat_content"], dep - summary["heat_boundary_loss"]))
    worst = max(abs(float(e["heat_content"]) - float(e["heat_deposited"]) + float(e["heat_boundary_loss"]))
                for e in energy) / dep
    check(worst <= 1e-3, "%s: balance error %g during the run" % (name, worst))
    loss = summary["heat_boundary_loss"] / dep
    check(loss_expected(loss), "%s: boundary loss %g of the deposited heat" % (name, loss))
    print("%s: deposited %.4g J/m, boundary loss %.3f of it, balance error %.2g" % (name, dep, loss, worst))


with tempfile.TemporaryDirectory() as tmp:
    # Accuracy and convergence of the graded heat mesh (free diffusion, Crank-Nicolson).
    errors = {}
    for h, along in ((1.6e-5, 4e-4), (8e-6, 2e-4), (4e-6, 1e-4)):
        rows, _, summary = run(tmp, "h%g" % h, ["-heat_mesh_h_crack", str(h), "-heat_mesh_h_along", str(along),
                                               "-final_time", "1e-2"])
        if rows:
            errors[h] = max_error(rows, 1e-6, 1e-2)
            print("first layer %g m: %d heat dofs, %d steps, max relative error %.4f on [1e-6, 1e-2] s"
                  % (h, summary["dofs_heat"], summary["steps_heat"], errors[h]))
    if len(errors) == 3:
        check(errors[4e-6] <= 0.03, "4 um: error %.4f > 3 %%" % errors[4e-6])
        check(errors[1.6e-5] > errors[8e-6] > errors[4e-6], "error does not fall under refinement: %s" % errors)
    rows, _, summary = run(tmp, "consistent", ["-heat_mesh_h_crack", "4e-6", "-heat_mesh_h_along", "1e-4",
                                               "-final_time", "1e-2", "-heat_lumped_mass", "0"])
    if rows:
        error = max_error(rows, 1e-6, 1e-2)
        print("first layer 4e-06 m, consistent mass: max relative error %.4f" % error)
        check(error <= 0.01, "consistent mass, 4 um: error %.4f > 1 %%" % error)
    # Balance with heat reaching the edges (a 1 cm plate, 0.2 s), default integrator.
    small = ["-specimen_width", "0.01", "-specimen_height", "0.01", "-crack_center", "0.005,0.005", "-mesh_h", "0.001",
             "-mesh_h_crack", "2e-4", "-final_time", "0.2"]
    for bc, expected in (("sink", lambda f: f > 0.3), ("insulated", lambda f: abs(f) < 1e-12),
                         ("convective", lambda f: 0 < f < 0.3)):
        _, energy, summary = run(tmp, bc, small + ["-heat_bc", bc, "-heat_h", "1e4"])
        if summary:
            balance(bc, energy, summary, expected)
            check(summary["physics_ran"] == ["heat"] and summary["steps_wave"] == 0,
                  "%s: only heat runs (%s)" % (bc, summary["physics_ran"]))
check.finish()
