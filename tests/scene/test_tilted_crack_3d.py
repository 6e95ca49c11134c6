#!/usr/bin/python3
"""Requirement (issue 26, deliverable 1: cracks "at any position and orientation"): a 3D crack
turned about z (-crack_angle 30) and tilted about its strike (-crack_tilt 20).

options/block3d_small.opts with its 6 x 4 mm crack at 30 degrees, tilted by +20 and by -20
degrees. The box, the crack's centre (z = D/2) and the source (tangential, x, on the top face)
are symmetric under z -> D - z, which maps one tilt onto the other, so
 - the two runs dissipate the same energy (within 1e-9) and heat the crack alike;
 - displacement and temperature at probes mirrored in z agree (u_x, u_y, T equal, u_z opposite,
   within 1e-6 of the amplitude).
Each run's crack is where the options put it, with the normal written out here from the two
angles, n = cos(tilt) (-sin(angle), cos(angle), 0) + sin(tilt) z:
 - every contact cell of crack_state.csv lies on the plane through the centre with that normal
   (1e-9 m), inside the 6 x 4 mm rectangle (|s1| <= 3 mm along the strike, |s2| <= 2 mm);
 - s1, s2 span the plane: s1^2 + s2^2 = |x - centre|^2 (the contact frame's tangents lie in it);
 - the crack's faces are the staircase of its rectangle: within 5 % of its area.
The energy budget closes (< 1e-5) and the friction heat equals the dissipated energy.

A crack parallel to the front face (-crack_tilt 90: a delamination, its grid planes normal to
z) is the same scene as an untilted crack in the box turned by 90 degrees about x, (x, y, z) ->
(x, z, H - y): box 20 x 20 x 10 mm with the source (tangential, x) on the front face z = D
against box 20 x 10 x 20 mm with it on the top face y = D, everything else absorbing. The
two runs (grid planes normal to z and to y) dissipate the same energy (within 1e-9), have as
many contact cells, and probes agree once turned (u_x, T equal, u_y(B) = u_z(A), u_z(B) =
-u_y(A), within 1e-6 of the amplitude; a probe at the crack centre: T only, since which face
holds a point on the crack is the locator's choice).
A transducer patch on the left face of the delamination's box has exactly its requested area
(the grid is unsheared along z there: the slopes of a crack at 90 degrees are exactly 0).
Bad input, refused in one line naming the option: a tilt above 90 degrees, a tilted crack that
leaves the box, a tilted crack through the thickness, a -crack_tilt list of the wrong length,
-crack_tilt in 2D.

usage: test_tilted_crack_3d.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import math, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, refused, run_scene, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("tilted_crack_3d")
ANGLE, TILT, L, W, CENTRE, DEPTH = 30.0, 20.0, 0.006, 0.004, (0.01, 0.01, 0.005), 0.01
PROBES = [(0.01, 0.015, 0.003), (0.004, 0.01, 0.002), (0.016, 0.006, 0.004)]
mirrored = PROBES + [(x, y, DEPTH - z) for x, y, z in PROBES]
base = ["-options_file", os.path.join(src, "options/block3d_small.opts"), "-crack_angle", str(ANGLE),
        "-probe_points", ",".join("%g" % v for p in mirrored for v in p)]


def normal(tilt):
    a, d = math.radians(ANGLE), math.radians(tilt)
    return (-math.sin(a) * math.cos(d), math.cos(a) * math.cos(d), math.sin(d))


def check_plane(out, tilt):
    n = normal(tilt)
    rows = outputs(out).rows("crack_state.csv")
    cells = [r for r in rows if r["t"] == rows[0]["t"]]
    off = spread = 0.0
    inside = True
    for r in cells:
        d = [float(r[k]) - c for k, c in zip("xyz", CENTRE)]
        off = max(off, abs(sum(a * b for a, b in zip(d, n))))
        s1, s2 = float(r["s1"]), float(r["s2"])
        spread = max(spread, abs(s1 * s1 + s2 * s2 - sum(a * a for a in d)))
        inside &= abs(s1) <= 0.5 * L + 1e-12 and abs(s2) <= 0.5 * W + 1e-12
    check(len(cells) > 0 and off < 1e-9, "tilt %g: %d cells, up to %.3g m off the plane" % (tilt, len(cells), off))
    check(spread < 1e-7 * (0.5 * L) ** 2, "tilt %g: s1, s2 miss |x - c|^2 by %.3g m^2" % (tilt, spread))
    check(inside, "tilt %g: a cell outside the %g x %g m rectangle" % (tilt, L, W))


def agree(A, B, pairs, what):
    """Probe rows A and B agree channel by channel ((name in A, name in B, sign) each), within 1e-6 of
    A's largest displacement component (of its temperature for the temperature)."""
    for name_a, name_b, sign in pairs:
        fields = ("temperature",) if name_a == "temperature" else ("ux", "uy", "uz")
        scale = max(abs(float(r[m])) for r in A for m in fields) or 1.0
        worst = max(abs(float(x[name_a]) - sign * float(y[name_b])) for x, y in zip(A, B))
        check(len(A) == len(B) and worst <= 1e-6 * scale,
              "%s: %s against %s differs by %.3g of %.3g" % (what, name_a, name_b, worst, scale))


def probes(out):
    rows = outputs(out).rows("probes.csv")
    by = {}
    for r in rows:
        by.setdefault(int(r["probe"]), []).append(r)
    return by


def check_delamination(tmp):
    small = os.path.join(src, "options/block3d_small.opts")
    a = ["-options_file", small, "-crack_angle", "0", "-crack_tilt", "90", "-edge_top", "absorbing",
         "-edge_front", "source", "-probe_points", "0.01,0.014,0.007,0.004,0.006,0.002,0.01,0.01,0.005"]
    b = ["-options_file", small, "-specimen_height", "0.01", "-specimen_depth", "0.02",
         "-crack_center", "0.01,0.005,0.01", "-crack_angle", "0",
         "-probe_points", "0.01,0.007,0.006,0.004,0.002,0.014,0.01,0.005,0.01"]
    out_a, out_b = os.path.join(tmp, "flat"), os.path.join(tmp, "turned")
    if not (run_scene(check, exe, a, out_a, mpiexec, 2) and run_scene(check, exe, b, out_b, mpiexec, 2)):
        return
    sa, sb = (outputs(o).summary for o in (out_a, out_b))
    check(sa["dissipated_energy"] > 0 and abs(sa["dissipated_energy"] / sb["dissipated_energy"] - 1) < 1e-9,
          "delamination %s J, turned box %s J" % (sa["dissipated_energy"], sb["dissipated_energy"]))
    check(sa["contact_cells"] == sb["contact_cells"], "contact cells %s, %s" % (sa["contact_cells"], sb["contact_cells"]))
    pa, pb = probes(out_a), probes(out_b)
    for k in range(3):
        A, B = pa[k], pb[k]
        pairs = [("temperature", "temperature", 1)] + ([] if k == 2 else
                 [("ux", "ux", 1), ("uz", "uy", 1), ("uy", "uz", -1)])
        agree(A, B, pairs, "delamination probe %d against the turned box's" % k)
    print("delamination: dissipated %.12g J, turned box %.12g J" % (sa["dissipated_energy"], sb["dissipated_energy"]))
    patch = os.path.join(tmp, "flat_patch")
    if run_scene(check, exe, a[:-2] + ["-edge_front", "absorbing", "-edge_left", "free", "-source_patch_edge", "left",
                                       "-source_patch_center",
                                       "0.0043,0.0022", "-source_patch_width", "0.0041,0.0023", "-final_time", "2e-7",
                                       "-heat", "off"], patch):
        area = outputs(patch).summary["mesh"]["source_area"]
        check(abs(area / (0.0041 * 0.0023) - 1) < 1e-12, "patch on the left face: area %.12g of %.12g"
              % (area, 0.0041 * 0.0023))


with tempfile.TemporaryDirectory() as tmp:
    runs = {}
    for tilt in (TILT, -TILT):
        out = os.path.join(tmp, "tilt%+g" % tilt)
        if not run_scene(check, exe, base + ["-crack_tilt", str(tilt)], out, mpiexec, 2):
            continue
        s = outputs(out).summary
        runs[tilt] = (out, s)
        crack = s["mesh"]["cracks"][0]
        check(abs(crack["area"] / (L * W) - 1) < 0.05, "tilt %g: faces' area %s of %s" % (tilt, crack["area"], L * W))
        check(s["dissipated_energy"] > 0, "tilt %g: dissipated %s" % (tilt, s["dissipated_energy"]))
        check(s["max_budget_error"] < 1e-5, "tilt %g: budget error %s" % (tilt, s["max_budget_error"]))
        friction = s["heat_deposited_by"].get("friction", 0)
        check(abs(friction / s["dissipated_energy"] - 1) < 1e-10, "tilt %g: friction heat %s" % (tilt, friction))
        check_plane(out, tilt)
    if len(runs) == 2:
        (a, sa), (b, sb) = runs[TILT], runs[-TILT]
        Wa, Wb = sa["dissipated_energy"], sb["dissipated_energy"]
        check(abs(Wa / Wb - 1) < 1e-9, "mirror tilts dissipate %s and %s" % (Wa, Wb))
        pa, pb = probes(a), probes(b)
        n = len(PROBES)
        for k in range(n):
            agree(pa[k], pb[k + n], [(name, name, sign) for name, sign in (("ux", 1), ("uy", 1), ("uz", -1),
                                                                           ("temperature", 1))],
                  "probe %d and its mirror" % k)
        print("tilts +-%g: dissipated %.10g and %.10g J" % (TILT, Wa, Wb))
    check_delamination(tmp)
    refused(check, exe, base, ["-crack_tilt", "95"], os.path.join(tmp, "steep"), "-crack_tilt")
    refused(check, exe, base, ["-crack_tilt", "45", "-crack_center", "0.01,0.001,0.005", "-crack_angle", "0"],
            os.path.join(tmp, "outside"), "-crack_tilt", "reaches the outside")
    refused(check, exe, base, ["-crack_tilt", "10,20"], os.path.join(tmp, "list"), "-crack_tilt", "2 values")
    refused(check, exe, base, ["-crack_tilt", "10", "-crack_width", "0.01"], os.path.join(tmp, "through"),
            "-crack_tilt", "through the thickness")
    refused(check, exe, ["-options_file", os.path.join(src, "options/paper.opts")], ["-crack_tilt", "10"],
            os.path.join(tmp, "twod"), "-crack_tilt", "3D box only")
check.finish()
