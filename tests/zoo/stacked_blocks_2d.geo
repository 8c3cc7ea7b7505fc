// dim: 2
// Three stacked blocks (zoo case stacked_blocks_2d), three separate meshes.
// `bottom_block` [-20,20] x [-10,0] mm ((5n+1) x 2n QUAD4), `middle_block`
// [-10,10] x [0,5] mm (4n x n), `top_block` [-8,8] x [5,10] mm ((3n+1) x n):
// the element sizes differ from block to block, so neither interface matches.
// Sets: `bottom` (y = -10), `lower_master` (bottom block top, y = 0),
// `lower_slave` (middle block bottom, y = 0), `upper_master` (middle block
// top, y = 5), `upper_slave` (top block bottom, y = 5), `top` (y = 10).
// Make with: scripts/make_mesh \
//   tests/zoo/stacked_blocks_2d.geo tests/zoo/meshes/stacked_blocks_2d.e -setnumber n 8
Geometry.AutoCoherence = 0;
DefineConstant[ n = {8, Min 1, Name "n: resolution (middle block 4n x n)"} ];

// bottom block
Point(1) = {-20, -10, 0};
Point(2) = {20, -10, 0};
Point(3) = {20, 0, 0};
Point(4) = {-20, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 5 * n + 2;
Transfinite Curve{2, 4} = 2 * n + 1;
Transfinite Surface{1};
Recombine Surface{1};

// middle block
Point(5) = {-10, 0, 0};
Point(6) = {10, 0, 0};
Point(7) = {10, 5, 0};
Point(8) = {-10, 5, 0};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 4 * n + 1;
Transfinite Curve{6, 8} = n + 1;
Transfinite Surface{2};
Recombine Surface{2};

// top block
Point(9) = {-8, 5, 0};
Point(10) = {8, 5, 0};
Point(11) = {8, 10, 0};
Point(12) = {-8, 10, 0};
Line(9) = {9, 10};
Line(10) = {10, 11};
Line(11) = {11, 12};
Line(12) = {12, 9};
Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(3) = {3};
Transfinite Curve{9, 11} = 3 * n + 2;
Transfinite Curve{10, 12} = n + 1;
Transfinite Surface{3};
Recombine Surface{3};

Physical Surface("bottom_block", 1) = {1};
Physical Surface("middle_block", 2) = {2};
Physical Surface("top_block", 3) = {3};
Physical Curve("bottom", 4) = {1};
Physical Curve("lower_master", 5) = {3};
Physical Curve("lower_slave", 6) = {5};
Physical Curve("upper_master", 7) = {7};
Physical Curve("upper_slave", 8) = {9};
Physical Curve("top", 9) = {11};
