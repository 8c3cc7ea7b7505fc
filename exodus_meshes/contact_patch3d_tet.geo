// Contact patch test, 3D, tetrahedra: a "punch" [0,1]^2 x [0.5,1] on a
// "base" [0,1]^2 x [0,0.5], two separate tetrahedral meshes (sizes hb and
// hp, default 0.4 and 0.3; the punch's bottom structured, the base's top
// not: the triangles of the interface z = 0.5 do not match). The sets are those of contact_patch3d.geo, so its
// decks run on it. At order 2 (scripts/make_mesh ... -order 2): TET10 cells,
// TRI6 contact faces.
// Make with: scripts/make_mesh exodus_meshes/contact_patch3d_tet.geo contact_patch3d_tet10.e -order 2
SetFactory("OpenCASCADE");
DefineConstant[ hb = {0.4, Min 0.01, Name "hb: base element size"} ];
DefineConstant[ hp = {0.3, Min 0.01, Name "hp: punch element size"} ];
// Two boxes, not fragmented: their faces at z = 0.5 stay two surfaces.
Box(1) = {0, 0, 0, 1, 1, 0.5};
Box(2) = {0, 0, 0.5, 1, 1, 0.5};
MeshSize{PointsOf{Volume{1};}} = hb;
MeshSize{PointsOf{Volume{2};}} = hp;
// The punch's bottom as a structured triangulation (np divisions a side),
// the base's top unstructured: the interface triangles do not match.
DefineConstant[ np = {4, Min 1, Name "np: divisions of the punch's bottom edges"} ];
Transfinite Curve{Boundary{Surface{11};}} = np + 1;
Transfinite Surface{11};
// OpenCASCADE numbers a box's faces x = min, x = max, y = min, y = max,
// z = min, z = max.
Physical Volume("base", 1) = {1};
Physical Volume("punch", 2) = {2};
Physical Surface("bottom", 3) = {5};
Physical Surface("master", 4) = {6};    // base top, z = 0.5
Physical Surface("slave", 5) = {11};    // punch bottom, z = 0.5
Physical Surface("top", 6) = {12};      // z = 1
Physical Surface("left", 7) = {1, 7};   // x = 0
Physical Surface("front", 8) = {3, 9};  // y = 0
Physical Surface("right", 9) = {2, 8};  // x = 1
