#!/usr/bin/python3
"""Requirement (issue 26, deliverable 1): a 3D -mesh_file, a gmsh mesh of hexahedra whose
physical surfaces name the crack (crack1), the source and the other faces' kinds.

The file here is written independently of vibrotherm (box_msh.py: a 20 x 20 x 10 mm box of
1 mm hexahedra, a 6 x 4 mm crack on the plane y = 10 mm, the top face the source, the rest
absorbing). Its generated twin is options/block3d_small.opts with the same crack at 0°,
-mesh_h = -mesh_h_crack = 1 mm (the same uniform grid) and -heat_mesh wave (the heat on the
wave grid, as a mesh file's default). On 2 ranks:
 - the file's mesh is read: 4000 hexahedra, 24 crack faces = cohesive cells, 77 contact cells;
 - its run equals the generated one: dissipated energy and heat content within 1e-9, probe
   displacements within 1e-9 of their amplitude, temperature rises within 1e-9 of the
   largest (the two meshes number and partition their points differently);
 - the same file as -heat_mesh_file gives the same heat content (1e-9);
 - a surface crack (issue 39): the same box with the crack reaching the front face (z from 6 to
   10 mm), read from a file, equals its generated twin (-crack_center z = 8 mm, 4 mm wide: its
   edge on the face), by the same measures.
Bad input, refused in one line naming the option and the file (exit 2): a file of
tetrahedra, an unknown physical surface, a file that does not exist.

usage: test_mesh_file_3d.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from box_msh import write_box_msh
from checks import Checks, refused, run_scene, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("mesh_file_3d")
opts = ["-options_file", os.path.join(src, "options/block3d_small.opts"),
        "-probe_points", "0.01,0.015,0.005,0.004,0.01,0.002,0.01,0.01,0.005"]
twin = ["-crack_center", "0.01,0.01,0.005", "-crack_angle", "0", "-mesh_h", "0.001", "-mesh_h_crack", "0.001",
        "-heat_mesh", "wave"]


def load(out):
    return (outputs(out).summary,
            outputs(out).rows("probes.csv"))


def same_run(label, a, b):
    (sa, pa), (sb, pb) = a, b
    for key in ("dissipated_energy", "heat_content"):
        check(sa[key] > 0 and abs(sa[key] / sb[key] - 1) < 1e-9, "%s: %s %s vs %s" % (label, key, sa[key], sb[key]))
    check(len(pa) == len(pb), "%s: probes rows %d vs %d" % (label, len(pa), len(pb)))
    t0 = float(pa[0]["temperature"])
    for name, offset in (("ux", 0), ("uy", 0), ("uz", 0), ("temperature", t0)):
        va, vb = [float(r[name]) - offset for r in pa], [float(r[name]) - offset for r in pb]
        scale = max(abs(v) for v in va) or 1.0
        worst = max(abs(x - y) for x, y in zip(va, vb))
        check(worst <= 1e-9 * scale, "%s: %s differs by %.3g of %.3g" % (label, name, worst, scale))


with tempfile.TemporaryDirectory() as tmp:
    box = os.path.join(tmp, "box.msh")
    write_box_msh(box, (20, 20, 10), 0.001, (10, 7, 13, 3, 7))
    runs = {}
    for name, extra in (("file", ["-mesh_file", box]), ("generated", twin),
                        ("heat_file", ["-mesh_file", box, "-heat_mesh_file", box])):
        out = os.path.join(tmp, name)
        if run_scene(check, exe, opts + extra, out, mpiexec, 2):
            runs[name] = load(out)
    if "file" in runs:
        s = runs["file"][0]
        check(s.get("dimension") == 3 and s["mesh"]["cells"] == 4000 and s["mesh"]["source"] == box,
              "mesh %s" % {k: s["mesh"].get(k) for k in ("cells", "source")})
        check(s["mesh"]["cohesive_cells"] == 24 and s["mesh"]["cracks"][0]["facets"] == 24,
              "cohesive cells %s" % s["mesh"]["cohesive_cells"])
        check(s["contact_cells"] == 77, "contact cells %s" % s["contact_cells"])
        check(s["max_budget_error"] < 1e-5, "budget %s" % s["max_budget_error"])
    if "file" in runs and "generated" in runs:
        same_run("file = generated", runs["file"], runs["generated"])
        print("file = generated: dissipated %.10g J" % runs["file"][0]["dissipated_energy"])
    surface = os.path.join(tmp, "surface.msh")
    write_box_msh(surface, (20, 20, 10), 0.001, (10, 7, 13, 6, 10))
    for name, extra in (("surface_file", ["-mesh_file", surface]),
                        ("surface_generated", twin + ["-crack_center", "0.01,0.01,0.008"])):
        out = os.path.join(tmp, name)
        if run_scene(check, exe, opts + extra, out, mpiexec, 2):
            runs[name] = load(out)
    if "surface_file" in runs and "surface_generated" in runs:
        check(runs["surface_generated"][0]["mesh"]["cracks"][0].get("breaks") == ["front"],
              "the generated surface crack breaks %s" % runs["surface_generated"][0]["mesh"]["cracks"][0].get("breaks"))
        same_run("surface crack: file = generated", runs["surface_file"], runs["surface_generated"])
        print("surface crack, file = generated: dissipated %.10g J" % runs["surface_file"][0]["dissipated_energy"])
    if "file" in runs and "heat_file" in runs:
        a, b = runs["file"][0]["heat_content"], runs["heat_file"][0]["heat_content"]
        check(abs(a / b - 1) < 1e-9, "-heat_mesh_file: heat content %s vs %s" % (b, a))
    tets = os.path.join(tmp, "tets.msh")
    write_box_msh(tets, (4, 4, 4), 0.005, (2, 1, 3, 1, 3), tets=True)
    refused(check, exe, opts, ["-mesh_file", tets], os.path.join(tmp, "tets"), "-mesh_file", "hexahedra")
    unknown = os.path.join(tmp, "unknown.msh")
    write_box_msh(unknown, (4, 4, 4), 0.005, (2, 1, 3, 1, 3))
    text = open(unknown).read().replace('"absorbing"', '"absorbent"')
    open(unknown, "w").write(text)
    refused(check, exe, opts, ["-mesh_file", unknown], os.path.join(tmp, "unknown"), "-mesh_file", "absorbent")
    refused(check, exe, opts, ["-mesh_file", os.path.join(tmp, "none.msh")], os.path.join(tmp, "none"),
            "-mesh_file", "none.msh")
check.finish()
