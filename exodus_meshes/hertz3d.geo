// Hertz 3D: a sphere R = 10 (a spherical-tipped column |x|, |y| <= 4, from the
// cap up to z = 6) touching a block at the origin; the geometry and names of
// the peer benchmark's hertz3d meshes (../shared/bench). `sym` = 0: full model;
// 2: quarter model x >= 0, y >= 0 with the sets `symmetry_x` (x = 0) and
// `symmetry_y` (y = 0) — the slave node at the origin then has two prescribed
// DoFs. Unstructured TET4 (OpenCASCADE geometry), element size h at the origin
// growing with the distance r as h + g r (at most 2); two separate meshes.
// Blocks `indenter`, `foundation`; sets `slave` (cap), `master` (block top),
// `top` (z = 6), `bottom` (z = -8).
// Make with: scripts/make_mesh exodus_meshes/hertz3d.geo hertz3d.e -setnumber h 0.2 -setnumber sym 0
SetFactory("OpenCASCADE");
DefineConstant[ h = {0.2, Min 0.001, Name "h: element size at the contact"} ];
DefineConstant[ g = {0.15, Min 0, Name "g: growth of the element size with the distance"} ];
DefineConstant[ sym = {0, Choices{0, 2}, Name "sym: 0 full, 2 quarter model"} ];
R = 10;
w = 4;
L = 8;
e = 1e-6;
lo = (sym == 2) ? 0 : -w;
blo = (sym == 2) ? 0 : -L;

Sphere(1) = {0, 0, R, R};
Box(2) = {lo, lo, 0, w - lo, w - lo, 6};
indenter() = BooleanIntersection{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(3) = {blo, blo, -8, L - blo, L - blo, 8};

Field[1] = MathEval;
Field[1].F = Sprintf("Min(%g + %g * Sqrt(x * x + y * y + z * z), 2)", h, g);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Volume("indenter", 1) = {indenter()};
Physical Volume("foundation", 2) = {3};
// The cap: the indenter's boundary without its planar faces (OpenCASCADE's
// bounding box of a spherical face is too loose to select it directly).
cap() = Abs(Boundary{ Volume{indenter()}; });
cap() -= Surface In BoundingBox{lo - e, lo - e, 6 - e, w + e, w + e, 6 + e};
cap() -= Surface In BoundingBox{lo - e, lo - e, -e, lo + e, w + e, 6 + e};
cap() -= Surface In BoundingBox{w - e, lo - e, -e, w + e, w + e, 6 + e};
cap() -= Surface In BoundingBox{lo - e, lo - e, -e, w + e, lo + e, 6 + e};
cap() -= Surface In BoundingBox{lo - e, w - e, -e, w + e, w + e, 6 + e};
Physical Surface("slave", 3) = {cap()};
Physical Surface("master", 4) = Surface In BoundingBox{blo - e, blo - e, -e, L + e, L + e, e};
Physical Surface("top", 5) = Surface In BoundingBox{lo - e, lo - e, 6 - e, w + e, w + e, 6 + e};
Physical Surface("bottom", 6) = Surface In BoundingBox{blo - e, blo - e, -8 - e, L + e, L + e, -8 + e};
If (sym == 2)
  Physical Surface("symmetry_x", 7) = Surface In BoundingBox{-e, -e, -8 - e, e, L + e, 6 + e};
  Physical Surface("symmetry_y", 8) = Surface In BoundingBox{-e, -e, -8 - e, L + e, e, 6 + e};
EndIf
