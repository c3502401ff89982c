// Seed mesh of the fuzz set (tests/fuzz): a 10 x 2 mm plate of 5 x 1
// elements, small so that a valid run takes milliseconds.
// Regenerate (Gmsh 4.x):
//   gmsh plate.geo -2 -format msh41 -o plate.msh
//   gmsh plate.geo -2 -format msh22 -setnumber order 2 -o plate_q8.msh
DefineConstant[ order = 1 ];
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 2, 0}; Point(4) = {0, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 6; Transfinite Curve{2, 4} = 2;
Transfinite Surface{1}; Recombine Surface{1};
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = 1;
Physical Surface("plate") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Point("corner") = {1};
