// A steel pin in an aluminium plate with a clearance hole: the pin's outer
// circle and the hole are closed contact surfaces (loops), the pin's bore
// is driven sideways by a rigid shaft (doc/scene-reference.md, "Closed
// surfaces"; deck pin_hole.nml). Units: mm.
// Regenerate: gmsh -2 -format msh41 pin_hole.geo -o pin_hole.msh
Geometry.AutoCoherence = 0;   // the two bodies' points stay apart
rb = 5; rp = 9.7; rh = 10; ro = 30;   // bore, pin, hole, plate edge
c = 0.299;                            // pin centre: the clearance, less a gap of 1e-3
nth = 12; npr = 3; nhr = 6;           // elements per quarter, through pin, through plate
Point(1) = {c, 0, 0};
Point(100) = {0, 0, 0};
// Pin: circles rb and rp about (c, 0); plate: circles rh and ro about 0.
For k In {0:3}
  Point(10 + k) = {c + rb*Cos(k*Pi/2), rb*Sin(k*Pi/2), 0};
  Point(20 + k) = {c + rp*Cos(k*Pi/2), rp*Sin(k*Pi/2), 0};
  Point(30 + k) = {rh*Cos(k*Pi/2), rh*Sin(k*Pi/2), 0};
  Point(40 + k) = {ro*Cos(k*Pi/2), ro*Sin(k*Pi/2), 0};
EndFor
For k In {0:3}
  k1 = (k + 1) % 4;
  Circle(10 + k) = {10 + k, 1, 10 + k1};
  Circle(20 + k) = {20 + k, 1, 20 + k1};
  Circle(30 + k) = {30 + k, 100, 30 + k1};
  Circle(40 + k) = {40 + k, 100, 40 + k1};
  Line(50 + k) = {10 + k, 20 + k};
  Line(60 + k) = {30 + k, 40 + k};
EndFor
For k In {0:3}
  k1 = (k + 1) % 4;
  Curve Loop(10 + k) = {50 + k, 20 + k, -(50 + k1), -(10 + k)};
  Plane Surface(10 + k) = {10 + k};
  Curve Loop(20 + k) = {60 + k, 40 + k, -(60 + k1), -(30 + k)};
  Plane Surface(20 + k) = {20 + k};
EndFor
Transfinite Curve{10:13, 20:23, 30:33, 40:43} = nth + 1;
Transfinite Curve{50:53} = npr + 1;
Transfinite Curve{60:63} = nhr + 1 Using Progression 1.25;
Transfinite Surface{10:13, 20:23};
Recombine Surface{10:13, 20:23};
Physical Surface("pin") = {10:13};
Physical Surface("plate") = {20:23};
Physical Curve("pin_bore") = {10:13};
Physical Curve("pin_surface") = {20:23};
Physical Curve("hole") = {30:33};
Physical Curve("plate_edge") = {40:43};
Mesh.MshFileVersion = 4.1;
