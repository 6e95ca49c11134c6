// A 5 cm x 10 cm plate with two embedded cracks, for -mesh_file.
// Physical curve names are what vibrotherm reads: source, absorbing, sink, crack*.
// Regenerate: gmsh -2 -format msh41 plate_two_cracks.geo (quads by recombination).
h = 0.004;
hc = 0.001;
Point(1) = {0, 0, 0, h};
Point(2) = {0.05, 0, 0, h};
Point(3) = {0.05, 0.1, 0, h};
Point(4) = {0, 0.1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
// crack_a: horizontal, 1.2 cm, centred at (0.02, 0.03)
Point(5) = {0.014, 0.03, 0, hc};
Point(6) = {0.026, 0.03, 0, hc};
Line(5) = {5, 6};
// crack_b: inclined, from (0.02, 0.065) to (0.035, 0.075)
Point(7) = {0.02, 0.065, 0, hc};
Point(8) = {0.035, 0.075, 0, hc};
Line(6) = {7, 8};
Curve{5, 6} In Surface{1};
Physical Curve("source") = {3};
Physical Curve("absorbing") = {1, 2, 4};
Physical Curve("sink") = {1, 2, 3, 4};
Physical Curve("crack_a") = {5};
Physical Curve("crack_b") = {6};
Physical Surface("specimen") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
