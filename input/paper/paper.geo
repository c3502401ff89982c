// Baillet & Sassi (2003), section 4: a disc part pressed into a thin soft block.
// Omega1 = lower half of the disc of radius 1 mm centred at (0, 1): flat top
// y = 1 (Gamma_u^1, driven), arc touching the block at (0, 0).
// Omega2 = block [-0.9, 0.9] x [-0.3, 0] (bottom Gamma_u^2 clamped).
// Units mm. The two bodies are meshed separately (no shared nodes); their
// contact curves touch at (0, 0) only and carry different node spacings.
//
// Parameters (gmsh -setnumber NAME VALUE), defaults = paper_q4.msh:
//   hb    block top element size in |x| < 0.7 (uniform)
//   nd    disc arc elements in |x| < 0.7 (even; uniform along the arc)
//   hcd   disc element size far from the contact (at the flat top)
//   order 1 = Q4, 2 = Q8 (serendipity)
// For Q8 the sizes are element sizes: halve the node spacing of a Q4 mesh
// with the same hb by passing twice the Q4 value.
DefineConstant[ hb = 0.02, nd = 56, hcd = 0.08, order = 1 ];

xc = 0.7;                       // refined interface zone |x| < xc
s0 = xc; c0 = Sqrt(1 - s0*s0);  // sin, cos of the arc angle at x = xc
hd = 2*Asin(s0)/nd;             // disc arc element length (uniform)
tb = 0.15;                      // radial thickness of the structured band under the arc
nr = Ceil(tb/hd - 0.3);         // band layers: about square elements

// ---------------- Omega1: the disc ----------------
Point(1) = {0, 1, 0};                      // centre (geometry only)
Point(2) = {-1, 1, 0};                     // ends of the flat top
Point(3) = { 1, 1, 0};
Point(4) = {-s0, 1 - c0, 0};               // arc at x = -0.7
Point(5) = {0, 0, 0};                      // lowest point
Point(6) = { s0, 1 - c0, 0};               // arc at x = +0.7
ri = 1 - tb;                               // inner radius of the band
Point(7) = {-s0*ri, 1 - c0*ri, 0};
Point(8) = {0, 1 - ri, 0};
Point(9) = { s0*ri, 1 - c0*ri, 0};

Circle(1) = {2, 1, 4};     // left outer arc (coarse)
Circle(2) = {4, 1, 5};     // contact arc, left half
Circle(3) = {5, 1, 6};     // contact arc, right half
Circle(4) = {6, 1, 3};     // right outer arc (coarse)
Line(5) = {3, 2};          // flat top, right to left
Line(6) = {4, 7};          // band radial sides
Line(7) = {5, 8};
Line(8) = {6, 9};
Circle(9) = {7, 1, 8};     // band inner arcs
Circle(10) = {8, 1, 9};

Curve Loop(1) = {2, 7, -9, -6};            // band, left (counter-clockwise)
Plane Surface(1) = {1};
Curve Loop(2) = {3, 8, -10, -7};           // band, right
Plane Surface(2) = {2};
Curve Loop(3) = {1, 6, 9, 10, -8, 4, 5};   // rest of the half-disc
Plane Surface(3) = {3};

Transfinite Curve{2, 3, 9, 10} = nd/2 + 1;
Transfinite Curve{6, 7, 8} = nr + 1;
Transfinite Surface{1} = {4, 5, 8, 7};
Transfinite Surface{2} = {5, 6, 9, 8};

// size grows from the band (hd) to hcd at the top; the coarse arcs follow it
Field[1] = Distance;
Field[1].CurvesList = {9, 10};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hd;
Field[2].SizeMax = hcd;
Field[2].DistMin = 0.02;
Field[2].DistMax = 0.6;
Background Field = 2;

// ---------------- Omega2: the block ----------------
hs = 2*hb;                                 // block size beyond |x| = 0.7
r = 1.12;                                  // vertical growth, fine at the top
ny = Ceil(Log(1 + 0.3*(r - 1)/hb)/Log(r));
Point(11) = {-0.9, -0.3, 0}; Point(12) = {-xc, -0.3, 0};
Point(13) = { xc, -0.3, 0};  Point(14) = { 0.9, -0.3, 0};
Point(15) = { 0.9, 0, 0};    Point(16) = { xc, 0, 0};
Point(17) = {-xc, 0, 0};     Point(18) = {-0.9, 0, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14};   // bottom
Line(14) = {15, 14};                                             // right side, top to bottom
Line(15) = {15, 16}; Line(16) = {16, 17}; Line(17) = {17, 18};   // top, right to left
Line(18) = {18, 11};                                             // left side, top to bottom
Line(19) = {16, 13}; Line(20) = {17, 12};                        // inner verticals, top to bottom
Curve Loop(11) = {11, -20, 17, 18};  Plane Surface(11) = {11};   // left
Curve Loop(12) = {12, -19, 16, 20};  Plane Surface(12) = {12};   // middle
Curve Loop(13) = {13, -14, 15, 19};  Plane Surface(13) = {13};   // right
Transfinite Curve{12, 16} = Round(2*xc/hb) + 1;
Transfinite Curve{11, 17, 13, 15} = Round((0.9 - xc)/hs) + 1;
Transfinite Curve{14, 18, 19, 20} = ny + 1 Using Progression r;
Transfinite Surface{11, 12, 13};

// the block is structured: keep the background field off its curves
Field[3] = Restrict;
Field[3].InField = 2;
Field[3].SurfacesList = {3};
Field[3].CurvesList = {1, 4, 5};
Background Field = 3;

Recombine Surface{:};
Mesh.Algorithm = 6;                 // frontal-Delaunay, then blossom recombination (Algorithm 8 crashes Gmsh 4.8 here)
Mesh.RecombinationAlgorithm = 1;    // blossom
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 1;
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;

Physical Surface("disc") = {1, 2, 3};
Physical Surface("block") = {11, 12, 13};
Physical Curve("disc_top") = {5};              // Gamma_u^1, driven
Physical Curve("disc_arc") = {1, 2, 3, 4};     // Gamma_c^1 (whole arc)
Physical Curve("block_top") = {17, 16, 15};    // Gamma_c^2 (whole top)
Physical Curve("block_bottom") = {11, 12, 13}; // Gamma_u^2, clamped
Physical Curve("block_left") = {18};
Physical Curve("block_right") = {14};
