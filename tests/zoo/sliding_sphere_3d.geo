// Sliding sphere, 3D half model y >= 0 (the symmetry plane y = 0 contains the
// sliding direction x): a stiff spherical cap (the die: sphere of radius
// R = 10 centred at (0, 0, R), cut by the plane z = H = 2, base radius 6)
// touching a softer slab [-5, 13] x [0, 5] x [-5, 0] at the origin; two
// separate meshes (built-in kernel).
// Slab: structured HEX8, uniform size h on the track x in [-1.5, 9.5],
// y in [0, 1.5] (the contact patch, radius a ~ 1.1, for the slide s in
// [0, 8]), growing geometrically towards the sides (ratio 2) and with the
// depth (ratio 1.5). Die: unstructured TET4, element size hd = 1.25 h within r0 = 1.5 of
// the pole (r = distance to the origin), growing as hd + 0.4 (r - r0) beyond,
// at most 1.5. The slab top is the slave (the finer mesh, on the soft body
// whose deformation it must resolve), the die's cap the master.
// Blocks `die`, `slab`; sets `slave` (slab top z = 0), `master` (die cap),
// `top` (die, z = H), `bottom` (slab, z = -5), `symmetry_y` (y = 0, both).
// Make with: scripts/make_mesh tests/zoo/sliding_sphere_3d.geo tests/zoo/meshes/sliding_sphere_3d.e -setnumber h 0.25
DefineConstant[ h = {0.25, Min 0.01, Name "h: slab (slave) element size along the track"} ];
R = 10;
H = 2;
rb = Sqrt(R * R - (R - H) * (R - H));
r0 = 1.5;
g = 0.4;
hm = h;
hd = 1.25 * h;
e = 1e-6;
// No geometric point of the die coincides with one of the slab (the pole lies
// inside a slab patch), so the default coherence keeps two separate meshes and
// merges the coincident points of the extruded slab patches.

// ---- die
Point(1) = {0, 0, 0, 1};      // pole
Point(2) = {0, 0, R, 1};      // sphere centre (not meshed)
Point(3) = {0, 0, H, 1};      // centre of the base circle (not meshed)
Point(4) = {rb, 0, H, 1};
Point(5) = {0, rb, H, 1};
Point(6) = {-rb, 0, H, 1};
Circle(1) = {1, 2, 4};        // meridian y = 0, x > 0
Circle(2) = {1, 2, 5};        // meridian x = 0
Circle(3) = {1, 2, 6};        // meridian y = 0, x < 0
Circle(4) = {4, 3, 5};        // base arcs
Circle(5) = {5, 3, 6};
Line(6) = {6, 4};             // diameter of the top, y = 0
Curve Loop(1) = {1, 4, -2};
Surface(1) = {1} In Sphere {2};
Curve Loop(2) = {2, 5, -3};
Surface(2) = {2} In Sphere {2};
Curve Loop(3) = {4, 5, 6};
Plane Surface(3) = {3};       // top z = H
Curve Loop(4) = {1, -6, -3};
Plane Surface(4) = {4};       // symmetry plane y = 0
Surface Loop(1) = {1, 2, 3, 4};
Volume(1) = {1};

Field[1] = MathEval;
Field[1].F = Sprintf("Min(Max(%g, %g + %g * (Sqrt(x * x + y * y + z * z) - %g)), 1.5)", hd, hd, g, r0);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// ---- slab: the top z = 0 as 3 x 2 structured patches, extruded downwards
xs[] = {-5, -1.5, 9.5, 13};
ys[] = {0, 1.5, 5};
D = 5;
For j In {0 : 2}
  For i In {0 : 3}
    Point(100 + 10 * j + i) = {xs[i], ys[j], 0, 1};
  EndFor
EndFor
rx = 2;
nmid = Ceil((xs[2] - xs[1]) / hm);
nxl = Ceil(Log(1 + (xs[1] - xs[0]) * (rx - 1) / hm) / Log(rx));
nxr = Ceil(Log(1 + (xs[3] - xs[2]) * (rx - 1) / hm) / Log(rx));
nyf = Ceil((ys[1] - ys[0]) / hm);
nyw = Ceil(Log(1 + (ys[2] - ys[1]) * (rx - 1) / hm) / Log(rx));
// lines along x (row j), oriented from the track outwards on graded parts
For j In {0 : 2}
  Line(200 + 10 * j + 0) = {100 + 10 * j + 1, 100 + 10 * j + 0};
  Line(200 + 10 * j + 1) = {100 + 10 * j + 1, 100 + 10 * j + 2};
  Line(200 + 10 * j + 2) = {100 + 10 * j + 2, 100 + 10 * j + 3};
  Transfinite Curve{200 + 10 * j + 0} = nxl + 1 Using Progression rx;
  Transfinite Curve{200 + 10 * j + 1} = nmid + 1;
  Transfinite Curve{200 + 10 * j + 2} = nxr + 1 Using Progression rx;
EndFor
// lines along y (column i), from y = 0 outwards
For i In {0 : 3}
  Line(300 + i) = {100 + i, 110 + i};
  Line(310 + i) = {110 + i, 120 + i};
  Transfinite Curve{300 + i} = nyf + 1;
  Transfinite Curve{310 + i} = nyw + 1 Using Progression rx;
EndFor
// patch (i, j): x between xs[i], xs[i+1], y between ys[j], ys[j+1]
// bottom edge of patch (i, j): x-line 200 + 10 j + i (i = 0 reversed), top edge 200 + 10 (j + 1) + i
For j In {0 : 1}
  For i In {0 : 2}
    s = 400 + 10 * j + i;
    If (i == 0)
      Curve Loop(s) = {-(200 + 10 * j), 300 + 10 * j + 1, (200 + 10 * (j + 1)), -(300 + 10 * j)};
    Else
      Curve Loop(s) = {200 + 10 * j + i, 300 + 10 * j + i + 1, -(200 + 10 * (j + 1) + i), -(300 + 10 * j + i)};
    EndIf
    Plane Surface(s) = {s};
    Transfinite Surface{s};
    Recombine Surface{s};
  EndFor
EndFor
patches[] = {400, 401, 402, 410, 411, 412};
// graded layers in depth: heights hm rz^k, k = 0..nz-1, scaled to D
rz = 1.5;
nz = Ceil(Log(1 + D * (rz - 1) / hm) / Log(rz));
total = hm * (rz^nz - 1) / (rz - 1);
cum = 0;
For k In {0 : nz - 1}
  one[k] = 1;
  cum += hm * rz^k / total;
  frac[k] = cum;
EndFor
slab[] = Extrude {0, 0, -D} { Surface{patches[]}; Layers{one[], frac[]}; Recombine; };
slabVol[] = {};
For k In {0 : 5}
  slabVol[] += slab[6 * k + 1];
EndFor

Physical Volume("die", 1) = {1};
Physical Volume("slab", 2) = {slabVol[]};
Physical Surface("slave", 3) = {patches[]};
Physical Surface("master", 4) = {1, 2};
Physical Surface("top", 5) = {3};
Physical Surface("bottom", 6) = Surface In BoundingBox{xs[0] - e, -e, -D - e, xs[3] + e, ys[2] + e, -D + e};
symSlab[] = Surface In BoundingBox{xs[0] - e, -e, -D - e, xs[3] + e, e, e};
Physical Surface("symmetry_y", 7) = {4, symSlab[]};
