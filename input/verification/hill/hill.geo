// Hill's thick-walled cylinder, inner radius 1, outer 2, plane strain:
// a quarter of the section, structured. Symmetry planes: 'xsym' (x = 0,
// u_x held) and 'ysym' (y = 0, u_y held); the internal pressure acts on
// 'inner'. nr elements through the wall, nt around the quarter:
//   gmsh -2 -setnumber nr 20 -setnumber nt 12 hill.geo -o hill_20.msh
If (!Exists(nr))
  nr = 20;
EndIf
If (!Exists(nt))
  nt = 12;
EndIf
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};
Point(4) = {0, 2, 0}; Point(5) = {0, 1, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = nr + 1;
Transfinite Curve {2, 4} = nt + 1;
Transfinite Surface {1};
Recombine Surface {1};
Physical Curve("ysym") = {1};
Physical Curve("outer") = {2};
Physical Curve("xsym") = {3};
Physical Curve("inner") = {4};
Physical Surface("ring") = {1};
Mesh.MshFileVersion = 4.1;
