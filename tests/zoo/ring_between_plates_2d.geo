// dim: 2
// Ring between plates, plane strain: a thin elastic `ring` (mean radius R = 1,
// wall t = 0.1: 0.95 <= r <= 1.05) between two plates, the `top_plate`
// [-0.5, 0.5] x [1.05, 1.25] and the `bottom_plate` [-0.5, 0.5] x [-1.25, -1.05],
// touching the ring at (0, +-1.05). Structured QUAD4, mirror symmetric about
// both axes: the ring in 8 sectors of 45 deg (from 0 deg), 12n elements around
// each (96n around the ring, element length 2 pi R / 96n = t / 6.1 at n = 4)
// and n through the wall; each plate 40 x 8 (node at x = 0). Separate meshes.
// Blocks `ring`, `top_plate`, `bottom_plate`; sets `slave_top` (ring outer arc
// 45..135 deg), `slave_bottom` (225..315 deg), `master_top` (top plate's
// bottom face), `master_bottom` (bottom plate's top face), `top` (y = 1.25),
// `bottom` (y = -1.25), node sets `ring_axis` (inner points at 90 and 270 deg,
// on the vertical axis) and `ring_side` (inner points at 0 and 180 deg).
// Make with: scripts/make_mesh tests/zoo/ring_between_plates_2d.geo tests/zoo/meshes/ring_between_plates_2d.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: resolution (12n elements per 45 deg, n through the wall)"} ];
ri = 0.95;
ro = 1.05;
w = 0.5;
hp = 0.2;
Geometry.AutoCoherence = 0;  // the plates touch the ring: keep separate meshes

Point(1) = {0, 0, 0};
For k In {0 : 7}
  Point(10 + k) = {ri * Cos(k * Pi / 4), ri * Sin(k * Pi / 4), 0};
  Point(20 + k) = {ro * Cos(k * Pi / 4), ro * Sin(k * Pi / 4), 0};
EndFor
For k In {0 : 7}
  k1 = (k + 1) % 8;
  Circle(10 + k) = {10 + k, 1, 10 + k1};   // inner arc of sector k
  Circle(20 + k) = {20 + k, 1, 20 + k1};   // outer arc of sector k
  Line(30 + k) = {10 + k, 20 + k};         // radial line at k 45 deg
EndFor
For k In {0 : 7}
  k1 = (k + 1) % 8;
  Curve Loop(10 + k) = {30 + k, 20 + k, -(30 + k1), -(10 + k)};
  Plane Surface(10 + k) = {10 + k};
  Transfinite Surface{10 + k};
EndFor
Transfinite Curve{10 : 17, 20 : 27} = 12 * n + 1;
Transfinite Curve{30 : 37} = n + 1;
Recombine Surface{10 : 17};

// plates
Point(101) = {-w, ro, 0};
Point(102) = {w, ro, 0};
Point(103) = {w, ro + hp, 0};
Point(104) = {-w, ro + hp, 0};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Point(111) = {-w, -ro - hp, 0};
Point(112) = {w, -ro - hp, 0};
Point(113) = {w, -ro, 0};
Point(114) = {-w, -ro, 0};
Line(111) = {111, 112};
Line(112) = {112, 113};
Line(113) = {113, 114};
Line(114) = {114, 111};
Curve Loop(111) = {111, 112, 113, 114};
Plane Surface(111) = {111};
Transfinite Curve{101, 103, 111, 113} = 41;
Transfinite Curve{102, 104, 112, 114} = 9;
Transfinite Surface{101, 111};
Recombine Surface{101, 111};

Physical Surface("ring", 1) = {10 : 17};
Physical Surface("top_plate", 2) = {101};
Physical Surface("bottom_plate", 3) = {111};
Physical Curve("slave_top", 4) = {21, 22};
Physical Curve("slave_bottom", 5) = {25, 26};
Physical Curve("master_top", 6) = {101};
Physical Curve("master_bottom", 7) = {113};
Physical Curve("top", 8) = {103};
Physical Curve("bottom", 9) = {111};
Physical Point("ring_axis", 10) = {12, 16};
Physical Point("ring_side", 11) = {10, 14};
