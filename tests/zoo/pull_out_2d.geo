// dim: 2
// Pull-out, plane strain, half model (y >= 0, the bar's mid-plane y = 0 a
// symmetry line): a `bar` [0, 3] x [0, 0.25] clamped by a `sleeve`
// [0.5, 2.5] x [0.25, 0.75] lying on it; two separate structured QUAD4
// meshes that do not match on the interface y = 0.25: the sleeve 12n x 3n
// elements (size 1/(6n)), the bar 12n x n (size 1/(4n)).
// Blocks `bar`, `sleeve`; sets `slave` (sleeve bottom, y = 0.25), `master`
// (bar top, y = 0.25, x in [0, 3]), `outer` (sleeve top, y = 0.75),
// `symmetry` (bar bottom, y = 0), `pull` (bar end x = 3).
// Make with: scripts/make_mesh tests/zoo/pull_out_2d.geo tests/zoo/meshes/pull_out_2d.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: resolution"} ];
L = 3;
hb = 0.25;
x0 = 0.5;
x1 = 2.5;
hs = 0.5;
Geometry.AutoCoherence = 0;  // the bodies touch along y = hb: keep two meshes

Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, hb, 0};
Point(4) = {0, hb, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 12 * n + 1;
Transfinite Curve{2, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};

Point(11) = {x0, hb, 0};
Point(12) = {x1, hb, 0};
Point(13) = {x1, hb + hs, 0};
Point(14) = {x0, hb + hs, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{11, 13} = 12 * n + 1;
Transfinite Curve{12, 14} = 3 * n + 1;
Transfinite Surface{11};
Recombine Surface{11};

Physical Surface("bar", 1) = {1};
Physical Surface("sleeve", 2) = {11};
Physical Curve("symmetry", 3) = {1};
Physical Curve("pull", 4) = {2};
Physical Curve("master", 5) = {3};
Physical Curve("slave", 6) = {11};
Physical Curve("outer", 7) = {13};
