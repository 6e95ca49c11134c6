#!/usr/bin/python3
"""Requirement (issue 26, deliverable 1): a 3D box with more than one crack.

options/block3d_small.opts with two 6 x 4 mm cracks at y = 7 and 13 mm, inclined at -5 and +5
degrees (mirror images in the plane y = 10 mm), driven by the same tangential (x) source on the
top and the bottom faces: the scene is symmetric under y -> 20 mm - y, so
 - each crack has its own label, faces, cohesive cells and contact cells (24 faces, 77 Q2
   contact cells each, counted as in test_block3d.py), and summary.json lists both;
 - each crack's contact cells lie along its own plane, with s1 = s2 = 0 at its own centre;
 - the two cracks dissipate the same energy (dissipated_energy_by_crack, within 1e-9), which
   sums to the run's dissipated energy, and crack_state.csv holds both cracks' cells;
 - temperature and displacement at mirrored probes agree (T, u_x equal, u_y opposite, within
   1e-6 of the amplitude), and so does the temperature at the two cracks' centres (which
   heat up): the friction heat reaches each crack's own heat faces;
 - the energy budget closes (< 1e-5), the friction heat equals the dissipated energy;
 - moving the upper crack by half a cell breaks the symmetry by more than 1 %: the check
   discriminates.
Bad input: two cracks overlapping on one plane are refused in one line naming -crack_center; a
-crack_shape list of the wrong length (one shape a crack: -crack_shape ellipse,rectangle) names
-crack_shape.

usage: test_cracks_3d.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, refused, run_scene, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("cracks_3d")
FACES = 6 * 4
CELLS = 5 * 3 + (6 * 3 + 5 * 4) + FACES  # per crack: interior vertices, interior edges, faces
base = ["-options_file", os.path.join(src, "options/block3d_small.opts"), "-edge_bottom", "source",
        "-crack_length", "0.006", "-crack_width", "0.004", "-crack_angle", "-5,5",
        "-probe_points", "0.01,0.004,0.005,0.01,0.016,0.005,0.004,0.008,0.003,0.004,0.012,0.003,"
        "0.01,0.007,0.005,0.01,0.013,0.005"]  # mirrored pairs; the last two at the cracks' centres
SYMMETRIC = "0.01,0.007,0.005,0.01,0.013,0.005"


def by_probe(rows):
    out = {}
    for r in rows:
        out.setdefault(int(r["probe"]), []).append(r)
    return out


def check_mirror(out):
    probes = by_probe(outputs(out).rows("probes.csv"))
    heated = max(float(r["temperature"]) for r in probes[4])
    check(heated > 0, "crack 1's centre heats: %s K" % heated)
    for a, b in ((0, 1), (2, 3), (4, 5)):
        amplitude = lambda names: max(abs(float(r[n])) for r in probes[a] for n in names) or 1.0
        on_crack = a == 4  # which face a point on a crack belongs to is the locator's choice: T only
        for name, sign in (("temperature", 1),) if on_crack else (("ux", 1), ("uy", -1), ("uz", 1), ("temperature", 1)):
            va = [float(r[name]) for r in probes[a]]
            vb = [sign * float(r[name]) for r in probes[b]]
            scale = amplitude(["temperature"] if name == "temperature" else ["ux", "uy", "uz"])
            worst = max(abs(x - y) for x, y in zip(va, vb))
            check(len(va) == len(vb) and worst <= 1e-6 * scale,
                  "probes %d, %d: %s differs by %.3g of %.3g" % (a, b, name, worst, scale))


with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "symmetric")
    if run_scene(check, exe, base + ["-crack_center", SYMMETRIC], out, mpiexec, 2):
        s = outputs(out).summary
        cracks = s["mesh"]["cracks"]
        check([c["name"] for c in cracks] == ["crack1", "crack2"], "summary cracks %s" % cracks)
        check(all(c["facets"] == FACES and abs(c["area"] - 2.4e-5) < 1e-12 for c in cracks),
              "faces, areas %s" % [(c["facets"], c["area"]) for c in cracks])
        check(s["mesh"]["cohesive_cells"] == 2 * FACES, "cohesive cells %s" % s["mesh"]["cohesive_cells"])
        check(s["contact_cells"] == 2 * CELLS, "contact cells %s, expected %d" % (s["contact_cells"], 2 * CELLS))
        W = s["dissipated_energy_by_crack"]
        check(len(W) == 2 and min(W) > 0 and abs(W[0] / W[1] - 1) < 1e-9, "dissipated by crack %s" % W)
        check(abs(sum(W) / s["dissipated_energy"] - 1) < 1e-12, "%s sums to %s" % (W, s["dissipated_energy"]))
        check(s["max_budget_error"] < 1e-5, "budget error %s" % s["max_budget_error"])
        friction = s["heat_deposited_by"].get("friction", 0)
        check(abs(friction / s["dissipated_energy"] - 1) < 1e-10, "friction heat %s" % friction)
        rows = outputs(out).rows("crack_state.csv")
        ids = {r["crack"] for r in rows}
        check(ids == {"1", "2"}, "crack_state.csv cracks %s" % ids)
        for k, y in (("1", 0.007), ("2", 0.013)):  # each crack's cells near its line, s1, s2 from its own centre
            mine = [r for r in rows if r["crack"] == k and r["t"] == rows[0]["t"]]
            far = max(abs(float(r["y"]) - y) for r in mine)
            check(far < 0.0031 * 0.0875 + 1e-9, "crack %s: cells up to %.3g m off y = %g" % (k, far, y))
            centre = [r for r in mine if abs(float(r["s1"])) < 1e-12 and abs(float(r["s2"])) < 1e-12]
            check(len(centre) == 1 and abs(float(centre[0]["x"]) - 0.01) < 1e-12 and
                  abs(float(centre[0]["y"]) - y) < 1e-12 and abs(float(centre[0]["z"]) - 0.005) < 1e-12,
                  "crack %s: the cell at s1 = s2 = 0 is %s" % (k, [(r["x"], r["y"], r["z"]) for r in centre]))
        check_mirror(out)
        print("symmetric: dissipated %s J, budget %.3g" % (W, s["max_budget_error"]))
    out = os.path.join(tmp, "shifted")
    if run_scene(check, exe, base + ["-crack_center", "0.01,0.007,0.005,0.01,0.0135,0.005", "-physics", "wave"],
                 out, mpiexec, 2):
        W = outputs(out).summary["dissipated_energy_by_crack"]
        check(abs(W[0] / W[1] - 1) > 0.01, "shifted by half a cell: dissipated %s should differ" % W)
        print("shifted: dissipated %s (%.3g apart)" % (W, W[0] / W[1] - 1))
    refused(check, exe, base, ["-crack_center", "0.01,0.007,0.005,0.013,0.007,0.005", "-crack_angle", "0"],
            os.path.join(tmp, "overlap"), "-crack_center", "overlap")
    refused(check, exe, base, ["-crack_center", SYMMETRIC, "-crack_shape", "ellipse,rectangle,ellipse"],
            os.path.join(tmp, "shapes"), "-crack_shape", "3 values for 2 cracks")
check.finish()
