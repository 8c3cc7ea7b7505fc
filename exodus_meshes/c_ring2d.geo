// dim: 2
// A C-shaped body, 2D (issue 18, item 5: self-contact): a column
// [0,t] x [0,H] with two arms, "bottom arm" [t,L] x [0,t] and "top arm"
// [t,L] x [H-t,H], one QUAD4 mesh (one element block "c_ring"). The gap
// between the arms, [t,L] x [t,H-t], is g0 = H - 2 t high. Pressing the top
// arm's tip down closes the gap: the arm's lower face touches the bottom
// arm's upper face, one surface of the body touching itself.
// Sets: "inner" the whole inner surface (the lower face of the top arm,
// the inner face of the column, the upper face of the bottom arm: the
// self-contact surface), "top_arm_bottom" and "bottom_arm_top" its two arm
// faces alone (the same contact as an ordinary pair, for comparison),
// "left" (x = 0), "tip" (the top arm's end, x = L), "bottom" (y = 0) and
// "top" (y = H).
// The arms have nt and nb elements along x (default 13 and 16: the faces
// across the gap do not match), m through the thickness.
// Make with: scripts/make_mesh exodus_meshes/c_ring2d.geo c_ring2d.e
DefineConstant[ nt = {13, Min 1, Name "nt: top arm elements along x"} ];
DefineConstant[ nb = {16, Min 1, Name "nb: bottom arm elements along x"} ];
DefineConstant[ m = {4, Min 1, Name "m: elements through the thickness"} ];
L = 2.0;
t = 0.4;
g0 = 0.1;
H = 2 * t + g0;

// Column corners and the arm ends.
Point(1) = {0, 0, 0};
Point(2) = {t, 0, 0};
Point(3) = {t, t, 0};
Point(4) = {0, t, 0};
Point(5) = {t, H - t, 0};
Point(6) = {0, H - t, 0};
Point(7) = {t, H, 0};
Point(8) = {0, H, 0};
Point(9) = {L, 0, 0};
Point(10) = {L, t, 0};
Point(11) = {L, H - t, 0};
Point(12) = {L, H, 0};

// Column: bottom square (1 2 3 4), middle (4 3 5 6), top square (6 5 7 8).
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};
Line(7) = {6, 4};
Line(8) = {5, 7};
Line(9) = {7, 8};
Line(10) = {8, 6};
// Bottom arm (2 9 10 3) and top arm (5 11 12 7).
Line(11) = {2, 9};
Line(12) = {9, 10};
Line(13) = {10, 3};
Line(14) = {5, 11};
Line(15) = {11, 12};
Line(16) = {12, 7};

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {-3, 5, 6, 7};
Curve Loop(3) = {-6, 8, 9, 10};
Curve Loop(4) = {11, 12, 13, -2};
Curve Loop(5) = {14, 15, 16, -8};
For s In {1:5}
  Plane Surface(s) = {s};
EndFor
Transfinite Curve{1, 2, 3, 4, 6, 8, 9, 10, 12, 15} = m + 1;
Transfinite Curve{5, 7} = 2;
Transfinite Curve{11, 13} = nb + 1;
Transfinite Curve{14, 16} = nt + 1;
Transfinite Surface{1:5};
Recombine Surface{1:5};

Physical Surface("c_ring", 1) = {1:5};
Physical Curve("inner", 2) = {14, 5, 13};
Physical Curve("top_arm_bottom", 3) = {14};
Physical Curve("bottom_arm_top", 4) = {13};
Physical Curve("left", 5) = {4, 7, 10};
Physical Curve("tip", 6) = {15};
Physical Curve("bottom", 7) = {1, 11};
Physical Curve("top", 8) = {9, 16};
