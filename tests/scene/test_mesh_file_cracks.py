#!/usr/bin/python3
"""Requirement (issue 27, item 9): cracks from a mesh file that cross, or bend, are said
plainly.

- Two cracks crossing in an X: refused in one line, exit 2, "cracks crack_a and crack_b
  cross ... at (0.01, 0.01)", with the default heat mesh (before: "too close ... room 0 m")
  and with -heat_mesh wave (before: a crash inside PETSc, "Faces should separate only two
  cells", exit 1).
- A kinked crack: runs, with a warning naming the crack, where it bends, the accuracy cost
  of the fallback to the wave mesh for heat and the two ways out (before: silent); none
  with -heat_mesh wave, which asks for that mesh.

The meshes are written here (gmsh's MSH 2.2, a 2 cm square of 1 mm quads, the cracks on
grid lines), so the test needs no gmsh executable.

usage: test_mesh_file_cracks.py VIBROTHERM"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks

exe = os.path.abspath(sys.argv[1])
check = Checks("mesh_file_cracks")
N, H = 20, 0.001  # quads per side, their size [m]


def node(i, j):
    return 1 + j * (N + 1) + i


def write_mesh(path, cracks):
    """cracks: {name: [(i, j) grid points along it]}; outer edges: top 'source', the others 'absorbing'."""
    names = ["source", "absorbing"] + list(cracks) + ["specimen"]
    lines = []  # (physical, elementary, a, b)
    for i in range(N):
        lines.append((1, 1, node(i, N), node(i + 1, N)))
        lines.append((2, 2, node(i, 0), node(i + 1, 0)))
    for j in range(N):
        lines.append((2, 2, node(0, j), node(0, j + 1)))
        lines.append((2, 2, node(N, j), node(N, j + 1)))
    for k, points in enumerate(cracks.values()):
        for (i0, j0), (i1, j1) in zip(points, points[1:]):
            lines.append((3 + k, 3 + k, node(i0, j0), node(i1, j1)))
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)) for j in range(N) for i in range(N)]
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(names))
        for tag, name in enumerate(names, 1):
            f.write('%d %d "%s"\n' % (2 if name == "specimen" else 1, tag, name))
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % ((N + 1) ** 2))
        for j in range(N + 1):
            for i in range(N + 1):
                f.write("%d %.17g %.17g 0\n" % (node(i, j), i * H, j * H))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(quads)))
        for n, (physical, entity, a, b) in enumerate(lines, 1):
            f.write("%d 1 2 %d %d %d %d\n" % (n, physical, entity, a, b))
        for n, q in enumerate(quads, len(lines) + 1):
            f.write("%d 3 2 %d 100 %d %d %d %d\n" % (n, len(names), *q))
        f.write("$EndElements\n")


def run(tmp, name, mesh, extra=()):
    out = os.path.join(tmp, name)
    r = subprocess.run([exe, "-mesh_file", mesh, "-final_time", "2e-6", "-wave_degree", "1", "-output_dir", out]
                       + list(extra), capture_output=True, text=True, timeout=300)
    return r, out


with tempfile.TemporaryDirectory() as tmp:
    crossing = os.path.join(tmp, "crossing.msh")
    write_mesh(crossing, {"crack_a": [(i, 10) for i in range(5, 16)], "crack_b": [(10, j) for j in range(5, 16)]})
    for label, extra in [("default heat mesh", []), ("-heat_mesh wave", ["-heat_mesh", "wave"])]:
        r, out = run(tmp, "x" + str(len(extra)), crossing, extra)
        lines = [l for l in r.stderr.splitlines() if l.strip()]
        check(r.returncode == 2 and len(lines) == 1, "X crossing, %s: one line, exit 2 (exit %d: %s)"
              % (label, r.returncode, r.stderr[-400:]))
        check(bool(lines) and "cracks crack_a and crack_b cross" in lines[0] and "(0.01, 0.01)" in lines[0],
              "X crossing, %s: the line names both cracks and where: %s" % (label, lines))
        check(not os.path.exists(out), "X crossing, %s: nothing written" % label)

    kinked = os.path.join(tmp, "kinked.msh")
    write_mesh(kinked, {"crack_k": [(i, 10) for i in range(5, 11)] + [(10, j) for j in range(11, 16)]})
    r, _ = run(tmp, "kinked", kinked)
    warning = [l for l in r.stdout.splitlines() if "warning" in l and "crack_k" in l]
    check(r.returncode == 0, "kinked crack: runs (%s)" % r.stderr[-300:])
    check(len(warning) == 1 and "bends at (0.01, 0.01)" in warning[0] and "-heat_mesh_file" in warning[0]
          and "low" in warning[0], "kinked crack: a warning naming it, where it bends, the cost and the way out: %s"
          % warning)
    r, _ = run(tmp, "kinked_wave", kinked, ["-heat_mesh", "wave"])
    check(r.returncode == 0 and not [l for l in r.stdout.splitlines() if "warning" in l and "crack_k" in l],
          "kinked crack, -heat_mesh wave: no warning")

check.finish()
