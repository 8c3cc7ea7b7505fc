// Sliding punch, 3D half model (y >= 0): the geometry of the peer benchmark's
// friction case (../shared/bench/calculix/README.md), coarse: a punch
// [-1,1] x [0,1] x [0,1] (np x np/2 x np/2 HEX8) on a base
// [-2.5,2.5] x [0,2] x [-2,0] (nb x nb/2 x nb/2), non-matching at z = 0.
// Make with: scripts/make_mesh exodus_meshes/friction_punch.geo friction_punch.e
DefineConstant[ np = {4, Min 2, Name "np: punch elements along x"} ];
DefineConstant[ nb = {5, Min 2, Name "nb: base elements along x"} ];

Point(1) = {-2.5, 0, -2};
Point(2) = {2.5, 0, -2};
Point(3) = {2.5, 2, -2};
Point(4) = {-2.5, 2, -2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nb + 1;
Transfinite Curve{2, 4} = Ceil(nb / 2) + 1;
Transfinite Surface{1};
Recombine Surface{1};
base[] = Extrude {0, 0, 2} { Surface{1}; Layers{Ceil(nb / 2)}; Recombine; };

// The punch is built one unit higher and moved down afterwards, so that gmsh
// does not merge its bottom with the base's top (separate meshes).
Point(101) = {-1, 0, 1};
Point(102) = {1, 0, 1};
Point(103) = {1, 1, 1};
Point(104) = {-1, 1, 1};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 103} = np + 1;
Transfinite Curve{102, 104} = Ceil(np / 2) + 1;
Transfinite Surface{101};
Recombine Surface{101};
punch[] = Extrude {0, 0, 1} { Surface{101}; Layers{Ceil(np / 2)}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {0, 0, -1} { Volume{punch[1]}; }

Physical Volume("base", 1) = {base[1]};
Physical Volume("punch", 2) = {punch[1]};
Physical Surface("bottom", 3) = {1};              // z = -2
Physical Surface("master", 4) = {base[0]};        // base top, z = 0
Physical Surface("slave", 5) = {101};             // punch bottom, z = 0
Physical Surface("top", 6) = {punch[0]};          // z = 1
Physical Surface("symmetry_y", 7) = {base[2], punch[2]};  // y = 0
