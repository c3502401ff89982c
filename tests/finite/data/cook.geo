// Cook's membrane (Cook 1974): trapezoid (0,0), (48,44), (48,60), (0,44),
// 16 x 16 Q4, left edge clamped, a shear traction on the right edge
// (tests/finite, near incompressibility: method brief 11.2).
Point(1) = {0, 0, 0, 1}; Point(2) = {48, 44, 0, 1};
Point(3) = {48, 60, 0, 1}; Point(4) = {0, 44, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2, 3, 4} = 17;
Transfinite Surface {1};
Recombine Surface {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
Physical Point("corner") = {3};
Physical Surface("membrane") = {1};
