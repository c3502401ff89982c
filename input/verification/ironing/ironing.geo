// 2D ironing (large-sliding frictional contact; method brief 11.1, set A,
// with a longer block): a soft block [-6.5, 6.5] x [-3, 0] and a stiff
// half-ring die, inner radius 2.8, outer 3.0, centre (-2.7, 3.03), its
// lowest point 0.03 above the block. Set A's block is [-4.5, 4.5]: there
// the die presses over the block's end (its contact zone reaches x = -5.2
// at full depth), a different hard case (doc/verification.md, section 14).
// Parameters (gmsh -setnumber NAME VALUE): nx elements along the block
// (0.45 long for nx = 29, as set A's 20 over 9), ny = 3 nx/29 through
// its depth, nd elements along the die.
DefineConstant[ nx = 29, nd = 20 ];
ny = Round(nx*3/29);
If (ny < 3)
  ny = 3;
EndIf
Point(1) = {-6.5, -3, 0}; Point(2) = {6.5, -3, 0}; Point(3) = {6.5, 0, 0}; Point(4) = {-6.5, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1; Transfinite Curve{2, 4} = ny + 1;
// the die: lower half of a ring about (cx, cy)
cx = -2.7; cy = 3.03;
Point(10) = {cx, cy, 0};
Point(11) = {cx - 3.0, cy, 0}; Point(12) = {cx, cy - 3.0, 0}; Point(13) = {cx + 3.0, cy, 0};
Point(14) = {cx + 2.8, cy, 0}; Point(15) = {cx, cy - 2.8, 0}; Point(16) = {cx - 2.8, cy, 0};
Circle(11) = {11, 10, 12}; Circle(12) = {12, 10, 13};
Line(13) = {13, 14};
Circle(14) = {14, 10, 15}; Circle(15) = {15, 10, 16};
Line(16) = {16, 11};
Curve Loop(2) = {11, 12, 13, 14, 15, 16}; Plane Surface(2) = {2};
Transfinite Curve{11, 12, 14, 15} = nd/2 + 1; Transfinite Curve{13, 16} = 2;
Transfinite Surface{2} = {11, 13, 14, 16};
Transfinite Surface{1};
Recombine Surface{:};
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
Physical Surface("block") = {1};
Physical Surface("die") = {2};
Physical Curve("block_bottom") = {1};
Physical Curve("block_top") = {3};
Physical Curve("die_outer") = {11, 12};
Physical Curve("die_ends") = {13, 16};
