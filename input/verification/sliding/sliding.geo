// A small block (slider) [-0.5, 0.5] x [0, 0.5] on a large block (base)
// [-2, 2] x [-0.5, 0], meshed separately: base top h = 4/nb, slider bottom
// h = 1/ns (non-matching). Units mm.
// Parameters (gmsh -setnumber NAME VALUE): nb, ns, order (1 Q4, 2 Q8).
DefineConstant[ nb = 80, ns = 14, order = 1 ];
Point(1) = {-2, -0.5, 0}; Point(2) = {2, -0.5, 0}; Point(3) = {2, 0, 0}; Point(4) = {-2, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nb + 1; Transfinite Curve{2, 4} = Round(nb/8) + 1;
Point(5) = {-0.5, 0, 0}; Point(6) = {0.5, 0, 0}; Point(7) = {0.5, 0.5, 0}; Point(8) = {-0.5, 0.5, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = ns + 1; Transfinite Curve{6, 8} = Round(ns/2) + 1;
Transfinite Surface{1, 2};
Recombine Surface{:};
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 1;
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
Physical Surface("base") = {1};
Physical Surface("slider") = {2};
Physical Curve("base_bottom") = {1};
Physical Curve("base_top") = {3};          // contact
Physical Curve("base_sides") = {2, 4};
Physical Curve("slider_bottom") = {5};     // contact
Physical Curve("slider_right") = {6};      // pulled in +x
Physical Curve("slider_top") = {7};        // pressed
Physical Curve("slider_left") = {8};
