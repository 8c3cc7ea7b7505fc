// dim: 2
// Flat punch with sharp corners on an elastic block (zoo case sharp_punch_2d).
// `punch` [-5,5] x [0,5] mm, structured 8n x 4n QUAD4; `block` [-20,20] x [-20,0]
// mm, unstructured QUAD4, 1.44 h along the top for |x| < 8 (h = 10 / (8n) the punch
// element size; not matching it), growing to 4 mm at the far corners. Two separate meshes.
// Sets: `slave` (punch bottom, y = 0), `master` (block top, y = 0), `top` (punch
// top, y = 5), `bottom` (block, y = -20).
// Make with: scripts/make_mesh \
//   tests/zoo/sharp_punch_2d.geo tests/zoo/meshes/sharp_punch_2d.e -setnumber n 4
Geometry.AutoCoherence = 0;
DefineConstant[ n = {4, Min 1, Name "n: resolution (punch 8n x 4n)"} ];
h = 10 / (8 * n);
hb = 1.44 * h;

// block: the top edge split at x = -8 and 8, fine between
Point(1) = {-20, -20, 0, 4};
Point(2) = {20, -20, 0, 4};
Point(3) = {20, 0, 0, 4 * hb};
Point(4) = {8, 0, 0, hb};
Point(5) = {-8, 0, 0, hb};
Point(6) = {-20, 0, 0, 4 * hb};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Transfinite Curve{4} = Ceil(16 / hb) + 1;
Recombine Surface{1};

// punch
Point(11) = {-5, 0, 0};
Point(12) = {5, 0, 0};
Point(13) = {5, 5, 0};
Point(14) = {-5, 5, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve{11, 13} = 8 * n + 1;
Transfinite Curve{12, 14} = 4 * n + 1;
Transfinite Surface{2};
Recombine Surface{2};


Physical Surface("block", 1) = {1};
Physical Surface("punch", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("master", 4) = {3, 4, 5};
Physical Curve("slave", 5) = {11};
Physical Curve("top", 6) = {13};
