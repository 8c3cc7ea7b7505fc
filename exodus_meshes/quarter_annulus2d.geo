// dim: 2
// Quarter of a thick-walled cylinder cross-section: inner radius 1, outer
// radius 2, first quadrant. Structured QUAD4 mesh, n elements through the
// wall and 2n around the quarter circle.
// Make with: scripts/make_mesh exodus_meshes/quarter_annulus2d.geo quarter_annulus2d.e -setnumber n 8
DefineConstant[ n = {4, Min 1, Name "n: elements through the wall"} ];
// tri = 1: triangles (each structured quadrilateral split in two) instead of quadrilaterals
DefineConstant[ tri = {0, Choices {0, 1}, Name "tri: triangles"} ];

Point(1) = {0, 0, 0};  // centre
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {0, 2, 0};
Point(5) = {0, 1, 0};
Line(1) = {2, 3};       // y = 0
Circle(2) = {3, 1, 4};  // r = 2
Line(3) = {4, 5};       // x = 0
Circle(4) = {5, 1, 2};  // r = 1
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 2 * n + 1;
Transfinite Surface{1};
If (tri == 0)
  Recombine Surface{1};
EndIf

Physical Surface("body", 1) = {1};
Physical Curve("symmetry_y", 2) = {1};  // on the line y = 0 (u_y = 0)
Physical Curve("outer", 3) = {2};
Physical Curve("symmetry_x", 4) = {3};  // on the line x = 0 (u_x = 0)
Physical Curve("inner", 5) = {4};
