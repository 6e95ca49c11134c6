#!/usr/bin/python3
"""Requirement (issue 39, item 4): a cracked part from a geometry file, the plate with a fastener
hole and a quarter-elliptical corner crack at the bore (meshes/plate_hole_corner_crack.geo),
given to vibrotherm as the gmsh script itself (-mesh_file FILE.geo: meshed by gmsh's library
into the output directory).

The mesh, read back from the .msh the run wrote (numpy, independent of vibrotherm):
 - 8-node hexahedra only, no sliver: the shortest edge at least 0.75 of the crack's cell;
 - crack1 is exactly the staircase the script states: of the faces on the plane y = 20 mm
   between the bore and 1.5 mm from it, within 1 mm of the front face, those whose centres lie
   in the quarter ellipse (its area within 10 % of the ellipse's quarter);
 - the run's cohesive cells = crack1's faces, and its front (buried_tips) = the vertices of the
   crack's edges that bound one crack face and lie on neither the bore nor the front face
   (the mouth is on those two surfaces: counting the mouth's edges too gives more);
 - the explicit step is that of hexahedra of its shortest edge: at least 0.8 of the step of
   a generated uncracked box of that cell size (split tetrahedra gave 0.1).
Waves, contact, heat and camera end to end (a normal drive on the back face's patch, 200 kHz,
20 us, no material damping so that the crack is the only heat):
 - the crack dissipates, its friction heat equals the dissipated energy, the budget closes;
 - the camera's hottest pixel lies on the crack's mouth (within a pixel of the trace y = 20 mm,
   x in [12.5, 14] mm on the front face);
 - 2 ranks (the script meshed under MPI) dissipate what serial does (1e-6).
Scripts: options/plate_hole.opts runs from the checkout (-mesh_only); the 2D script
meshes/plate_two_cracks.geo gives its committed .msh's mesh. Bad input, refused in one line
naming the option and the script, nothing left behind: a .geo that does not exist, one gmsh
cannot read, one it cannot mesh (a transfinite square whose sides disagree), one meshed in
tetrahedra, one with physical groups but no Physical Volume, and a bad -heat_mesh_file script
after a good -mesh_file one.

usage: test_plate_hole.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import math, os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, refused, run_scene, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("plate with a hole")
GEO = os.path.join(src, "meshes", "plate_hole_corner_crack.geo")
# The script's geometry (its header): plate, hole centre and radius, crack extents, cell at the crack.
T, XH, YH, R, A, C, HC = 0.003, 0.01, 0.02, 0.0025, 0.0015, 0.001, 0.25e-3
SCENE = ["-mesh_file", GEO, "-source_type", "displacement", "-source_component", "normal", "-source_frequency", "2e5",
         "-source_amplitude", "1e-6", "-source_ramp_cycles", "1", "-source_duration", "1e-4", "-final_time", "2e-5",
         "-crack_law", "mmd", "-crack_a0", "2e-9", "-camera", "-camera_face", "front", "-camera_integration", "5e-6",
         "-camera_fps", "2e5", "-petscpartitioner_type", "metis"]
HEX_FACES = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def read_msh(path):
    """A MSH 2.2 ASCII file: node coordinates (by tag), hexahedra, and the quads of each physical surface."""
    lines = open(path).read().split("\n")
    at = lines.index("$PhysicalNames")
    names = {int(l.split()[1]): l.split()[2].strip('"') for l in lines[at + 2:at + 2 + int(lines[at + 1])]}
    at = lines.index("$Nodes")
    nodes = {int(p[0]): np.array([float(v) for v in p[1:4]]) for p in (l.split() for l in lines[at + 2:at + 2 + int(lines[at + 1])])}
    at = lines.index("$Elements")
    hexes, quads, types = [], {}, set()
    for l in lines[at + 2:at + 2 + int(lines[at + 1])]:
        p = [int(v) for v in l.split()]
        kind, ntags = p[1], p[2]
        corners = p[3 + ntags:]
        types.add(kind)
        if kind == 5:
            hexes.append(corners)
        elif kind == 3:
            quads.setdefault(names.get(p[3], str(p[3])), []).append(corners)
    return nodes, hexes, quads, types


def check_mesh(msh, summary):
    nodes, hexes, quads, types = read_msh(msh)
    check(types <= {3, 5} and hexes, "the mesh holds element types %s (hexahedra 5, their faces 3)" % sorted(types))
    edges = {tuple(sorted((h[f[k]], h[f[(k + 1) % 4]]))) for h in hexes for f in HEX_FACES for k in range(4)}
    shortest = min(np.linalg.norm(nodes[a] - nodes[b]) for a, b in edges)
    check(shortest >= 0.75 * HC, "the shortest edge is %.3g mm (a sliver: < 0.75 of %.3g mm)" % (1e3 * shortest, 1e3 * HC))
    # The staircase, from every hexahedron face on the crack's plane near the bore and the front face.
    faces = {tuple(sorted(h[i] for i in f)) for h in hexes for f in HEX_FACES}
    expected = set()
    for face in faces:
        corners = np.array([nodes[n] for n in face])
        if np.ptp(corners[:, 1]) > 1e-12 or abs(corners[0, 1] - YH) > 1e-12:
            continue
        u, w = (corners[:, 0].mean() - XH - R) / A, (T - corners[:, 2].mean()) / C
        if 0 < u < 1 and 0 < w < 1 and u * u + w * w <= 1:
            expected.add(face)
    crack_quads = quads.get("crack1", [])  # corners in order around each face
    crack = {tuple(sorted(q)) for q in crack_quads}
    check(crack == expected and len(crack) > 10, "crack1 has %d faces, %d of them the staircase's %d" %
          (len(crack), len(crack & expected), len(expected)))
    area = sum(0.5 * np.linalg.norm(np.cross(nodes[q[2]] - nodes[q[0]], nodes[q[3]] - nodes[q[1]])) for q in crack_quads)
    check(abs(area / (0.25 * math.pi * A * C) - 1) < 0.1, "crack1's area %.4g mm2, the quarter ellipse's %.4g mm2" %
          (1e6 * area, 1e6 * 0.25 * math.pi * A * C))
    # The front: edges bounding one crack face, on neither the bore (r = R) nor the front face (z = T).
    count = {}
    for q in crack_quads:
        for k in range(4):
            edge = tuple(sorted((q[k], q[(k + 1) % 4])))
            count[edge] = count.get(edge, 0) + 1
    on_mouth = lambda n: abs(np.hypot(nodes[n][0] - XH, nodes[n][1] - YH) - R) < 1e-9 or abs(nodes[n][2] - T) < 1e-9
    outline = [e for e, n in count.items() if n == 1]
    front = {v for e in outline if not (on_mouth(e[0]) and on_mouth(e[1])) for v in e}
    with_mouth = {v for e in outline for v in e}
    c = summary["mesh"]["cracks"][0]
    check(summary["mesh"]["cohesive_cells"] == len(crack) == c["facets"], "cohesive cells %d, crack faces %d (file %d)" %
          (summary["mesh"]["cohesive_cells"], c["facets"], len(crack)))
    check(c["buried_tips"] == len(front) < len(with_mouth), "front vertices %d, the buried outline's %d (with the "
          "mouth %d)" % (c["buried_tips"], len(front), len(with_mouth)))
    print("mesh: %d hexahedra, shortest edge %.3g mm, crack1 %d faces of %.4g mm2, front %d vertices (outline %d)" %
          (len(hexes), 1e3 * shortest, len(crack), 1e6 * area, len(front), len(with_mouth)))
    return shortest


def check_step(tmp, summary, shortest):
    """The step against a generated uncracked box of hexahedra of the plate's shortest edge."""
    out = os.path.join(tmp, "box")
    box = ["-specimen_width", "0.004", "-specimen_height", "0.004", "-specimen_depth", "0.002",
           "-mesh_h", repr(shortest), "-mesh_h_crack", repr(shortest), "-physics", "wave", "-final_time", "1e-7"]
    if not run_scene(check, exe, box, out):
        return
    ratio = summary["derived"]["wave_stable_dt"] / outputs(out).summary["derived"]["wave_stable_dt"]
    check(ratio >= 0.8, "the plate's stable step is %.3g of a box of hexahedra of its shortest edge" % ratio)
    print("stable step %.4g s, %.3f of the box's of %.3g mm hexahedra" % (summary["derived"]["wave_stable_dt"], ratio,
                                                                           1e3 * shortest))


def check_waves(summary):
    s = summary
    check(s["dissipated_energy"] > 0, "dissipated %s J" % s["dissipated_energy"])
    friction = s["heat_deposited_by"].get("friction", 0)
    check(abs(friction / s["dissipated_energy"] - 1) < 1e-10, "friction heat %s of %s" % (friction, s["dissipated_energy"]))
    check(s["max_budget_error"] < 1e-5, "budget error %s" % s["max_budget_error"])
    camera = s.get("camera") or {}
    x, y = camera.get("peak_at", [math.nan, math.nan])
    pixel = 0.02 / max(camera.get("cols", 1), 1)
    on = abs(y - YH) <= pixel and XH + R - pixel <= x <= XH + R + A + pixel
    check(on, "the camera's hottest pixel (%.3g, %.3g) mm is off the mouth y = %.3g mm, x in [%.3g, %.3g] mm (pixel %.3g"
          " mm)" % (1e3 * x, 1e3 * y, 1e3 * YH, 1e3 * (XH + R), 1e3 * (XH + R + A), 1e3 * pixel))
    print("waves: dissipated %.4g J, budget %.2g, camera peak %.3g K at (%.2f, %.2f) mm" %
          (s["dissipated_energy"], s["max_budget_error"], camera.get("peak_rise", math.nan), 1e3 * x, 1e3 * y))


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def check_scripts(tmp):
    """The shipped options file as a newcomer runs it (from the checkout, -mesh_only); a 2D script
    gives the mesh of its committed .msh; bad scripts are refused in one line, nothing left behind."""
    out = os.path.join(tmp, "opts")
    r = subprocess.run([exe, "-options_file", "options/plate_hole.opts", "-mesh_only", "-output_dir", out], cwd=src,
                       capture_output=True, text=True)
    check(r.returncode == 0 and outputs(out).summary["mesh"]["cells"] == 9744, "options/plate_hole.opts -mesh_only: %s"
          % r.stderr[-600:])
    meshes = {}
    for kind in ("geo", "msh"):
        out = os.path.join(tmp, "two_cracks_" + kind)
        if run_scene(check, exe, ["-options_file", os.path.join(src, "options/paper.opts"), "-mesh_only", "-mesh_file",
                                  os.path.join(src, "meshes", "plate_two_cracks." + kind)], out):
            m = outputs(out).summary["mesh"]
            meshes[kind] = (m["cells"], m["vertices"], m["cohesive_cells"])
    check(len(meshes) == 2 and meshes["geo"] == meshes["msh"], "2D: the .geo gives %s, its .msh %s" %
          (meshes.get("geo"), meshes.get("msh")))
    refused(check, exe, SCENE, ["-mesh_file", os.path.join(tmp, "none.geo")], os.path.join(tmp, "missing"),
            "-mesh_file", "none.geo", "cannot open")
    broken = write(os.path.join(tmp, "broken.geo"), "Point(1) = {0, 0, 0;\n")
    refused(check, exe, SCENE, ["-mesh_file", broken], os.path.join(tmp, "unreadable"), "-mesh_file", "broken.geo",
            "cannot read")
    # A transfinite square with 4 and 5 nodes on opposite sides: gmsh logs an error and meshes on.
    mismatched = write(os.path.join(tmp, "mismatched.geo"), "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; "
                       "Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\nLine(1) = {1, 2}; Line(2) = {2, 3}; "
                       "Line(3) = {3, 4}; Line(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                       "Transfinite Curve {1} = 4; Transfinite Curve {3} = 5; Transfinite Curve {2, 4} = 3;\n"
                       "Transfinite Surface {1}; Recombine Surface {1};\nPhysical Curve(\"source\") = {3};\n"
                       "Physical Surface(\"body\") = {1};\n")
    paper = ["-options_file", os.path.join(src, "options/paper.opts")]
    refused(check, exe, paper, ["-mesh_file", mismatched], os.path.join(tmp, "mismatched"), "-mesh_file",
            "mismatched.geo", "cannot mesh")
    tets = write(os.path.join(tmp, "tets.geo"), 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 0.01, 0.01, 0.01};\n'
                 'Physical Surface("free") = {1};\nPhysical Volume("body") = {1};\nMesh.MeshSizeMax = 0.005;\n')
    refused(check, exe, SCENE, ["-mesh_file", tets], os.path.join(tmp, "tets"), "-mesh_file", "tets", "hexahedra")
    no_cells = write(os.path.join(tmp, "no_cells.geo"), 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 0.01, 0.01, '
                     '0.01};\nPhysical Surface("free") = {1};\n')
    refused(check, exe, SCENE, ["-mesh_file", no_cells], os.path.join(tmp, "no_cells"), "-mesh_file", "no_cells.geo",
            "Physical Volume")
    # A good wave script with a bad heat script: refused, and the wave mesh made first is gone again.
    refused(check, exe, SCENE, ["-heat_mesh_file", broken], os.path.join(tmp, "bad_heat"), "-heat_mesh_file",
            "broken.geo")


with tempfile.TemporaryDirectory() as tmp:
    serial = os.path.join(tmp, "np1")
    if run_scene(check, exe, SCENE, serial):
        s = outputs(serial).summary
        shortest = check_mesh(os.path.join(serial, "plate_hole_corner_crack.msh"), s)
        check_step(tmp, s, shortest)
        check_waves(s)
        parallel = os.path.join(tmp, "np2")  # the script meshed under MPI too
        if run_scene(check, exe, SCENE, parallel, mpiexec, 2):
            W1, W2 = s["dissipated_energy"], outputs(parallel).summary["dissipated_energy"]
            check(abs(W1 / W2 - 1) < 1e-6, "serial dissipated %r, 2 ranks %r" % (W1, W2))
    check_scripts(tmp)
check.finish()
