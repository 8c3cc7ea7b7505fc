// A punch on two blocks, 3D (issue 18, item 4; the 2D case is
// punch_two_blocks2d.geo): "left_base" [0,1] x [0,1] x [0,0.5] and
// "right_base" [1,2] x [0,1] x [0,0.5] side by side (touching at x = 1, not
// joined), and a "punch" [0,2] x [0,1] x [0.5,1] across both; three separate
// HEX8 meshes, nl x nl and nr x nr elements in the bases' plan (default 2, 3)
// and np x np/2 in the punch's (default 5 x 2): no interface matches.
// Make with: scripts/make_mesh exodus_meshes/punch_two_blocks3d.geo punch_two_blocks3d.e
DefineConstant[ nl = {2, Min 1, Name "nl: left base elements per edge"} ];
DefineConstant[ nr = {3, Min 1, Name "nr: right base elements per edge"} ];
DefineConstant[ np = {5, Min 1, Name "np: punch elements along x"} ];

// Body i (0 left base, 1 right base, 2 punch) is extruded from the rectangle
// [x0, x0 + w] x [0, 1] at height z0, built apart (the right base 10 units
// to the right, the punch one unit higher) and moved into place after
// Geometry.AutoCoherence = 0, as in contact_patch3d.geo: the bodies touch but
// must stay separate meshes (extruding with AutoCoherence off is not clean).
x0[] = {0, 11, 0};
w[] = {1, 1, 2};
z0[] = {0, 0, 1.5};
nx[] = {nl, nr, np};
ny[] = {nl, nr, Ceil(np / 2)};
layers[] = {2, 2, 3};
For i In {0:2}
  p = 100 * i + 1;
  Point(p) = {x0[i], 0, z0[i]};
  Point(p + 1) = {x0[i] + w[i], 0, z0[i]};
  Point(p + 2) = {x0[i] + w[i], 1, z0[i]};
  Point(p + 3) = {x0[i], 1, z0[i]};
  Line(p) = {p, p + 1};
  Line(p + 1) = {p + 1, p + 2};
  Line(p + 2) = {p + 2, p + 3};
  Line(p + 3) = {p + 3, p};
  Curve Loop(p) = {p, p + 1, p + 2, p + 3};
  Plane Surface(p) = {p};
  Transfinite Curve{p, p + 2} = nx[i] + 1;
  Transfinite Curve{p + 1, p + 3} = ny[i] + 1;
  Transfinite Surface{p};
  Recombine Surface{p};
  ex[] = Extrude {0, 0, 0.5} { Surface{p}; Layers{layers[i]}; Recombine; };
  top[i] = ex[0];
  volume[i] = ex[1];
  front[i] = ex[2];  // y = 0
  right[i] = ex[3];  // x = x0 + w
  back[i] = ex[4];   // y = 1
  left[i] = ex[5];   // x = x0
EndFor
Geometry.AutoCoherence = 0;
Translate {-10, 0, 0} { Volume{volume[1]}; }
Translate {0, 0, -1} { Volume{volume[2]}; }

Physical Volume("left_base", 1) = {volume[0]};
Physical Volume("right_base", 2) = {volume[1]};
Physical Volume("punch", 3) = {volume[2]};
Physical Surface("bottom", 4) = {1, 101};
Physical Surface("top", 5) = {top[2]};
Physical Surface("left", 6) = {left[0], left[2]};      // x = 0: left base and punch
Physical Surface("right", 7) = {right[1], right[2]};   // x = 2: right base and punch
Physical Surface("front", 8) = {front[0], front[1], front[2]};  // y = 0, every body
Physical Surface("back", 9) = {back[0], back[1], back[2]};      // y = 1, every body
Physical Surface("left_base_right", 10) = {right[0]};  // x = 1, where the bases touch
Physical Surface("right_base_left", 11) = {left[1]};
Physical Surface("left_base_top", 12) = {top[0]};
Physical Surface("right_base_top", 13) = {top[1]};
Physical Surface("punch_bottom", 14) = {201};
