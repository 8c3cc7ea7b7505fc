// dim: 2
// A punch on two blocks, 2D (issue 18, item 4: one slave surface on two
// master bodies): "left_base" [0,1] x [0,0.5] and "right_base" [1,2] x [0,0.5]
// side by side (touching at x = 1, not joined), and a "punch" [0,2] x [0.5,1]
// across both; three separate QUAD4 meshes. Elements along x: nl and nr in
// the bases (default 3, 4), pl and pr in the punch's halves x < 1 and x > 1
// (default 4, 3; the punch has a node at x = 1). Neither interface matches.
// Make with: scripts/make_mesh exodus_meshes/punch_two_blocks2d.geo punch_two_blocks2d.e
Geometry.AutoCoherence = 0;
DefineConstant[ nl = {3, Min 1, Name "nl: left base elements along x"} ];
DefineConstant[ nr = {4, Min 1, Name "nr: right base elements along x"} ];
DefineConstant[ pl = {4, Min 1, Name "pl: punch elements along x < 1"} ];
DefineConstant[ pr = {3, Min 1, Name "pr: punch elements along x > 1"} ];

// Base i (0 left, 1 right) is [i, i + 1] x [0, 0.5], with n[i] elements
// along x and 2 along y; its bottom, right, top and left curves are
// 10 i + 1 .. 10 i + 4, its surface 10 i + 1.
n[] = {nl, nr};
For i In {0:1}
  p = 10 * i;
  Point(p + 1) = {i, 0, 0};
  Point(p + 2) = {i + 1, 0, 0};
  Point(p + 3) = {i + 1, 0.5, 0};
  Point(p + 4) = {i, 0.5, 0};
  Line(p + 1) = {p + 1, p + 2};
  Line(p + 2) = {p + 2, p + 3};
  Line(p + 3) = {p + 3, p + 4};
  Line(p + 4) = {p + 4, p + 1};
  Curve Loop(p + 1) = {p + 1, p + 2, p + 3, p + 4};
  Plane Surface(p + 1) = {p + 1};
  Transfinite Curve{p + 1, p + 3} = n[i] + 1;
  Transfinite Curve{p + 2, p + 4} = 3;
  Transfinite Surface{p + 1};
  Recombine Surface{p + 1};
EndFor

// The punch: its bottom is two curves meeting at x = 1.
Point(101) = {0, 0.5, 0};
Point(102) = {1, 0.5, 0};
Point(103) = {2, 0.5, 0};
Point(104) = {2, 1, 0};
Point(105) = {0, 1, 0};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 105};
Line(105) = {105, 101};
Curve Loop(101) = {101, 102, 103, 104, 105};
Plane Surface(101) = {101};
Transfinite Curve{101} = pl + 1;
Transfinite Curve{102} = pr + 1;
Transfinite Curve{104} = pl + pr + 1;
Transfinite Curve{103, 105} = 4;
Transfinite Surface{101} = {101, 103, 104, 105};
Recombine Surface{101};

Physical Surface("left_base", 1) = {1};
Physical Surface("right_base", 2) = {11};
Physical Surface("punch", 3) = {101};
Physical Curve("bottom", 4) = {1, 11};
Physical Curve("top", 5) = {104};
Physical Curve("left", 6) = {4, 105};      // x = 0: left base and punch
Physical Curve("right", 7) = {12, 103};    // x = 2: right base and punch
Physical Curve("left_base_right", 13) = {2};  // x = 1, where the bases touch
Physical Curve("right_base_left", 14) = {14};
Physical Curve("left_base_top", 8) = {3};
Physical Curve("right_base_top", 9) = {13};
Physical Curve("punch_bottom", 10) = {101, 102};
Physical Curve("punch_bottom_left", 11) = {101};
Physical Curve("punch_bottom_right", 12) = {102};
