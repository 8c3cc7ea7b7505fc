// Pressed torsion (Lubkin), 3D: a short elastic cylinder (the `punch`,
// radius a = 1, z in [0, 2]) stands on a coaxial cylinder of the same radius
// and material (the `base`, z in [-2, 0]); two separate HEX8 meshes that do
// not match on the interface z = 0 except on its rim: both rims are the same
// 8n-gon (nodes at 45 deg + k 360/(8n) deg), so that no slave rim node lies
// outside the master face. Punch: unstructured quadrilateral disc (size
// 0.6 / n inside), extruded in ceil(2.5 n) layers. Base: an O-grid disc
// (inner square 2n x 2n of half width a/2, n elements radially), extruded
// in 2n layers.
// Blocks `punch`, `base`; sets `slave` (punch bottom, z = 0), `master` (base
// top, z = 0), `top` (punch, z = 2), `bottom` (base, z = -2).
// Make with: scripts/make_mesh tests/zoo/pressed_torsion_3d.geo tests/zoo/meshes/pressed_torsion_3d.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: resolution (8n rim segments)"} ];
a = 1;
H = 2;
c45 = Cos(Pi / 4);

// ---------------------------------------------------------------- base (O-grid)
Point(1) = {0, 0, 0, 1};
s = 0.5 * a;
Point(2) = {a * c45, a * c45, 0, 1};
Point(3) = {-a * c45, a * c45, 0, 1};
Point(4) = {-a * c45, -a * c45, 0, 1};
Point(5) = {a * c45, -a * c45, 0, 1};
Point(6) = {s, s, 0, 1};
Point(7) = {-s, s, 0, 1};
Point(8) = {-s, -s, 0, 1};
Point(9) = {s, -s, 0, 1};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {8, 9};
Line(8) = {9, 6};
Line(9) = {6, 2};
Line(10) = {7, 3};
Line(11) = {8, 4};
Line(12) = {9, 5};
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = 2 * n + 1;
Transfinite Curve{9, 10, 11, 12} = n + 1;
Curve Loop(1) = {5, 6, 7, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 1, -10, -5};
Plane Surface(2) = {2};
Curve Loop(3) = {10, 2, -11, -6};
Plane Surface(3) = {3};
Curve Loop(4) = {11, 3, -12, -7};
Plane Surface(4) = {4};
Curve Loop(5) = {12, 4, -9, -8};
Plane Surface(5) = {5};
Transfinite Surface{1, 2, 3, 4, 5};
Recombine Surface{1, 2, 3, 4, 5};

// the base is extruded downwards from its top z = 0 (the master face); each
// input surface gives 6 entries: top, volume, 4 laterals
b[] = Extrude {0, 0, -H} { Surface{1, 2, 3, 4, 5}; Layers{2 * n}; Recombine; };

// ---------------------------------------------------------------- punch (unstructured disc)
// built one unit higher and moved down afterwards, so that gmsh does not merge
// its bottom rim with the base's top rim (two separate meshes)
hp = 0.6 / n;
Point(1001) = {0, 0, 1, hp};
Point(1002) = {a * c45, a * c45, 1, hp};
Point(1003) = {-a * c45, a * c45, 1, hp};
Point(1004) = {-a * c45, -a * c45, 1, hp};
Point(1005) = {a * c45, -a * c45, 1, hp};
Circle(1001) = {1002, 1001, 1003};
Circle(1002) = {1003, 1001, 1004};
Circle(1003) = {1004, 1001, 1005};
Circle(1004) = {1005, 1001, 1002};
Transfinite Curve{1001, 1002, 1003, 1004} = 2 * n + 1;
Curve Loop(1001) = {1001, 1002, 1003, 1004};
Plane Surface(1001) = {1001};
Recombine Surface{1001};
Mesh.RecombinationAlgorithm = 1;
p[] = Extrude {0, 0, H} { Surface{1001}; Layers{Ceil(2.5 * n)}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {0, 0, -1} { Volume{p[1]}; }

Physical Volume("base", 1) = {b[1], b[7], b[13], b[19], b[25]};
Physical Volume("punch", 2) = {p[1]};
Physical Surface("slave", 3) = {1001};
Physical Surface("master", 4) = {1, 2, 3, 4, 5};
Physical Surface("top", 5) = {p[0]};
Physical Surface("bottom", 6) = {b[0], b[6], b[12], b[18], b[24]};
