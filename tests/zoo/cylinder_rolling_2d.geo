// dim: 2
// Rolling cylinder, plane strain: a `cylinder` (disc of radius R = 10 about
// (0, R) with a hub bore of radius 2, the `hub` where the motion is
// prescribed) touching a `block` [-8, 10] x [-8, 0] at the origin; two
// separate unstructured QUAD4 meshes, element size h within the rolling track
// (distance d to the segment y = 0, -1.5 <= x <= 3), growing as h + 0.15 d,
// at most 1.5.
// Blocks `cylinder`, `block`; sets `slave` (the cylinder's outer arc from 240
// to 300 deg about its centre), `master` (block top, y = 0), `bottom`
// (y = -8), `hub` (the bore, r = 2).
// Make with: scripts/make_mesh tests/zoo/cylinder_rolling_2d.geo tests/zoo/meshes/cylinder_rolling_2d.e -setnumber h 0.1
DefineConstant[ h = {0.1, Min 0.005, Name "h: element size along the rolling track"} ];
R = 10;
rh = 2;
Geometry.AutoCoherence = 0;  // the bodies touch at the origin: keep two meshes

Point(1) = {0, R, 0};
a1 = 240 * Pi / 180;
a2 = 300 * Pi / 180;
Point(2) = {R * Cos(a1), R + R * Sin(a1), 0};
Point(3) = {R * Cos(a2), R + R * Sin(a2), 0};
Point(4) = {R, R, 0};
Point(5) = {0, 2 * R, 0};
Point(6) = {-R, R, 0};
Circle(1) = {2, 1, 3};   // slave arc through the origin
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 6};
Circle(5) = {6, 1, 2};
Point(7) = {rh, R, 0};
Point(8) = {0, R + rh, 0};
Point(9) = {-rh, R, 0};
Point(10) = {0, R - rh, 0};
Circle(6) = {7, 1, 8};
Circle(7) = {8, 1, 9};
Circle(8) = {9, 1, 10};
Circle(9) = {10, 1, 7};
Curve Loop(1) = {1, 2, 3, 4, 5};
Curve Loop(2) = {6, 7, 8, 9};
Plane Surface(1) = {1, 2};

Point(11) = {-8, -8, 0};
Point(12) = {10, -8, 0};
Point(13) = {10, 0, 0};
Point(14) = {-8, 0, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};

Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g + 0.15 * Sqrt(Max(Max(-1.5 - x, x - 3), 0)^2 + y^2), 1.5)", h);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Recombine Surface{1, 11};
Mesh.RecombinationAlgorithm = 1;

Physical Surface("cylinder", 1) = {1};
Physical Surface("block", 2) = {11};
Physical Curve("slave", 3) = {1};
Physical Curve("master", 4) = {13};
Physical Curve("bottom", 5) = {11};
Physical Curve("hub", 6) = {6, 7, 8, 9};
