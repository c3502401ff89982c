// Impact of two identical bars 10 x 1 mm, facing ends g = 0.01 mm apart:
// left bar [-10 - g/2, -g/2] x [0, 1], right bar [g/2, 10 + g/2] x [0, 1].
// Meshed separately; the facing ends have nyl and nyr elements (equal: the
// interface nodes match; different: non-matching). Units mm.
// Parameters (gmsh -setnumber NAME VALUE): nx (elements along each bar),
// nyl, nyr (elements across the left / right bar).
DefineConstant[ nx = 100, nyl = 10, nyr = 10 ];
L = 10; B = 1; g = 0.01;
Point(1) = {-L - g/2, 0, 0}; Point(2) = {-g/2, 0, 0}; Point(3) = {-g/2, B, 0}; Point(4) = {-L - g/2, B, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(5) = {g/2, 0, 0}; Point(6) = {L + g/2, 0, 0}; Point(7) = {L + g/2, B, 0}; Point(8) = {g/2, B, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 5, 7} = nx + 1;
Transfinite Curve{2, 4} = nyl + 1;
Transfinite Curve{6, 8} = nyr + 1;
Transfinite Surface{1, 2};
Recombine Surface{:};
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
Physical Surface("left_bar") = {1};
Physical Surface("right_bar") = {2};
Physical Curve("left_bar_end") = {2};     // contact, faces +x
Physical Curve("right_bar_end") = {8};    // contact, faces -x
Physical Curve("left_bar_outer") = {4};
Physical Curve("right_bar_outer") = {6};
Physical Curve("left_bar_sides") = {1, 3};
Physical Curve("right_bar_sides") = {5, 7};
