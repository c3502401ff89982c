// Two bodies for the mesh-reader tests: a block split in two halves by an
// interior curve, and a body with a curved (circular) bottom above it.
// Transfinite + Recombine gives a structured all-quad mesh, so the element
// and node counts asserted by the tests are stable across Gmsh versions.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};

// Upper body: flat top, circular-arc bottom (centre 11) bulging downwards.
Point(7) = {0.6, 1.2, 0};
Point(8) = {1.4, 1.2, 0};
Point(9) = {1.4, 1.6, 0};
Point(10) = {0.6, 1.6, 0};
Point(11) = {1.0, 1.8, 0};
Circle(8) = {7, 11, 8};
Line(9) = {8, 9};
Line(10) = {9, 10};
Line(11) = {10, 7};
Curve Loop(3) = {8, 9, 10, 11};
Plane Surface(3) = {3};

// A free point meshed as a lone node: it belongs to no element, so the
// reader must drop it (it would have zero mass).
Point(12) = {3, 3, 0};

Transfinite Curve{1, 2, 5, 4} = 5;
Transfinite Curve{6, 7, 3} = 4;
Transfinite Curve{8, 10} = 5;
Transfinite Curve{9, 11} = 3;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};

Physical Surface("block") = {1, 2};
Physical Surface("body") = {3};
Physical Curve("base") = {1, 2};
Physical Curve("block_top") = {4, 5};
Physical Curve("interface") = {7};
Physical Curve("body_bottom") = {8};
Physical Curve("body_top") = {10};
Physical Curve(20) = {6};          // unnamed: its name is "20"
Physical Point("anchor") = {1};
Physical Point("stray") = {12};
