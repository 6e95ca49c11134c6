"""Writes a gmsh 2.2 ASCII mesh of a box of uniform hexahedra with a rectangular crack on a
grid plane y = const (physical surfaces crack1, source on the top face y = H, absorbing on
the other faces): the 3D -mesh_file of the tests, independent of vibrotherm's box grid.

    write_box_msh(path, n=(nx, ny, nz), h, crack=(j, i0, i1, k0, k1))
the crack on node plane y = j h, cells i0..i1-1 along x, k0..k1-1 along z."""


def write_box_msh(path, n, h, crack, tets=False):
    nx, ny, nz = n
    node = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", "4",
             '2 1 "crack1"', '2 2 "source"', '2 3 "absorbing"', '3 4 "body"', "$EndPhysicalNames", "$Nodes",
             str((nx + 1) * (ny + 1) * (nz + 1))]
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                lines.append("%d %.17g %.17g %.17g" % (node(i, j, k), i * h, j * h, k * h))
    lines.append("$EndNodes")
    elements = []
    quad = lambda phys, a, b, c, d: elements.append("3 2 %d %d %d %d %d %d" % (phys, phys, a, b, c, d))
    jc, i0, i1, k0, k1 = crack
    for i in range(i0, i1):
        for k in range(k0, k1):
            quad(1, node(i, jc, k), node(i + 1, jc, k), node(i + 1, jc, k + 1), node(i, jc, k + 1))
    for i in range(nx):
        for k in range(nz):
            quad(2, node(i, ny, k), node(i, ny, k + 1), node(i + 1, ny, k + 1), node(i + 1, ny, k))
            quad(3, node(i, 0, k), node(i + 1, 0, k), node(i + 1, 0, k + 1), node(i, 0, k + 1))
    for j in range(ny):
        for k in range(nz):
            quad(3, node(0, j, k), node(0, j, k + 1), node(0, j + 1, k + 1), node(0, j + 1, k))
            quad(3, node(nx, j, k), node(nx, j + 1, k), node(nx, j + 1, k + 1), node(nx, j, k + 1))
    for i in range(nx):
        for j in range(ny):
            quad(3, node(i, j, 0), node(i, j + 1, 0), node(i + 1, j + 1, 0), node(i + 1, j, 0))
            quad(3, node(i, j, nz), node(i + 1, j, nz), node(i + 1, j + 1, nz), node(i, j + 1, nz))
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                v = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                     node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                if tets:  # one tetrahedron a cell is enough to be refused
                    elements.append("4 2 4 4 %d %d %d %d" % (v[0], v[1], v[3], v[4]))
                else:
                    elements.append("5 2 4 4 " + " ".join(map(str, v)))
    lines += ["$Elements", str(len(elements))]
    lines += ["%d %s" % (e + 1, text) for e, text in enumerate(elements)]
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
