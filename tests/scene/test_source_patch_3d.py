#!/usr/bin/python3
"""Requirement (issue 26, items 1 and 8): a transducer patch on a face of a 3D box
(-source_patch_edge top|bottom|left|right|front|back, -source_patch_center c1,c2,
-source_patch_width w1,w2 in the face's axes); the rest of the face keeps its kind.
Checked on options/block3d_small.opts (waves only):
 - the grid puts nodes on the patch's edges: the faces labelled source (summary.json
   mesh.source_area) are the requested rectangle to rounding, on the top face and on a
   left face whose grid lines the crack's shear moves (bounds off the unpatched grid);
 - a patch over the whole face is the face source (energy.csv to rounding);
 - energy: a normal (piston) source through a patch, in its first 0.6 µs (the P wave has
   run 3.8 mm, a third of the patch's width), does the work of the whole face times a
   ratio between the area ratio (the plane wave's ρ c_p A v² per area) and the ratio of
   the patch grown by half a -mesh_h_crack cell on each side (its edge nodes, prescribed
   too, drag a strip of the free surface around it along); the budget closes (summary
   max_budget_error < 1e-5) for a shear patch;
 - 2 ranks equal serial (energy.csv within 1e-10 of each column's largest value);
 - bad patches are refused in one line naming the option, exit 2, nothing written: off
   the face, a zero size, the face itself a source, front/back on a 2D specimen, three
   centre values.

usage: test_source_patch_3d.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, refused, run_scene, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("source patch 3d")
box = ["-options_file", os.path.join(src, "options/block3d_small.opts"), "-heat", "off", "-probe_points",
       "0.01,0.015,0.005"]
# Off the unpatched grid on purpose: the nodes must move onto the patch's edges.
top = ["-edge_top", "free", "-source_patch_edge", "top", "-source_patch_center", "0.0082,0.0035",
       "-source_patch_width", "0.0064,0.0041"]
TOP_AREA = 0.0064 * 0.0041


def summary(out):
    return outputs(out).summary


def energy(out):
    return outputs(out).rows("energy.csv")


def agree(label, a, b, names, tol):
    """Each column of b equals a's within tol of a's largest magnitude; the worst relative difference."""
    check(len(a) == len(b), "%s: %d rows vs %d" % (label, len(a), len(b)))
    worst_all = 0.0
    for k in names:
        ca, cb = [float(r[k]) for r in a], [float(r[k]) for r in b]
        scale = max(abs(v) for v in ca) or 1.0
        worst = max(abs(x - y) for x, y in zip(ca, cb)) / scale
        worst_all = max(worst_all, worst)
        check(worst <= tol, "%s %s: differ by %.3g of the largest value" % (label, k, worst))
    return worst_all


with tempfile.TemporaryDirectory() as tmp:
    # The area, on the top face and on the left face (y there is the sheared axis).
    serial = os.path.join(tmp, "top")
    short = ["-final_time", "4e-6", "-source_ramp_cycles", "1"]
    if run_scene(check, exe, box + top + short, serial):
        s = summary(serial)
        area = s["mesh"]["source_area"]
        print("top patch: source_area %.12g m^2, requested %.12g (relative %.2g); budget error %.3g"
              % (area, TOP_AREA, area / TOP_AREA - 1, s["max_budget_error"]))
        check(abs(area / TOP_AREA - 1) < 1e-12, "top patch area %.12g, requested %.12g" % (area, TOP_AREA))
        check(s["max_budget_error"] < 1e-5, "shear patch: budget error %g" % s["max_budget_error"])
        check(float(energy(serial)[-1]["work_source"]) > 0, "the patch does work")
    left = os.path.join(tmp, "left")  # bounds 1.2 mm from the crack plane's line on that face (a fixed line within a third of a cell would stay the bound)
    if run_scene(check, exe, box + ["-edge_top", "absorbing", "-edge_left", "free", "-source_patch_edge", "left", "-source_patch_center",
                                    "0.0123,0.0061", "-source_patch_width", "0.0057,0.0029", "-final_time", "2e-7"],
                 left):
        area = summary(left)["mesh"]["source_area"]
        print("left patch (sheared face): source_area %.12g m^2, requested %.12g" % (area, 0.0057 * 0.0029))
        check(abs(area / (0.0057 * 0.0029) - 1) < 1e-12, "left patch area %.12g" % area)
    parallel = os.path.join(tmp, "top_np2")
    if os.path.isdir(serial) and run_scene(check, exe, box + top + short + ["-petscpartitioner_type", "simple"],
                                           parallel, mpiexec, 2):
        a, b = energy(serial), energy(parallel)
        worst = agree("2 ranks", a, b, [k for k in a[0] if k != "budget_error"], 1e-10)
        print("2 ranks vs serial: energy.csv differs by at most %.3g of a column's largest value" % worst)

    # The whole face as a patch is the face source.
    piston = ["-source_component", "normal", "-final_time", "6e-7", "-wave_dt", "2.5e-8"]
    whole, face = os.path.join(tmp, "whole"), os.path.join(tmp, "face")
    ok = run_scene(check, exe, box + piston + ["-edge_top", "free", "-source_patch_edge", "top",
                                               "-source_patch_width", "0.02,0.01"], whole)
    if ok and run_scene(check, exe, box + piston, face):
        agree("whole-face patch vs face source", energy(face), energy(whole), ["work_source", "kinetic"], 1e-12)

    # Piston work against area (see the docstring); the same time grid (-wave_dt) for both.
    patch = os.path.join(tmp, "piston_patch")
    if os.path.isdir(face) and run_scene(check, exe, box + piston + ["-edge_top", "free", "-source_patch_edge", "top",
                                                                     "-source_patch_width", "0.012,0.006"], patch):
        low, high = 0.012 * 0.006 / (0.02 * 0.01), 0.013 * 0.007 / (0.02 * 0.01)
        for a, b in zip(energy(face), energy(patch)):
            t = float(a["t"])
            if t == 0 or t > 6e-7:
                continue
            ratio = float(b["work_source"]) / float(a["work_source"])
            print("piston: work(patch)/work(face) at t = %.3g s: %.4f (area ratio %.4f, grown patch %.4f)"
                  % (t, ratio, low, high))
            check(float(b["t"]) == t and low < ratio < high,
                  "piston work ratio %.4f at t = %g outside [%.4f, %.4f]" % (ratio, t, low, high))

    bad = [
        (top[:4] + ["-source_patch_center", "0.018,0.005", "-source_patch_width", "0.006"], "leaves the top face"),
        (top[:4] + ["-source_patch_center", "0.01,0.009", "-source_patch_width", "0.004"], "-source_patch_center"),
        (top[:4] + ["-source_patch_width", "0.004,0"], "-source_patch_width must be > 0"),
        (["-source_patch_edge", "top", "-source_patch_width", "0.004"], "cannot be source"),
        (top[:4] + ["-source_patch_center", "0.01,0.005,0.001"], "-source_patch_center"),
    ]
    for k, (extra, word) in enumerate(bad):
        refused(check, exe, box, extra, os.path.join(tmp, "bad%d" % k), word)
    refused(check, exe, ["-options_file", os.path.join(src, "options/paper.opts"), "-edge_top", "free"],
            ["-source_patch_edge", "front", "-source_patch_width", "0.01"], os.path.join(tmp, "bad_2d"),
            "-source_patch_edge front")
check.finish()
