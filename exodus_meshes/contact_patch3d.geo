// Contact patch test, 3D: a "punch" [0,1]^2 x [0.5,1] on a "base" [0,1]^2 x [0,0.5],
// two separate HEX8 meshes that do not match on the interface z = 0.5:
// nb x nb elements in the base, np x np in the punch (default 3 and 4).
// Make with: scripts/make_mesh exodus_meshes/contact_patch3d.geo contact_patch3d.e
DefineConstant[ nb = {3, Min 1, Name "nb: base elements per edge"} ];
DefineConstant[ np = {4, Min 1, Name "np: punch elements per edge"} ];
// Mixed meshes: tetbase = 1 meshes the base, tetpunch = 1 the punch, with
// structured tetrahedra instead of hexahedra (at -order 2: a HEX27 or HEX20
// body on a TET10 one, or the other way round).
DefineConstant[ tetbase = {0, Choices{0, 1}, Name "tetbase: tetrahedra in the base"} ];
DefineConstant[ tetpunch = {0, Choices{0, 1}, Name "tetpunch: tetrahedra in the punch"} ];
DefineConstant[ sides = {0, Choices{0, 1}, Name "sides: the punch's sides as the set punch_sides"} ];

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = nb + 1;
Transfinite Surface{1};
If (tetbase)
  base[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{2}; };
Else
  Recombine Surface{1};
  base[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{2}; Recombine; };
EndIf

// Tags from 101: the base's extrusion took the next free ones. The punch is
// built one unit higher and moved down afterwards, so that gmsh does not merge
// its bottom with the base's top (the two bodies must stay separate meshes).
Point(101) = {0, 0, 1.5};
Point(102) = {1, 0, 1.5};
Point(103) = {1, 1, 1.5};
Point(104) = {0, 1, 1.5};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = np + 1;
Transfinite Surface{101};
If (tetpunch)
  punch[] = Extrude {0, 0, 0.5} { Surface{101}; Layers{3}; };
Else
  Recombine Surface{101};
  punch[] = Extrude {0, 0, 0.5} { Surface{101}; Layers{3}; Recombine; };
EndIf
Geometry.AutoCoherence = 0;
Translate {0, 0, -1} { Volume{punch[1]}; }

Physical Volume("base", 1) = {base[1]};
Physical Volume("punch", 2) = {punch[1]};
Physical Surface("bottom", 3) = {1};
Physical Surface("master", 4) = {base[0]};    // base top, z = 0.5
Physical Surface("slave", 5) = {101};           // punch bottom, z = 0.5
Physical Surface("top", 6) = {punch[0]};      // z = 1
Physical Surface("left", 7) = {base[5], punch[5]};   // x = 0
Physical Surface("front", 8) = {base[2], punch[2]};  // y = 0
Physical Surface("right", 9) = {base[3], punch[3]};  // x = 1 (the frictional patch tests load it)
// -setnumber sides 1: the punch's four sides (x = 0, y = 0, x = 1, y = 1)
// as a set too, which with `slave` makes a slave surface with sharp edges
// (tests/unit/contact_sharp_edges_mpi.cpp). Off by default: another physical
// group renumbers gmsh's nodes, and the other meshes keep theirs.
If (sides)
  Physical Surface("punch_sides", 10) = {punch[2], punch[3], punch[4], punch[5]};
EndIf
