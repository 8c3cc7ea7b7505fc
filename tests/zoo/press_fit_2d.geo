// dim: 2
// Press fit (Lame interference), plane strain, quarter model: an annular
// `disc` (inner radius 0.5, outer radius b = 1) inside a `ring` (inner radius
// b - delta, outer radius 2) with the interference delta = 1e-3: the two
// meshes overlap by delta at the start. Structured QUAD4; both interface
// arcs have 8n elements at the same angles (uniform over 0..90 deg), so that
// the chords of the two polygons are parallel and the discrete interference
// is delta everywhere (with non-matching angles the chord sagitta,
// b (pi/(32n))^2/2 ~ 1.3e-4 at n = 6, would change the local interference by
// up to 13 %); radially the disc has 2n
// elements, the ring 3n: the interface nodes match in angle, the meshes differ.
// Blocks `disc`, `ring`; sets `slave` (ring inner arc), `master` (disc outer
// arc), `symmetry_x` (x = 0, both bodies), `symmetry_y` (y = 0, both bodies),
// `ring_outer` (r = 2), `disc_inner` (r = 0.5).
// Make with: scripts/make_mesh tests/zoo/press_fit_2d.geo tests/zoo/meshes/press_fit_2d.e -setnumber n 6
DefineConstant[ n = {4, Min 1, Name "n: resolution (8n elements along the interface arcs)"} ];
ri = 0.5;
b = 1.0;
delta = 1e-3;
ro = 2.0;
Geometry.AutoCoherence = 0;  // the bodies overlap: keep two meshes

// disc: ri .. b
Point(1) = {0, 0, 0};
Point(2) = {ri, 0, 0};
Point(3) = {b, 0, 0};
Point(4) = {0, b, 0};
Point(5) = {0, ri, 0};
Line(1) = {2, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * n + 1;
Transfinite Curve{2, 4} = 8 * n + 1;
Transfinite Surface{1};
Recombine Surface{1};

// ring: b - delta .. ro
Point(11) = {0, 0, 0};
Point(12) = {b - delta, 0, 0};
Point(13) = {ro, 0, 0};
Point(14) = {0, ro, 0};
Point(15) = {0, b - delta, 0};
Line(11) = {12, 13};
Circle(12) = {13, 11, 14};
Line(13) = {14, 15};
Circle(14) = {15, 11, 12};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{11, 13} = 3 * n + 1;
Transfinite Curve{12, 14} = 8 * n + 1;
Transfinite Surface{11};
Recombine Surface{11};

Physical Surface("disc", 1) = {1};
Physical Surface("ring", 2) = {11};
Physical Curve("slave", 3) = {14};
Physical Curve("master", 4) = {2};
Physical Curve("symmetry_y", 5) = {1, 11};
Physical Curve("symmetry_x", 6) = {3, 13};
Physical Curve("ring_outer", 7) = {12};
Physical Curve("disc_inner", 8) = {4};
