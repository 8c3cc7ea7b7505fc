// dim: 2
// Press fit (Lame interference) as an axisymmetric section (Plane Assumption =
// Axisymmetric: x = r, y = z): a `disc` ring (r from 0.5 to b = 1) inside a
// `ring` (r from b - delta to 2) with the interference delta = 1e-3 (the two
// meshes overlap by delta at the start), a slice of height 0.25 held at
// u_z = 0 on its bottom and top (plane strain). Structured QUAD4: the disc has
// 2n elements through its wall, the ring 3n, both n along the axis (the
// interface nodes do not match).
// Blocks `disc`, `ring`; sets `slave` (ring inner face), `master` (disc outer
// face), `bottom`, `top` (both bodies).
// Make with: scripts/make_mesh exodus_meshes/press_fit_axisymmetric.geo press_fit_axisymmetric.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: resolution"} ];
ri = 0.5;
b = 1.0;
delta = 1e-3;
ro = 2.0;
H = 0.25;
Geometry.AutoCoherence = 0;  // the bodies overlap: keep two meshes

Point(1) = {ri, 0, 0};
Point(2) = {b, 0, 0};
Point(3) = {b, H, 0};
Point(4) = {ri, H, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * n + 1;
Transfinite Curve{2, 4} = n + 1;
Transfinite Surface{1};

Point(11) = {b - delta, 0, 0};
Point(12) = {ro, 0, 0};
Point(13) = {ro, H, 0};
Point(14) = {b - delta, H, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve{11, 13} = 3 * n + 1;
Transfinite Curve{12, 14} = n + 2;
Transfinite Surface{2};
Recombine Surface{1, 2};

Physical Surface("disc", 1) = {1};
Physical Surface("ring", 2) = {2};
Physical Curve("slave", 3) = {14};
Physical Curve("master", 4) = {2};
Physical Curve("bottom", 5) = {1, 11};
Physical Curve("top", 6) = {3, 13};
