// dim: 2
// Hertz 2D (plane strain): the section of a cylinder R = 10 (a circular-tipped
// column |x| <= 4, from the arc up to y = 6) touching a block [-8,8] x [-8,0]
// at the origin; the same geometry and names as the peer benchmark's
// hertz2d_2d meshes (../shared/bench). Unstructured QUAD4, element size h at
// the contact point growing with the distance; two separate meshes.
// Blocks `indenter`, `foundation`; sets `slave` (arc), `master` (block top),
// `top` (y = 6), `bottom` (y = -8).
// Make with: scripts/make_mesh exodus_meshes/hertz2d.geo hertz2d.e -setnumber h 0.1
DefineConstant[ h = {0.1, Min 0.001, Name "h: element size at the contact"} ];
DefineConstant[ g = {0.1, Min 0, Name "g: growth of the element size with the distance"} ];
R = 10;
w = 4;
yArc = R - Sqrt(R * R - w * w);
Geometry.AutoCoherence = 0;  // the bodies touch at the origin: keep two meshes

// Indenter
Point(1) = {0, R, 0, 1};         // centre (not meshed)
Point(2) = {-w, yArc, 0, 20 * h};
Point(3) = {0, 0, 0, h};
Point(4) = {w, yArc, 0, 20 * h};
Point(5) = {w, 6, 0, 20 * h};
Point(6) = {-w, 6, 0, 20 * h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Line(5) = {6, 2};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

// Foundation, its top split at the origin
Point(11) = {-8, -8, 0, 40 * h};
Point(12) = {8, -8, 0, 40 * h};
Point(13) = {8, 0, 0, 20 * h};
Point(14) = {0, 0, 0, h};
Point(15) = {-8, 0, 0, 20 * h};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 11};
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};

// Element size: h at the contact point, growing linearly with the distance
// (size field: h + g r, r the distance to the origin), at most 2.
Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g + %g * Sqrt(x * x + y * y), 2)", h, g);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Recombine Surface{1, 2};
Mesh.RecombinationAlgorithm = 1;

Physical Surface("indenter", 1) = {1};
Physical Surface("foundation", 2) = {2};
Physical Curve("slave", 3) = {1, 2};
Physical Curve("master", 4) = {13, 14};
Physical Curve("top", 5) = {4};
Physical Curve("bottom", 6) = {11};
