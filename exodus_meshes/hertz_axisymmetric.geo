// dim: 2
// Hertz sphere on a flat as an axisymmetric section (Plane Assumption =
// Axisymmetric: x = r, y = z): the x >= 0 half of hertz2d.geo turned about
// the y axis, a sphere R = 10 (a round-tipped cylinder r <= 4 up to z = 6)
// touching a disc r <= 8, z in [-8, 0], at the origin. Unstructured QUAD4,
// element size h at the contact point growing with the distance.
// Blocks `indenter`, `foundation`; sets `slave` (arc), `master` (disc top),
// `top` (z = 6), `bottom` (z = -8), `axis` (r = 0, both bodies).
// Make with: scripts/make_mesh exodus_meshes/hertz_axisymmetric.geo hertz_axisymmetric.e -setnumber h 0.05
DefineConstant[ h = {0.05, Min 0.001, Name "h: element size at the contact"} ];
DefineConstant[ g = {0.1, Min 0, Name "g: growth of the element size with the distance"} ];
R = 10;
w = 4;
yArc = R - Sqrt(R * R - w * w);
Geometry.AutoCoherence = 0;  // the bodies touch at the origin: keep two meshes

// Indenter
Point(1) = {0, R, 0, 1};  // centre (not meshed)
Point(3) = {0, 0, 0, h};
Point(4) = {w, yArc, 0, 20 * h};
Point(5) = {w, 6, 0, 20 * h};
Point(6) = {0, 6, 0, 20 * h};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Line(5) = {6, 3};  // the axis
Curve Loop(1) = {2, 3, 4, 5};
Plane Surface(1) = {1};

// Foundation
Point(12) = {8, -8, 0, 40 * h};
Point(13) = {8, 0, 0, 20 * h};
Point(14) = {0, 0, 0, h};
Point(16) = {0, -8, 0, 40 * h};
Line(11) = {16, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 16};  // the axis
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};

Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g + %g * Sqrt(x * x + y * y), 2)", h, g);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Recombine Surface{1, 2};
Mesh.RecombinationAlgorithm = 1;

Physical Surface("indenter", 1) = {1};
Physical Surface("foundation", 2) = {2};
Physical Curve("slave", 3) = {2};
Physical Curve("master", 4) = {13};
Physical Curve("top", 5) = {4};
Physical Curve("bottom", 6) = {11};
Physical Curve("axis", 7) = {5, 14};
