// Contact patch test: two stacked blocks 1 x 0.5 mm, lower [0, 1] x [-0.5, 0],
// upper [0, 1] x [0, 0.5], meshed separately with non-matching interfaces:
// the lower top has nl uniform elements, the upper bottom nu elements
// graded by the progression g (spacing ratio 3.7 .. 4.3), so no interior interface node of one body
// coincides with one of the other (only the end points x = 0 and 1 do; with
// g = 1.0076 the closest interior pair is 0.0119 mm apart for Q4, 0.0062 mm for Q8).
// Units mm.
// Parameters (gmsh -setnumber NAME VALUE), defaults = patch_q4.msh:
//   nl, nu  interface elements of the lower / upper block; order 1 (Q4) or 2 (Q8)
DefineConstant[ nl = 5, nu = 20, g = 1.0076, order = 1 ];

Point(1) = {0, -0.5, 0}; Point(2) = {1, -0.5, 0}; Point(3) = {1, 0, 0}; Point(4) = {0, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nl + 1;
Transfinite Curve{2, 4} = Ceil(nl/2) + 1;
Transfinite Surface{1};

Point(5) = {0, 0, 0}; Point(6) = {1, 0, 0}; Point(7) = {1, 0.5, 0}; Point(8) = {0, 0.5, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {8, 7}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, -7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = nu + 1 Using Progression g;   // both left to right
Transfinite Curve{6, 8} = Ceil(nu/2) + 1;
Transfinite Surface{2};

Recombine Surface{:};
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 1;
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;

Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_right") = {2};
Physical Curve("lower_top") = {3};       // contact
Physical Curve("lower_left") = {4};
Physical Curve("upper_bottom") = {5};    // contact
Physical Curve("upper_right") = {6};
Physical Curve("upper_top") = {7};       // pressure
Physical Curve("upper_left") = {8};
Physical Point("lower_anchor") = {1};    // (0, -0.5): held in x
Physical Point("upper_anchor") = {8};    // (0, 0.5): held in x
