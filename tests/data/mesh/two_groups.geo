// One square element in two physical surfaces and one edge in two physical
// curves: MSH 2.2 writes such an element once per group under new ids, the
// reader must merge the copies back into one element.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("a") = {1};
Physical Surface("b") = {1};
Physical Curve("c") = {1};
Physical Curve("d") = {1, 2};
