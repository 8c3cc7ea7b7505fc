// dim: 2
// Axisymmetric section (x = radius r, y = axis z) of a thick-walled cylinder:
// inner radius 1, outer radius 2, a slice of height 0.5. Structured mesh of
// n elements through the wall and n/2 (at least 1) along the axis;
// tri = 1 splits each quadrilateral in two triangles.
// Make with: scripts/make_mesh exodus_meshes/axisymmetric_cylinder.geo cylinder.e -setnumber n 8
DefineConstant[ n = {4, Min 1, Name "n: elements through the wall"} ];
DefineConstant[ tri = {0, Choices {0, 1}, Name "tri: triangles"} ];

Point(1) = {1, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 0.5, 0};
Point(4) = {1, 0.5, 0};
Line(1) = {1, 2};  // bottom, z = 0
Line(2) = {2, 3};  // outer, r = 2
Line(3) = {3, 4};  // top, z = 0.5
Line(4) = {4, 1};  // inner, r = 1
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = Max(1, n / 2) + 1;
Transfinite Surface{1};
If (tri == 0)
  Recombine Surface{1};
EndIf

Physical Surface("body", 1) = {1};
Physical Curve("bottom", 2) = {1};
Physical Curve("outer", 3) = {2};
Physical Curve("top", 4) = {3};
Physical Curve("inner", 5) = {4};
