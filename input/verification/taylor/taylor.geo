// Plane-strain Taylor test: a bar (slab of unit thickness) 2 a wide and L
// long moving in -y hits a stiff, heavy wall (y < 0), frictionless. Half
// model: x >= 0, the symmetry line x = 0 is held in x on both bodies.
// bar  [0, a] x [g, g + L],  wall [0, w] x [-d, 0]; gap g between them.
// Meshed separately, structured; the bar has nx x ny elements (square for
// nx : ny = a : L), the wall nw x nd. Units mm.
// Parameters (gmsh -setnumber NAME VALUE): nx, ny (bar), nw, nd (wall).
DefineConstant[ nx = 8, ny = 80, nw = 24, nd = 8 ];
a = 1; L = 10; g = 0.01; w = 3; d = 1;
Point(1) = {0, g, 0}; Point(2) = {a, g, 0}; Point(3) = {a, g + L, 0}; Point(4) = {0, g + L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {0, -d, 0}; Point(6) = {w, -d, 0}; Point(7) = {w, 0, 0}; Point(8) = {0, 0, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Curve{5, 7} = nw + 1;
Transfinite Curve{6, 8} = nd + 1;
Transfinite Surface{1, 2};
Recombine Surface{:};
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
Physical Surface("bar") = {1};
Physical Surface("wall") = {2};
Physical Curve("bar_face") = {1};     // impact face, contact slave, faces -y
Physical Curve("bar_side") = {2};     // free side (the mushroom)
Physical Curve("bar_top") = {3};      // free end
Physical Curve("bar_axis") = {4};     // symmetry, u_x = 0
Physical Curve("wall_top") = {7};     // contact master, faces +y
Physical Curve("wall_bottom") = {5};  // held
Physical Curve("wall_axis") = {8};    // symmetry, u_x = 0
Physical Curve("wall_side") = {6};
