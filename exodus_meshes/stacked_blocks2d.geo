// dim: 2
// Three blocks stacked, 2D (issue 18, item 4: a body in two contact pairs):
// "bottom_block" [0,1] x [0,0.5], "middle_block" [0,1] x [0.5,1] and
// "top_block" [0,1] x [1,1.5], three separate QUAD4 meshes with nb, nm, nt
// elements along x (default 4, 7, 5: neither interface matches).
// Make with: scripts/make_mesh exodus_meshes/stacked_blocks2d.geo stacked_blocks2d.e
Geometry.AutoCoherence = 0;
DefineConstant[ nb = {4, Min 1, Name "nb: bottom block elements along x"} ];
DefineConstant[ nm = {7, Min 1, Name "nm: middle block elements along x"} ];
DefineConstant[ nt = {5, Min 1, Name "nt: top block elements along x"} ];

// Block i (0 bottom, 1 middle, 2 top) is [0,1] x [i/2, i/2 + 0.5], with
// n[i] elements along x and 2 along y; its bottom, right, top and left
// curves are 10 i + 1 .. 10 i + 4, its surface 10 i + 1.
n[] = {nb, nm, nt};
For i In {0:2}
  p = 10 * i;
  y0 = 0.5 * i;
  Point(p + 1) = {0, y0, 0};
  Point(p + 2) = {1, y0, 0};
  Point(p + 3) = {1, y0 + 0.5, 0};
  Point(p + 4) = {0, y0 + 0.5, 0};
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

Physical Surface("bottom_block", 1) = {1};
Physical Surface("middle_block", 2) = {11};
Physical Surface("top_block", 3) = {21};
Physical Curve("bottom", 4) = {1};
Physical Curve("top", 5) = {23};
Physical Curve("left", 6) = {4, 14, 24};  // x = 0, every block
Physical Curve("bottom_block_top", 7) = {3};
Physical Curve("middle_block_bottom", 8) = {11};
Physical Curve("middle_block_top", 9) = {13};
Physical Curve("top_block_bottom", 10) = {21};
