// dim: 2
// Contact patch test, 2D: a "punch" [0,1] x [0.5,1] on a "base" [0,1] x [0,0.5],
// two separate QUAD4 meshes that do not match on the interface y = 0.5:
// the base has nb elements along x, the punch np (default 4 and 7).
// Make with: scripts/make_mesh exodus_meshes/contact_patch2d.geo contact_patch2d.e
// The two bodies touch but must stay separate meshes: no merging of coincident points.
Geometry.AutoCoherence = 0;
DefineConstant[ nb = {4, Min 1, Name "nb: base elements along x"} ];
DefineConstant[ np = {7, Min 1, Name "np: punch elements along x"} ];

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nb + 1;
Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};

Point(5) = {0, 0.5, 0};
Point(6) = {1, 0.5, 0};
Point(7) = {1, 1, 0};
Point(8) = {0, 1, 0};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{5, 7} = np + 1;
Transfinite Curve{6, 8} = 4;
Transfinite Surface{2};
Recombine Surface{2};

Physical Surface("base", 1) = {1};
Physical Surface("punch", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("master", 4) = {3};   // base top, y = 0.5
Physical Curve("slave", 5) = {5};    // punch bottom, y = 0.5
Physical Curve("top", 6) = {7};
Physical Curve("left", 7) = {4, 8};  // x = 0, both bodies
// The sides of each body alone (the frictional patch tests load them).
Physical Curve("base_left", 8) = {4};
Physical Curve("base_right", 9) = {2};
Physical Curve("punch_left", 10) = {8};
Physical Curve("punch_right", 11) = {6};
