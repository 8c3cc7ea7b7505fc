// Quarter of a thick-walled cylinder, a slice of thickness t along z: the
// cross-section of quarter_annulus2d.geo (inner radius 1, outer radius 2,
// first quadrant) extruded by one layer of structured HEX8 (n elements
// through the wall, 2n around). With u_z = 0 on both faces z = 0 and z = t
// it is the plane-strain Lamé problem in 3D.
// tet = 1: unstructured tetrahedra of size about 1/n instead, in a slice
// 1/n thick (the plane-strain answer does not depend on it; for TET10 at -order 2).
// Make with: scripts/make_mesh exodus_meshes/quarter_annulus3d.geo quarter_annulus3d.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: elements through the wall"} ];
DefineConstant[ tet = {0, Choices {0, 1}, Name "tet: unstructured tetrahedra"} ];
DefineConstant[ t = {0.25, Min 0, Name "t: thickness along z"} ];

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

// out[0] top face, out[1] the volume, out[2..5] the sides of curves 1..4
If (tet == 0)
  Transfinite Curve{1, 3} = n + 1;
  Transfinite Curve{2, 4} = 2 * n + 1;
  Transfinite Surface{1};
  Recombine Surface{1};
  out[] = Extrude {0, 0, t} { Surface{1}; Layers{1}; Recombine; };
Else
  out[] = Extrude {0, 0, 1.0 / n} { Surface{1}; };
  MeshSize{ PointsOf{ Volume{out[1]}; } } = 1.0 / n;
  Mesh.MeshSizeFromCurvature = 0;
EndIf

Physical Volume("body", 1) = {out[1]};
Physical Surface("symmetry_y", 2) = {out[2]};  // y = 0 (u_y = 0)
Physical Surface("outer", 3) = {out[3]};
Physical Surface("symmetry_x", 4) = {out[4]};  // x = 0 (u_x = 0)
Physical Surface("inner", 5) = {out[5]};
Physical Surface("back", 6) = {1};             // z = 0 (u_z = 0)
Physical Surface("front", 7) = {out[0]};       // z = t (u_z = 0)
