// Unit square block, 4 x 4 elements, for the finite-strain tests
// (tests/finite). Q4 by default; gmsh -2 -order 2 with
// Mesh.SecondOrderIncomplete = 1 gives the Q8 twin (block_q8.msh).
Point(1) = {0, 0, 0, 1}; Point(2) = {1, 0, 0, 1};
Point(3) = {1, 1, 0, 1}; Point(4) = {0, 1, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2, 3, 4} = 5;
Transfinite Surface {1};
Recombine Surface {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("block") = {1};
