// Hertz point contact, axisymmetric (tests/axisymmetric; doc/verification.md):
// the r-z section of a sphere of radius R = 10 mm (the quarter disc centred at
// (0, R), flat top z = R) on a block [0, 20] x [-20, 0] (20 a) standing for the
// half-space. x is the radius, y the axis of symmetry. They touch at (0, 0);
// the contact radius at the test load is a ~ 1 mm = R/10.
// Under the contact both bodies have a structured band in r < 2 mm with
// uniform interface spacing (non-matching: different element counts);
// elsewhere the mesh is unstructured quadrilateral, growing away from (0, 0).
// Adapted from input/verification/hertz/hertz.geo (the plane-strain
// cylinder), keeping the half x >= 0. Units mm.
//
// Parameters (gmsh -setnumber NAME VALUE):
//   nb    block top elements in r < 2 (uniform)
//   nc    sphere arc elements in r < 2 (uniform along the arc)
//   hmax  largest element size (far from the contact)
//   order 1 = Q4, 2 = Q8
DefineConstant[ nb = 20, nc = 24, hmax = 4.0, order = 1 ];

R = 10; W = 20; H = 20; xc = 2;
hbk = xc/nb;
s0 = xc/R; c0 = Sqrt(1 - s0*s0);
hcy = R*Asin(s0)/nc;
tb = 0.5;
nrc = Ceil(tb/hcy - 0.3); nrb = Ceil(tb/hbk - 0.3);

// ---------------- the sphere ----------------
Point(1) = {0, R, 0};
Point(3) = {R, R, 0};
Point(5) = {0, 0, 0};
Point(6) = {xc, R - R*c0, 0};
ri = R - tb;
Point(8) = {0, tb, 0};
Point(9) = {xc*ri/R, R - c0*ri, 0};
Circle(3) = {5, 1, 6}; Circle(4) = {6, 1, 3};
Line(5) = {3, 1};
Line(8) = {5, 8}; Line(9) = {6, 9};
Circle(11) = {8, 1, 9};
Line(12) = {8, 1};
Curve Loop(2) = {3, 9, -11, -8};  Plane Surface(2) = {2};
Curve Loop(4) = {-9, 4, 5, -12, 11};  Plane Surface(4) = {4};
Transfinite Curve{3, 11} = nc + 1;
Transfinite Curve{8, 9} = nrc + 1;
Transfinite Surface{2} = {5, 6, 9, 8};
gr = 1.15;
larc = R*(Pi/2 - Asin(s0));
narc = Ceil(Log(1 + larc*(gr - 1)/hcy)/Log(gr));
nax = Ceil(Log(1 + (R - tb)*(gr - 1)/hcy)/Log(gr));
ntop = Ceil(R/hmax);
If ((narc + nrc + nc + nax + ntop) % 2 == 1)
  ntop = ntop + 1;
EndIf
Transfinite Curve{4} = narc + 1 Using Progression gr;
Transfinite Curve{12} = nax + 1 Using Progression gr;
Transfinite Curve{5} = ntop + 1;

// ---------------- the block ----------------
Point(11) = {0, -H, 0}; Point(12) = {W, -H, 0}; Point(13) = {W, 0, 0};
Point(14) = {xc, 0, 0}; Point(15) = {0, 0, 0};
Point(17) = {xc, -tb, 0}; Point(18) = {0, -tb, 0};
Line(21) = {11, 12}; Line(22) = {12, 13};
Line(23) = {13, 14}; Line(24) = {14, 15};
Line(27) = {14, 17}; Line(28) = {17, 18}; Line(29) = {18, 15};
Line(30) = {18, 11};
Curve Loop(11) = {-28, -27, 24, -29};  Plane Surface(11) = {11};
Curve Loop(12) = {21, 22, 23, 27, 28, 30};  Plane Surface(12) = {12};
Transfinite Curve{24, 28} = nb + 1;
Transfinite Curve{27, 29} = nrb + 1;
Transfinite Surface{11};
// fixed counts on the other curves of the unstructured part, graded from the
// band, with an even number of boundary edges in all (Blossom needs it)
n23 = Ceil(Log(1 + (W - xc)*(gr - 1)/hbk)/Log(gr));
n30 = Ceil(Log(1 + (H - tb)*(gr - 1)/hbk)/Log(gr));
n21 = Ceil(W/hmax); n22 = Ceil(H/hmax);
If ((n21 + n22 + n23 + nrb + nb + n30) % 2 == 1)
  n21 = n21 + 1;
EndIf
Transfinite Curve{23} = n23 + 1 Using Progression 1/gr;
Transfinite Curve{30} = n30 + 1 Using Progression gr;
Transfinite Curve{21} = n21 + 1;
Transfinite Curve{22} = n22 + 1;

Field[1] = Distance;
Field[1].PointsList = {5};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hcy;
Field[2].SizeMax = hmax;
Field[2].DistMin = 2.2;
Field[2].DistMax = 20;
Background Field = 2;

Recombine Surface{:};
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 1;
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;

Physical Surface("sphere") = {2, 4};
Physical Surface("block") = {11, 12};
Physical Curve("sphere_top") = {5};
Physical Curve("sphere_arc") = {3, 4};
Physical Curve("sphere_axis") = {8, 12};
Physical Curve("block_top") = {23, 24};
Physical Curve("block_bottom") = {21};
Physical Curve("block_right") = {22};
Physical Curve("block_axis") = {29, 30};
