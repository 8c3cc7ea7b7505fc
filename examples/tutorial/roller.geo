// dim: 2
// Tutorial (docs/tutorial.md): two bodies of one's own, a roller pressed into
// a slab and rolled-dragged over it, plane strain.
// Roller: the lower half of a disk of radius R centred at (0, R), touching
// the slab at the origin. Slab: [-L, L] x [-H, 0]. QUAD4 (recombined), size
// h near the contact growing away from it; the bodies are meshed apart.
// Physical groups become element blocks (surfaces) and side sets + node sets
// (curves) of the same names: blocks `roller`, `slab`; sets `roller_arc`
// (contact, slave), `slab_top` (contact, master), `roller_top` (y = R, where
// the roller is driven) and `slab_bottom` (y = -H, fixed).
// Make with: scripts/make_mesh roller.geo roller.e [-setnumber h 0.01]
DefineConstant[ h = {0.02, Min 0.002, Name "h: element size at the contact"} ];
R = 1;
L = 3;
H = 1.5;
Geometry.AutoCoherence = 0;  // the bodies touch at the origin: keep two meshes

// Roller
Point(1) = {0, R, 0, 10 * h}; // centre
Point(2) = {-R, R, 0, 10 * h};
Point(3) = {0, 0, 0, h};
Point(4) = {R, R, 0, 10 * h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 1};
Line(4) = {1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Slab, its top split at the origin so a node sits where the roller touches
Point(11) = {-L, -H, 0, 20 * h};
Point(12) = {L, -H, 0, 20 * h};
Point(13) = {L, 0, 0, 10 * h};
Point(14) = {0, 0, 0, h};
Point(15) = {-L, 0, 0, 10 * h};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 11};
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};
Recombine Surface{1, 2};

Physical Surface("roller", 1) = {1};
Physical Surface("slab", 2) = {2};
Physical Curve("roller_arc", 3) = {1, 2};
Physical Curve("slab_top", 4) = {13, 14};
Physical Curve("roller_top", 5) = {3, 4};
Physical Curve("slab_bottom", 6) = {11};
