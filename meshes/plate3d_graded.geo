// A plate 100 x 50 x 5 mm with a buried crack 4 mm long (x) and 2 mm deep (z), 0.5 mm
// under the front face z = 5 mm, on the plane y = 25 mm, and a 6 mm source patch on the
// back face; meshed unstructured and graded: tetrahedra of hc (1 mm) at the crack growing
// to 5 mm (capped at 2.5 mm) away from it, each split into four hexahedra. The cell-size
// spread of a real part, for measuring local time stepping in 3D (docs/MEASUREMENTS.md
// "Local time stepping in 3D"). Not committed as .msh (5 MB):
//   gmsh meshes/plate3d_graded.geo -3 -o plate3d_graded.msh      (Debian package gmsh)
SetFactory("OpenCASCADE");
If (!Exists(hc)) hc = 0.001; EndIf
L = 0.1; W = 0.05; T = 0.005;
Box(1) = {0, 0, 0, L, W, T};
Rectangle(10) = {0.048, 0.0, 0.0025, 0.004, 0.002};
Rotate {{1, 0, 0}, {0.048, 0.0, 0.0025}, Pi/2} { Surface{10}; }
Translate {0, 0.025, 0} { Surface{10}; }
Rectangle(20) = {0.012, 0.022, 0, 0.006, 0.006};
v() = BooleanFragments{ Volume{1}; Delete; }{ Surface{10, 20}; Delete; };
e = 1e-6;
crack() = Surface In BoundingBox{0.048 - e, 0.025 - e, 0.0025 - e, 0.052 + e, 0.025 + e, 0.0045 + e};
patch() = Surface In BoundingBox{0.012 - e, 0.022 - e, -e, 0.018 + e, 0.028 + e, e};
Physical Surface("crack1") = crack();
Physical Surface("source") = patch();
Physical Volume("body") = Volume{:};
Mesh.MeshSizeMax = 0.0025;
Field[1] = Distance; Field[1].SurfacesList = crack();
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = hc; Field[2].SizeMax = 0.005;
Field[2].DistMin = 0.0005; Field[2].DistMax = 0.012;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.SubdivisionAlgorithm = 2;
Mesh.MshFileVersion = 2.2;
