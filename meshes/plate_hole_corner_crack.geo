// A cracked part: an aluminium plate 20 x 40 x 3 mm (x, y, z; z = 3 mm the front face the
// camera films) with a fastener hole of 5 mm diameter through its middle, and a
// quarter-elliptical corner crack at the hole's edge, as fatigue under loading along the
// plate's length (y) grows it: in the plane y = 20 mm through the hole's centre, from the
// bore (x = 12.5 mm) and the front face, a = 1.5 mm along the front face (x) and c = 1 mm
// deep (z). A 4 x 4 mm transducer patch ("source") on the back face, 10 mm below the hole.
//
// All hexahedra, structured blocks (gmsh's transfinite meshing, built-in kernel), so that
// the explicit Q2 step is the cells' size, not a sliver's: around the hole an O-grid of
// rings (hc wide where the crack lies, then one ring to a 10 mm square), 12 sectors whose
// rays end on the square's corners and on the plate's block lines; outside the square a
// tensor grid of rectangles up to hmax; through the thickness, layers of hc over the
// crack's depth and of about 2 hc below. The crack plane is the ray at angle 0 (y = 20 mm),
// between sectors; the crack ("crack1") is the staircase of that ray's faces whose centres
// lie in the quarter ellipse (as the generated box makes an ellipse), its mouth on the bore
// and the front face. Measured in docs/MEASUREMENTS.md ("A cracked part from a geometry
// file").
//   gmsh meshes/plate_hole_corner_crack.geo -3 -o plate_hole.msh      (Debian package gmsh)
// or let vibrotherm mesh it: -mesh_file meshes/plate_hole_corner_crack.geo
// (options/plate_hole.opts). -setnumber hc 0.125e-3 halves the cells at the crack.
If (!Exists(hc)) hc = 0.25e-3; EndIf    // cells at the crack [m]
If (!Exists(hmax)) hmax = 1.5e-3; EndIf // cells away from it [m]
L = 0.02; W = 0.04; T = 0.003; R = 0.0025;
a = 0.0015; c = 0.001;                   // the crack: along the front face, deep
xh = 0.5 * L; yh = 0.5 * W; S = 0.005;   // the hole's centre, the O-grid square's half side
px = 0.008; py = 0.004; ps = 0.004;      // the transducer patch: corner, side

// Block lines of the tensor grid outside the square (the square's sides and the patch's
// edges among them), and the cells of each interval.
xs[] = {0, xh - S, px, xh, px + ps, xh + S, L};
ys[] = {0, py, py + ps, yh - S, yh, yh + S, W};

// The square's 12 boundary points, counter-clockwise from angle 0 (the crack's ray).
sx[] = {xh + S, xh + S, px + ps, xh, px, xh - S, xh - S, xh - S, px, xh, px + ps, xh + S};
sy[] = {yh, yh + S, yh + S, yh + S, yh + S, yh + S, yh, yh - S, yh - S, yh - S, yh - S, yh - S};
NS = 12;
// Cells a sector along its arc: about hc on the bore.
For m In {0 : NS - 1}
  m1 = (m + 1) % NS;
  t0 = Atan2(sy[m] - yh, sx[m] - xh); t1 = Atan2(sy[m1] - yh, sx[m1] - xh);
  dt = t1 - t0; If (dt < 0) dt += 2 * Pi; EndIf
  sector_cells[m] = Max(1, Ceil((dt * R) / (hc) - 0.01));
EndFor

// Rings: radii R + k a / na (k = 0 .. na), then the square.
na = Round(a / hc); If (na < 2) na = 2; EndIf
For k In {0 : na}
  r = R + k * a / na;
  For m In {0 : NS - 1}
    t = Atan2(sy[m] - yh, sx[m] - xh);
    ring_pt[k * NS + m] = newp; Point(ring_pt[k * NS + m]) = {xh + r * Cos(t), yh + r * Sin(t), 0};
  EndFor
EndFor
centre = newp; Point(centre) = {xh, yh, 0};
For m In {0 : NS - 1}
  sq_pt[m] = newp; Point(sq_pt[m]) = {sx[m], sy[m], 0};
EndFor
// Arcs of each ring, straight sides of the square.
For k In {0 : na}
  For m In {0 : NS - 1}
    arc[k * NS + m] = newc; Circle(arc[k * NS + m]) = {ring_pt[k * NS + m], centre, ring_pt[k * NS + (m + 1) % NS]};
    Transfinite Curve {arc[k * NS + m]} = sector_cells[m] + 1;
  EndFor
EndFor
For m In {0 : NS - 1}
  side[m] = newc; Line(side[m]) = {sq_pt[m], sq_pt[(m + 1) % NS]};
  Transfinite Curve {side[m]} = sector_cells[m] + 1;
EndFor
// Rays: one cell between rings, then graded to the square.
r_out = R + a; d_sq = S - r_out; n_out = Max(1, Ceil((d_sq) / (0.5 * (a / na + hmax)) - 0.01));
For k In {0 : na - 1}
  For m In {0 : NS - 1}
    ray[k * NS + m] = newc; Line(ray[k * NS + m]) = {ring_pt[k * NS + m], ring_pt[(k + 1) * NS + m]};
    Transfinite Curve {ray[k * NS + m]} = 2;
  EndFor
EndFor
For m In {0 : NS - 1}
  ray_out[m] = newc; Line(ray_out[m]) = {ring_pt[na * NS + m], sq_pt[m]};
  Transfinite Curve {ray_out[m]} = n_out + 1 Using Progression 1.15;
EndFor
base[] = {};
For k In {0 : na - 1}
  For m In {0 : NS - 1}
    m1 = (m + 1) % NS;
    cl = newll; Curve Loop(cl) = {arc[k * NS + m], ray[k * NS + m1], -arc[(k + 1) * NS + m], -ray[k * NS + m]};
    s = news; Plane Surface(s) = {cl}; Transfinite Surface {s}; Recombine Surface {s}; base[] += s;
  EndFor
EndFor
For m In {0 : NS - 1}
  m1 = (m + 1) % NS;
  cl = newll; Curve Loop(cl) = {arc[na * NS + m], ray_out[m1], -side[m], -ray_out[m]};
  s = news; Plane Surface(s) = {cl}; Transfinite Surface {s}; Recombine Surface {s}; base[] += s;
EndFor

// The tensor grid outside the square: points, lines and rectangles; the square's own points
// and sides are reused where the grid meets it (its sides are the grid's lines there).
NX = #xs[]; NY = #ys[];
For i In {0 : NX - 1}
  For j In {0 : NY - 1}
    g_pt[i * NY + j] = -1;
    For m In {0 : NS - 1}
      If (Abs(sx[m] - xs[i]) < 1e-12 && Abs(sy[m] - ys[j]) < 1e-12) g_pt[i * NY + j] = sq_pt[m]; EndIf
    EndFor
    If (g_pt[i * NY + j] < 0)
      g_pt[i * NY + j] = newp; Point(g_pt[i * NY + j]) = {xs[i], ys[j], 0};
    EndIf
  EndFor
EndFor
// Cells of each interval: the square's sectors where it bounds the square, else about hmax.
For i In {0 : NX - 2}
  nx[i] = Max(1, Ceil((xs[i + 1] - xs[i]) / (hmax) - 0.01));
EndFor
For j In {0 : NY - 2}
  ny[j] = Max(1, Ceil((ys[j + 1] - ys[j]) / (hmax) - 0.01));
EndFor
For m In {0 : NS - 1}  // a side of the square fixes its interval's cells
  m1 = (m + 1) % NS;
  For i In {0 : NX - 2}
    If (Abs(sy[m] - sy[m1]) < 1e-12 && Abs(Min(sx[m], sx[m1]) - xs[i]) < 1e-12 && Abs(Max(sx[m], sx[m1]) - xs[i + 1]) < 1e-12)
      nx[i] = sector_cells[m];
    EndIf
  EndFor
  For j In {0 : NY - 2}
    If (Abs(sx[m] - sx[m1]) < 1e-12 && Abs(Min(sy[m], sy[m1]) - ys[j]) < 1e-12 && Abs(Max(sy[m], sy[m1]) - ys[j + 1]) < 1e-12)
      ny[j] = sector_cells[m];
    EndIf
  EndFor
EndFor
// Horizontal lines h(i, j): (xs[i], ys[j]) -> (xs[i+1], ys[j]); vertical v(i, j): (xs[i], ys[j]) -> (xs[i], ys[j+1]).
For i In {0 : NX - 2}
  For j In {0 : NY - 1}
    h_line[i * NY + j] = -1;
    qx = 0.5 * (xs[i] + xs[i + 1]); qy = ys[j];
    in_sq = (qx > xh - S - 1e-12 && qx < xh + S + 1e-12 && qy > yh - S - 1e-12 && qy < yh + S + 1e-12);  // on the square or in it
    If (!in_sq)
      h_line[i * NY + j] = newc; Line(h_line[i * NY + j]) = {g_pt[i * NY + j], g_pt[(i + 1) * NY + j]};
    EndIf
    If (in_sq)  // on the square's side (or inside it: unused)
      For m In {0 : NS - 1}
        m1 = (m + 1) % NS;
        If (Abs(sy[m] - ys[j]) < 1e-12 && Abs(sy[m1] - ys[j]) < 1e-12 && Abs(Min(sx[m], sx[m1]) - xs[i]) < 1e-12)
          h_line[i * NY + j] = side[m];
        EndIf
      EndFor
    EndIf
    If (h_line[i * NY + j] >= 0) Transfinite Curve {Abs(h_line[i * NY + j])} = nx[i] + 1; EndIf
  EndFor
EndFor
For i In {0 : NX - 1}
  For j In {0 : NY - 2}
    v_line[i * NY + j] = -1;
    qx = xs[i]; qy = 0.5 * (ys[j] + ys[j + 1]);
    in_sq = (qx > xh - S - 1e-12 && qx < xh + S + 1e-12 && qy > yh - S - 1e-12 && qy < yh + S + 1e-12);
    If (!in_sq)
      v_line[i * NY + j] = newc; Line(v_line[i * NY + j]) = {g_pt[i * NY + j], g_pt[i * NY + j + 1]};
    EndIf
    If (in_sq)
      For m In {0 : NS - 1}
        m1 = (m + 1) % NS;
        If (Abs(sx[m] - xs[i]) < 1e-12 && Abs(sx[m1] - xs[i]) < 1e-12 && Abs(Min(sy[m], sy[m1]) - ys[j]) < 1e-12)
          v_line[i * NY + j] = side[m];
        EndIf
      EndFor
    EndIf
    If (v_line[i * NY + j] >= 0) Transfinite Curve {Abs(v_line[i * NY + j])} = ny[j] + 1; EndIf
  EndFor
EndFor
For i In {0 : NX - 2}
  For j In {0 : NY - 2}
    qx = 0.5 * (xs[i] + xs[i + 1]); qy = 0.5 * (ys[j] + ys[j + 1]);
    in_sq = (qx > xh - S && qx < xh + S && qy > yh - S && qy < yh + S);
    If (!in_sq)
      loop[] = {h_line[i * NY + j], v_line[(i + 1) * NY + j], h_line[i * NY + j + 1], v_line[i * NY + j]};
      // Each edge counter-clockwise around the rectangle (corner e to corner e + 1); a line
      // made here or a square side (which runs around the square) is reversed when it
      // starts at the other end.
      starts[] = {g_pt[i * NY + j], g_pt[(i + 1) * NY + j], g_pt[(i + 1) * NY + j + 1], g_pt[i * NY + j + 1]};
      For side_k In {0 : 3}
        ends[] = Boundary{ Curve{loop[side_k]}; };
        dir[side_k] = 1; If (ends[0] != starts[side_k]) dir[side_k] = -1; EndIf
      EndFor
      cl = newll;
      Curve Loop(cl) = {dir[0] * loop[0], dir[1] * loop[1], dir[2] * loop[2], dir[3] * loop[3]};
      s = news; Plane Surface(s) = {cl}; Transfinite Surface {s}; Recombine Surface {s}; base[] += s;
    EndIf
  EndFor
EndFor

// Through the thickness: layers below the crack, then one layer of c / nc per stage over
// its depth (each stage's rays' faces are the crack's staircase candidates).
nc = Round(c / hc); If (nc < 2) nc = 2; EndIf
n_below = Max(1, Ceil((T - c) / (2 * hc) - 0.01));
eps = 1e-9;  // the bounding boxes' margin [m]
Extrude {0, 0, T - c} { Surface{base[]}; Layers{n_below}; Recombine; }
For j In {0 : nc - 1}
  z0 = T - c + j * c / nc;
  top[] = Surface In BoundingBox{-eps, -eps, z0 - eps, L + eps, W + eps, z0 + eps};
  If (#top[] != #base[]) Error("plate_hole_corner_crack.geo: %g faces at z = %g, the base has %g", #top[], z0, #base[]); EndIf
  Extrude {0, 0, c / nc} { Surface{top[]}; Layers{1}; Recombine; }
EndFor

// The crack: the faces on the ray y = yh (one ring wide, one stage deep) whose centres lie
// in the quarter ellipse ((x - xh - R) / a)^2 + ((T - z) / c)^2 <= 1.
crack[] = {};
For k In {0 : na - 1}
  For j In {0 : nc - 1}
    u = (k + 0.5) / na; w = (j + 0.5) / nc;
    If (u * u + w * w <= 1)
      x0 = xh + R + k * a / na; z1 = T - j * c / nc;
      face[] = Surface In BoundingBox{x0 - eps, yh - eps, z1 - c / nc - eps, x0 + a / na + eps, yh + eps, z1 + eps};
      If (#face[] != 1) Error("plate_hole_corner_crack.geo: %g faces at the crack's cell (%g, %g)", #face[], k, j); EndIf
      crack[] += face[];
    EndIf
  EndFor
EndFor
patch[] = Surface In BoundingBox{px - eps, py - eps, -eps, px + ps + eps, py + ps + eps, eps};
Physical Surface("crack1") = crack[];
Physical Surface("source") = patch[];
Physical Volume("body") = Volume{:};
Mesh.MshFileVersion = 2.2;
