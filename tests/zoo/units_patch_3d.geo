// Block pressed and slid on a larger block, in any length unit (zoo cases
// units_patch_3d_mm, units_patch_3d_m, units_patch_3d_kN): every coordinate is
// multiplied by `scale` (1: mm, 0.001: m).
// `punch` [0,10]^2 x [5,10] (4n x 4n x 2n HEX8) on `base` [-5,15]^2 x [0,5]
// (6n x 6n x n HEX8: 1.67 against 1.25 at n = 2, non-matching), times scale.
// Two separate meshes: the punch is built 10 higher and moved down, so that
// gmsh does not merge its bottom with the base's top.
// Sets: `bottom` (z = 0), `master` (base top), `slave` (punch bottom), `top`
// (punch top, z = 10 scale).
// Make with: scripts/make_mesh \
//   tests/zoo/units_patch_3d.geo tests/zoo/meshes/units_patch_3d_m.e -setnumber n 2 -setnumber scale 0.001
DefineConstant[ n = {2, Min 1, Name "n: resolution (punch 4n x 4n x 2n)"} ];
DefineConstant[ scale = {1, Name "scale: length unit factor (1 mm, 0.001 m)"} ];
s = scale;

Point(1) = {-5 * s, -5 * s, 0};
Point(2) = {15 * s, -5 * s, 0};
Point(3) = {15 * s, 15 * s, 0};
Point(4) = {-5 * s, 15 * s, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 6 * n + 1;
Transfinite Surface{1};
Recombine Surface{1};
base[] = Extrude {0, 0, 5 * s} { Surface{1}; Layers{n}; Recombine; };

Point(101) = {0, 0, 15 * s};
Point(102) = {10 * s, 0, 15 * s};
Point(103) = {10 * s, 10 * s, 15 * s};
Point(104) = {0, 10 * s, 15 * s};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = 4 * n + 1;
Transfinite Surface{101};
Recombine Surface{101};
punch[] = Extrude {0, 0, 5 * s} { Surface{101}; Layers{2 * n}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {0, 0, -10 * s} { Volume{punch[1]}; }

Physical Volume("base", 1) = {base[1]};
Physical Volume("punch", 2) = {punch[1]};
Physical Surface("bottom", 3) = {1};
Physical Surface("master", 4) = {base[0]};
Physical Surface("slave", 5) = {101};
Physical Surface("top", 6) = {punch[0]};
// -setnumber skin 1 (zoo case units_patch_skin_3d): the punch's bottom and its
// four sides as one more set, `skin`: a slave surface with sharp edges and
// corners. Off by default: a physical group more renumbers the nodes.
DefineConstant[ skin = {0, Choices{0, 1}, Name "skin: the punch's bottom and sides as the set skin"} ];
If (skin)
  Physical Surface("skin", 7) = {101, punch[2], punch[3], punch[4], punch[5]};
EndIf
