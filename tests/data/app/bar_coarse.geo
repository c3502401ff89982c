// Coarse version of input/examples/bar.geo for the program tests
// (tests/app): 100 mm x 10 mm, 20 x 2 Q4 elements, so that a run takes
// a few tens of steps and well under a second in a Debug build.
// Regenerate: gmsh -2 -format msh41 bar_coarse.geo -o bar_coarse.msh
L = 100; H = 10; nx = 20; ny = 2;
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, H, 0}; Point(4) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1; Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("bar") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Mesh.MshFileVersion = 4.1;
