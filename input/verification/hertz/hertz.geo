// Hertz line contact: a cylinder of radius R = 10 mm (the lower half-disc
// centred at (0, R), flat top y = R) on a block [-40, 40] x [-40, 0].
// They touch at (0, 0); the half-width at the design load is a ~ 1 mm = R/10.
// Under the contact both bodies have a structured band in |x| < 2 mm with
// uniform interface spacing (non-matching: different element counts);
// elsewhere the mesh is unstructured quadrilateral, growing away from (0, 0).
// The cylinder is split along its axis x = 0 (curve "cylinder_axis", a node
// set inside the body) so a symmetric run can hold the axis in x.
// Units mm. Also used by input/verification/cattaneo.
//
// Parameters (gmsh -setnumber NAME VALUE), defaults = hertz_q4.msh:
//   nb    block top elements in |x| < 2 (uniform)
//   nc    cylinder arc elements in |x| < 2 (even, uniform along the arc)
//   hmax  largest element size (far from the contact)
//   order 1 = Q4, 2 = Q8
DefineConstant[ nb = 60, nc = 70, hmax = 3.0, order = 1 ];

R = 10; W = 40; H = 40; xc = 2;      // half-width and depth of the block, refined zone
hbk = 2*xc/nb;                        // block interface element size
s0 = xc/R; c0 = Sqrt(1 - s0*s0);
hcy = 2*R*Asin(s0)/nc;                // cylinder interface element size (along the arc)
tb = 0.5;                             // depth of the structured bands
nrc = Ceil(tb/hcy - 0.3); nrb = Ceil(tb/hbk - 0.3);

// ---------------- the cylinder ----------------
Point(1) = {0, R, 0};                       // centre, on the flat top
Point(2) = {-R, R, 0}; Point(3) = {R, R, 0};
Point(4) = {-xc, R - R*c0, 0};              // arc at x = -2
Point(5) = {0, 0, 0};                       // lowest point
Point(6) = { xc, R - R*c0, 0};
ri = R - tb;
Point(7) = {-xc*ri/R, R - c0*ri, 0};
Point(8) = {0, tb, 0};
Point(9) = { xc*ri/R, R - c0*ri, 0};
Circle(1) = {2, 1, 4}; Circle(2) = {4, 1, 5}; Circle(3) = {5, 1, 6}; Circle(4) = {6, 1, 3};
Line(5) = {3, 1}; Line(6) = {1, 2};         // flat top, right to left, in two halves
Line(7) = {4, 7}; Line(8) = {5, 8}; Line(9) = {6, 9};
Circle(10) = {7, 1, 8}; Circle(11) = {8, 1, 9};
Line(12) = {8, 1};                          // axis above the band
Curve Loop(1) = {2, 8, -10, -7};  Plane Surface(1) = {1};   // band, left
Curve Loop(2) = {3, 9, -11, -8};  Plane Surface(2) = {2};   // band, right
Curve Loop(3) = {1, 7, 10, 12, 6};  Plane Surface(3) = {3}; // left quarter
Curve Loop(4) = {-9, 4, 5, -12, 11};  Plane Surface(4) = {4}; // right quarter
Transfinite Curve{2, 3, 10, 11} = nc/2 + 1;
Transfinite Curve{7, 8, 9} = nrc + 1;
Transfinite Surface{1} = {4, 5, 8, 7};
Transfinite Surface{2} = {5, 6, 9, 8};
// The unstructured quarters get fixed, graded counts on their other curves so
// that each has an even number of boundary edges (blossom needs it for an
// all-quadrilateral mesh): outer arcs and axis fine at the band, top uniform.
gr = 1.15;                                   // growth ratio along those curves
larc = R*(Pi/2 - Asin(s0));                  // outer arc length
narc = Ceil(Log(1 + larc*(gr - 1)/hcy)/Log(gr));
nax = Ceil(Log(1 + (R - tb)*(gr - 1)/hcy)/Log(gr));
ntop = Ceil(R/hmax);
If ((narc + nrc + nc/2 + nax + ntop) % 2 == 1)
  ntop = ntop + 1;
EndIf
Transfinite Curve{1} = narc + 1 Using Progression 1/gr;   // from (-R, R) down to the band
Transfinite Curve{4} = narc + 1 Using Progression gr;     // from the band up to (R, R)
Transfinite Curve{12} = nax + 1 Using Progression gr;     // from the band up to the centre
Transfinite Curve{5, 6} = ntop + 1;

// ---------------- the block ----------------
Point(11) = {-W, -H, 0}; Point(12) = {W, -H, 0}; Point(13) = {W, 0, 0};
Point(14) = {xc, 0, 0}; Point(15) = {-xc, 0, 0}; Point(16) = {-W, 0, 0};
Point(17) = {xc, -tb, 0}; Point(18) = {-xc, -tb, 0};
Line(21) = {11, 12}; Line(22) = {12, 13};
Line(23) = {13, 14}; Line(24) = {14, 15}; Line(25) = {15, 16};   // top, right to left
Line(26) = {16, 11};
Line(27) = {14, 17}; Line(28) = {17, 18}; Line(29) = {18, 15};
Curve Loop(11) = {-28, -27, 24, -29};  Plane Surface(11) = {11};           // band
Curve Loop(12) = {21, 22, 23, 27, 28, 29, 25, 26};  Plane Surface(12) = {12};
Transfinite Curve{24, 28} = nb + 1;
Transfinite Curve{27, 29} = nrb + 1;
Transfinite Surface{11};

// size: hbk..hcy near (0, 0), growing linearly to hmax
Field[1] = Distance;
Field[1].PointsList = {5};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hcy;
Field[2].SizeMax = hmax;
Field[2].DistMin = 2.2;
Field[2].DistMax = 25;
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

Physical Surface("cylinder") = {1, 2, 3, 4};
Physical Surface("block") = {11, 12};
Physical Curve("cylinder_top") = {5, 6};
Physical Curve("cylinder_arc") = {1, 2, 3, 4};
Physical Curve("cylinder_axis") = {8, 12};    // inside the body: a node set only
Physical Curve("block_top") = {23, 24, 25};
Physical Curve("block_bottom") = {21};
Physical Curve("block_left") = {26};
Physical Curve("block_right") = {22};
