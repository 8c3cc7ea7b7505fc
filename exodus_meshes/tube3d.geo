// dim: 3
// A rectangular tube, 3D (issue 18, item 5: self-contact): the cross
// section [0,W] x [0,H] with the hole [t,W-t] x [t,H-t] (W = 3, H = 1,
// walls t = 0.3 thick: the hole is 2.4 wide and 0.4 high), extruded along z
// over [0,D], D = 1; one HEX8 mesh (element block "tube"). Two rigid plates
// pressing the middle of the top and the bottom wall, x in [a,b] = [1.2,1.8],
// bend the walls inward until they touch: the tube's inner surface
// touching itself.
// Sets: "inner" the whole inner surface (the self-contact surface),
// "inner_top" and "inner_bottom" its faces on the top and the bottom wall
// alone (the same contact as an ordinary pair, for comparison),
// "plate_top" and "plate_bottom" the outer faces under the plates, "front"
// (z = 0) and "back" (z = D).
// The walls have nt[] and nb[] elements along x in the three spans
// [t,a], [a,b], [b,W-t] (default 6, 3, 6 on top and 5, 4, 5 below: the
// faces across the hole do not match), m through the thickness, k up the
// side walls, nz along z; r multiplies every count (r = 4: 13932
// nodes, 41.8k DoFs: scripts/bench tube --ref 4); tet = 1: tetrahedra on
// the same grid (-order 2: TET10, TRI6 faces).
// Make with: scripts/make_mesh exodus_meshes/tube3d.geo tube3d.e [-setnumber r 4]
DefineConstant[ r = {1, Min 0.1, Name "r: refinement factor of every element count"} ];
DefineConstant[ m0 = {2, Min 1, Name "m0: elements through a wall (r = 1)"} ];
DefineConstant[ k0 = {3, Min 1, Name "k0: elements up a side wall (r = 1)"} ];
DefineConstant[ nz0 = {2, Min 1, Name "nz0: elements along z (r = 1)"} ];
DefineConstant[ tet = {0, Choices{0, 1}, Name "tet: 1 meshes tetrahedra (the same grid, each hexahedron in six)"} ];
m = Ceil(m0 * r);
k = Ceil(k0 * r);
nz = Ceil(nz0 * r);
W = 3.0;
H = 1.0;
t = 0.3;
a = 1.2;
b = 1.8;
D = 1.0;
xs[] = {0, t, a, b, W - t, W};
ys[] = {0, t, H - t, H};
nt[] = {m, Ceil(6 * r), Ceil(3 * r), Ceil(6 * r), m};  // along x per column, top wall (the corners: m)
nb[] = {m, Ceil(5 * r), Ceil(4 * r), Ceil(5 * r), m};  // bottom wall

// Grid points P(i, j) = 10 j + i + 1, horizontal curves 100 + 10 j + i
// (P(i,j) -> P(i+1,j)), vertical 200 + 10 j + i (P(i,j) -> P(i,j+1)).
For j In {0:3}
  For i In {0:5}
    Point(10 * j + i + 1) = {xs[i], ys[j], 0};
  EndFor
EndFor
For j In {0:3}
  For i In {0:4}
    Line(100 + 10 * j + i) = {10 * j + i + 1, 10 * j + i + 2};
    Transfinite Curve{100 + 10 * j + i} = (j < 2 ? nb[i] : nt[i]) + 1;
  EndFor
EndFor
For j In {0:2}
  For i In {0:5}
    Line(200 + 10 * j + i) = {10 * j + i + 1, 10 * (j + 1) + i + 1};
    Transfinite Curve{200 + 10 * j + i} = (j == 1 ? k : m) + 1;
  EndFor
EndFor
// The material cells: the bottom (j = 0) and top (j = 2) walls, and the
// side walls (j = 1, i = 0 and 4).
cells[] = {};
For j In {0:2}
  For i In {0:4}
    If (j != 1 || i == 0 || i == 4)
      s = 300 + 10 * j + i;
      Curve Loop(s) = {100 + 10 * j + i, 200 + 10 * j + i + 1, -(100 + 10 * (j + 1) + i), -(200 + 10 * j + i)};
      Plane Surface(s) = {s};
      Transfinite Surface{s};
      If (tet == 0)
        Recombine Surface{s};
      EndIf
      cells[] += s;
    EndIf
  EndFor
EndFor
If (tet == 0)
  Extrude {0, 0, D} { Surface{cells[]}; Layers{nz}; Recombine; }
Else
  // Structured triangles extruded without Recombine: each prism in three tetrahedra.
  Extrude {0, 0, D} { Surface{cells[]}; Layers{nz}; }
EndIf

e = 1e-6;
Physical Volume("tube", 1) = Volume{:};
Physical Surface("inner", 2) = Surface In BoundingBox{t - e, t - e, -e, W - t + e, H - t + e, D + e};
Physical Surface("inner_top", 3) = Surface In BoundingBox{t - e, H - t - e, -e, W - t + e, H - t + e, D + e};
Physical Surface("inner_bottom", 4) = Surface In BoundingBox{t - e, t - e, -e, W - t + e, t + e, D + e};
Physical Surface("plate_top", 5) = Surface In BoundingBox{a - e, H - e, -e, b + e, H + e, D + e};
Physical Surface("plate_bottom", 6) = Surface In BoundingBox{a - e, -e, -e, b + e, e, D + e};
Physical Surface("front", 7) = Surface In BoundingBox{-e, -e, -e, W + e, H + e, e};
Physical Surface("back", 8) = Surface In BoundingBox{-e, -e, D - e, W + e, H + e, D + e};
