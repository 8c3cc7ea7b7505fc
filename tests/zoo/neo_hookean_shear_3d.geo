// Rubber block pressed and sheared on a stiffer base (zoo case neo_hookean_shear_3d).
// `block` [0,10] x [0,10] x [0,5] mm, structured 2n x 2n x n HEX8; `base`
// [-5,20] x [-5,15] x [-5,0] mm, (3n+1) x (2n+2) x Ceil(n/2) HEX8 (coarser,
// non-matching). Two separate meshes: the block is built 10 mm higher and moved
// down, so that gmsh does not merge its bottom with the base's top.
// Sets: `slave` (block bottom, z = 0), `master` (base top, z = 0), `top` (block
// top, z = 5), `bottom` (base, z = -5).
// Make with: scripts/make_mesh \
//   tests/zoo/neo_hookean_shear_3d.geo tests/zoo/meshes/neo_hookean_shear_3d.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: resolution (block 2n x 2n x n)"} ];

Point(1) = {-5, -5, -5};
Point(2) = {20, -5, -5};
Point(3) = {20, 15, -5};
Point(4) = {-5, 15, -5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3 * n + 2;
Transfinite Curve{2, 4} = 2 * n + 3;
Transfinite Surface{1};
Recombine Surface{1};
base[] = Extrude {0, 0, 5} { Surface{1}; Layers{Ceil(n / 2)}; Recombine; };

Point(101) = {0, 0, 10};
Point(102) = {10, 0, 10};
Point(103) = {10, 10, 10};
Point(104) = {0, 10, 10};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = 2 * n + 1;
Transfinite Surface{101};
Recombine Surface{101};
block[] = Extrude {0, 0, 5} { Surface{101}; Layers{n}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {0, 0, -10} { Volume{block[1]}; }

Physical Volume("base", 1) = {base[1]};
Physical Volume("block", 2) = {block[1]};
Physical Surface("bottom", 3) = {1};
Physical Surface("master", 4) = {base[0]};
Physical Surface("slave", 5) = {101};
Physical Surface("top", 6) = {block[0]};
