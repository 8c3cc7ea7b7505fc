// dim: 2
// Contact patch test across dissimilar bodies (zoo case dissimilar_patch_2d):
// a soft, finely meshed `punch` [0,1] x [0.5,1] ((3n+1) x Ceil(3n/2) QUAD4) on a
// stiff, coarsely meshed `base` [0,1] x [0,0.5] (n x Ceil(n/2) QUAD4): element
// size ratio (3n+1)/n ~ 3.1 on the interface y = 0.5, non-matching. Two
// separate meshes.
// Sets: `bottom` (y = 0), `master` (base top), `slave` (punch bottom), `top`
// (y = 1), and the sides of each body: `base_left`, `base_right`, `punch_left`,
// `punch_right` (x = 0 and x = 1).
// Make with: scripts/make_mesh \
//   tests/zoo/dissimilar_patch_2d.geo tests/zoo/meshes/dissimilar_patch_2d.e -setnumber n 7
Geometry.AutoCoherence = 0;
DefineConstant[ n = {7, Min 1, Name "n: base elements along x"} ];

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
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = Ceil(n / 2) + 1;
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
Transfinite Curve{5, 7} = 3 * n + 2;
Transfinite Curve{6, 8} = Ceil(3 * n / 2) + 1;
Transfinite Surface{2};
Recombine Surface{2};

Physical Surface("base", 1) = {1};
Physical Surface("punch", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("master", 4) = {3};
Physical Curve("slave", 5) = {5};
Physical Curve("top", 6) = {7};
Physical Curve("base_left", 7) = {4};
Physical Curve("base_right", 8) = {2};
Physical Curve("punch_left", 9) = {8};
Physical Curve("punch_right", 10) = {6};
