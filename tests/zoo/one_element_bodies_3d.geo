// One element per body, 3D (zoo case one_element_bodies_3d): a `left` cube
// [0,1]^3 and a `right` cube [1,2] x [0,1]^2, one HEX8 each, touching on
// x = 1 through separate (coincident) nodes: two meshes, not merged. Run at
// more ranks than elements, it leaves ranks that own no element of a block,
// no slave face, or nothing at all.
// Sets: `x0` (x = 0), `slave` (left cube, x = 1), `master` (right cube,
// x = 1), `x2` (x = 2), `y0` (y = 0) and `z0` (z = 0) of both cubes.
// The right cube is built one unit further and moved back, so that gmsh does
// not merge the coincident faces.
// Make with: scripts/make_mesh tests/zoo/one_element_bodies_3d.geo tests/zoo/meshes/one_element_bodies_3d.e
Point(1) = {0, 0, 0};
Point(2) = {0, 1, 0};
Point(3) = {0, 1, 1};
Point(4) = {0, 0, 1};
Line(1) = {1, 2};  // z = 0
Line(2) = {2, 3};  // y = 1
Line(3) = {3, 4};  // z = 1
Line(4) = {4, 1};  // y = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
left[] = Extrude {1, 0, 0} { Surface{1}; Layers{1}; Recombine; };

Point(101) = {2, 0, 0};
Point(102) = {2, 1, 0};
Point(103) = {2, 1, 1};
Point(104) = {2, 0, 1};
Line(101) = {101, 102};
Line(102) = {102, 103};
Line(103) = {103, 104};
Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = 2;
Transfinite Surface{101};
Recombine Surface{101};
right[] = Extrude {1, 0, 0} { Surface{101}; Layers{1}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {-1, 0, 0} { Volume{right[1]}; }

// Extrude gives [end face, volume, the faces of lines 1..4 in order].
Physical Volume("left", 1) = {left[1]};
Physical Volume("right", 2) = {right[1]};
Physical Surface("x0", 3) = {1};
Physical Surface("slave", 4) = {left[0]};
Physical Surface("master", 5) = {101};
Physical Surface("x2", 6) = {right[0]};
Physical Surface("y0", 7) = {left[5], right[5]};
Physical Surface("z0", 8) = {left[2], right[2]};
