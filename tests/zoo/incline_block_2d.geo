// dim: 2
// Block on an incline (zoo cases incline_block_2d_mu02, incline_block_2d_mu05).
// The incline is modelled in its own frame: x along the incline (up the slope),
// y normal to it; the deck tilts the body force instead of the geometry.
// `block` [0,40] x [0,10] mm (8n x 2n QUAD4) on `base` [-10,70] x [-10,0] mm
// ((7n+1) x n QUAD4: a coarser, non-matching interface), two separate meshes.
// Sets: `slave` (block bottom, y = 0), `master` (base top, y = 0), `back` (the
// block's face x = 0, the pusher), `bottom` (base, y = -10).
// Make with: scripts/make_mesh \
//   tests/zoo/incline_block_2d.geo tests/zoo/meshes/incline_block_2d_mu02.e -setnumber n 6
Geometry.AutoCoherence = 0;
DefineConstant[ n = {4, Min 1, Name "n: resolution (block 8n x 2n)"} ];

// base
Point(1) = {-10, -10, 0};
Point(2) = {70, -10, 0};
Point(3) = {70, 0, 0};
Point(4) = {-10, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 7 * n + 2;
Transfinite Curve{2, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};

// block
Point(5) = {0, 0, 0};
Point(6) = {40, 0, 0};
Point(7) = {40, 10, 0};
Point(8) = {0, 10, 0};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 8 * n + 1;
Transfinite Curve{6, 8} = 2 * n + 1;
Transfinite Surface{2};
Recombine Surface{2};

Physical Surface("base", 1) = {1};
Physical Surface("block", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("master", 4) = {3};
Physical Curve("slave", 5) = {5};
Physical Curve("back", 6) = {8};
// -setnumber skin 1 (zoo case incline_block_skin_2d): the block's bottom and
// both ends (x = 0 and x = 40) as one more set, `skin`: a slave surface with
// two sharp corners. Off by default: a physical group more renumbers the nodes.
DefineConstant[ skin = {0, Choices{0, 1}, Name "skin: the block's bottom and ends as the set skin"} ];
If (skin)
  Physical Curve("skin", 7) = {5, 6, 8};
EndIf
