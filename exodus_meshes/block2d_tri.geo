// dim: 2
// Rectangle [0,2] x [0,1], structured TRI3 mesh: the 2n x n QUAD4 grid of
// block2d.geo with every square cut into two triangles (alternating diagonals).
// Make with: scripts/make_mesh exodus_meshes/block2d_tri.geo block2d_tri.e -setnumber n 8
DefineConstant[ n = {4, Min 1, Name "n: elements across the height"} ];

Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};  // bottom
Line(2) = {2, 3};  // right
Line(3) = {3, 4};  // top
Line(4) = {4, 1};  // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = 2 * n + 1;
Transfinite Curve{2, 4} = n + 1;
Transfinite Surface{1} Alternate;

Physical Surface("body", 1) = {1};
Physical Curve("bottom", 2) = {1};
Physical Curve("right", 3) = {2};
Physical Curve("top", 4) = {3};
Physical Curve("left", 5) = {4};
