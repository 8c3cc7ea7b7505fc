// Rotated pair, 3D: two blocks of the same square section stacked, a `lower`
// [-0.5, 0.5]^2 x [-1, 0] (n x n x n HEX8) and an `upper` [-0.5, 0.5]^2 x [0, 1]
// ((n+1) x (n+1) x (n+1) HEX8): the meshes do not match on the interface z = 0.
// Blocks `lower`, `upper`; sets `bottom` (z = -1), `master` (lower top, z = 0),
// `slave` (upper bottom, z = 0), `top` (z = 1).
// The upper block is built one unit higher and moved down, so that gmsh does
// not merge the coincident faces (two separate meshes).
// Make with: scripts/make_mesh tests/zoo/rotated_pair_3d.geo tests/zoo/meshes/rotated_pair_3d.e -setnumber n 6
DefineConstant[ n = {6, Min 1, Name "n: lower block elements per edge (upper: n + 1)"} ];

Point(1) = {-0.5, -0.5, -1};
Point(2) = {0.5, -0.5, -1};
Point(3) = {0.5, 0.5, -1};
Point(4) = {-0.5, 0.5, -1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
lower[] = Extrude {0, 0, 1} { Surface{1}; Layers{n}; Recombine; };

Point(101) = {-0.5, -0.5, 1};
Point(102) = {0.5, -0.5, 1};
Point(103) = {0.5, 0.5, 1};
Point(104) = {-0.5, 0.5, 1};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = n + 2;
Transfinite Surface{101};
Recombine Surface{101};
upper[] = Extrude {0, 0, 1} { Surface{101}; Layers{n + 1}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {0, 0, -1} { Volume{upper[1]}; }

Physical Volume("lower", 1) = {lower[1]};
Physical Volume("upper", 2) = {upper[1]};
Physical Surface("bottom", 3) = {1};
Physical Surface("master", 4) = {lower[0]};
Physical Surface("slave", 5) = {101};
Physical Surface("top", 6) = {upper[0]};
