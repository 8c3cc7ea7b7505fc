// dim: 2
// Sliding cylinder, plane strain: a stiff half disc (the die: lower half of a
// disc of radius R = 10, flat top y = R along its diameter) touching a softer
// slab [-8, 16] x [-10, 0] at the origin; two separate meshes.
// Slab: structured QUAD4, uniform size h along the track x in [-1.6, 9.6]
// (the contact patch |x - s| <= a ~ 1 for the slide s in [0, 8]), growing
// geometrically (ratio 1.25) towards the ends and (ratio 1.15) with the depth.
// Die: unstructured QUAD4, element size hd = 1.5 h within r0 = 1.5 of the
// contact point (r = distance to the origin), growing as hd + 0.25 (r - r0)
// beyond, at most 1.5. The slab top is the slave (the finer mesh, on the soft
// body whose deformation it must resolve), the die's arc the master.
// Blocks `die`, `slab`; sets `slave` (slab top), `master` (die arc),
// `top` (die, y = R), `bottom` (slab, y = -10).
// Make with: scripts/make_mesh tests/zoo/sliding_cylinder_2d.geo tests/zoo/meshes/sliding_cylinder_2d.e -setnumber h 0.125
DefineConstant[ h = {0.125, Min 0.005, Name "h: slab (slave) element size along the track"} ];
R = 10;
r0 = 1.5;
g = 0.25;
hm = h;
hd = 1.5 * h;
Geometry.AutoCoherence = 0;  // the bodies touch at the origin: keep two meshes

// Die: the lower half disc, centre (0, R)
Point(1) = {0, R, 0, 1};
Point(2) = {-R, R, 0, 1};
Point(3) = {0, 0, 0, 1};
Point(4) = {R, R, 0, 1};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

Field[1] = MathEval;
Field[1].F = Sprintf("Min(Max(%g, %g + %g * (Sqrt(x * x + y * y) - %g)), 1.5)", hd, hd, g, r0);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Recombine Surface{1};
Mesh.RecombinationAlgorithm = 2;  // simple full-quad: no triangle left

// Slab: three structured patches along x
xl = -8; xa = -1.6; xb = 9.6; xr = 16; d = 10;
Point(11) = {xl, 0, 0, 1};
Point(12) = {xa, 0, 0, 1};
Point(13) = {xb, 0, 0, 1};
Point(14) = {xr, 0, 0, 1};
Point(15) = {xl, -d, 0, 1};
Point(16) = {xa, -d, 0, 1};
Point(17) = {xb, -d, 0, 1};
Point(18) = {xr, -d, 0, 1};
// top, oriented from the fine track outwards on the graded parts
Line(11) = {12, 11};
Line(12) = {12, 13};
Line(13) = {13, 14};
// bottom, the same orientations
Line(14) = {16, 15};
Line(15) = {16, 17};
Line(16) = {17, 18};
// verticals, top to bottom
Line(17) = {11, 15};
Line(18) = {12, 16};
Line(19) = {13, 17};
Line(20) = {14, 18};
nmid = Ceil((xb - xa) / hm);
rx = 1.25;
nside = Ceil(Log(1 + (xa - xl) * (rx - 1) / hm) / Log(rx));
ry = 1.15;
ny = Ceil(Log(1 + d * (ry - 1) / hm) / Log(ry));
Transfinite Curve{12, 15} = nmid + 1;
Transfinite Curve{11, 13, 14, 16} = nside + 1 Using Progression rx;
Transfinite Curve{17, 18, 19, 20} = ny + 1 Using Progression ry;
Curve Loop(11) = {-11, 18, 14, -17};
Plane Surface(11) = {11};
Curve Loop(12) = {12, 19, -15, -18};
Plane Surface(12) = {12};
Curve Loop(13) = {13, 20, -16, -19};
Plane Surface(13) = {13};
Transfinite Surface{11} = {11, 12, 16, 15};
Transfinite Surface{12} = {12, 13, 17, 16};
Transfinite Surface{13} = {13, 14, 18, 17};
Recombine Surface{11, 12, 13};

Physical Surface("die", 1) = {1};
Physical Surface("slab", 2) = {11, 12, 13};
Physical Curve("slave", 3) = {11, 12, 13};
Physical Curve("master", 4) = {1, 2};
Physical Curve("top", 5) = {3};
Physical Curve("bottom", 6) = {14, 15, 16};
