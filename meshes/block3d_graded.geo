// A block 20 x 20 x 10 mm (block3d_small's) with a buried crack 6 x 4 mm on the plane
// y = 10 mm (along x: block3d_small's is turned 20 degrees), the source on the top face,
// the bottom face absorbing, the others free; meshed unstructured and graded: tetrahedra of about hc at the crack and 4 hc
// away from it, each split into four hexahedra (gmsh's SubdivisionAlgorithm 2), so that
// local time stepping has cells of several sizes in 3D (tests/scene/test_local_time_stepping_3d.py).
// Regenerate: gmsh meshes/block3d_graded.geo -3 -o meshes/block3d_graded.msh (Debian package gmsh)
SetFactory("OpenCASCADE");
If (!Exists(hc)) hc = 0.0015; EndIf
Box(1) = {0, 0, 0, 0.02, 0.02, 0.01};
Rectangle(10) = {0.007, 0.003, 0, 0.006, 0.004};
Rotate {{1, 0, 0}, {0, 0, 0}, Pi/2} { Surface{10}; }
Translate {0, 0.01, 0} { Surface{10}; }
v() = BooleanFragments{ Volume{1}; Delete; }{ Surface{10}; Delete; };
e = 1e-6;
crack() = Surface In BoundingBox{0.007 - e, 0.01 - e, 0.003 - e, 0.013 + e, 0.01 + e, 0.007 + e};
Physical Surface("crack1") = crack();
Physical Surface("source") = Surface In BoundingBox{-e, 0.02 - e, -e, 0.02 + e, 0.02 + e, 0.01 + e};
Physical Surface("absorbing") = Surface In BoundingBox{-e, -e, -e, 0.02 + e, e, 0.01 + e};
Physical Volume("body") = Volume{:};
Field[1] = Distance; Field[1].SurfacesList = crack();
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = hc; Field[2].SizeMax = 4 * hc;
Field[2].DistMin = 0.0005; Field[2].DistMax = 0.006;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.SubdivisionAlgorithm = 2;
Mesh.Optimize = 1;
Mesh.MshFileVersion = 2.2;
Mesh.Binary = 0;
