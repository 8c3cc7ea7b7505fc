// Unit cube [0,1]^3, structured HEX8 mesh of n x n x n elements.
// Make with: scripts/make_mesh exodus_meshes/block3d.geo block3d.e -setnumber n 4
DefineConstant[ n = {4, Min 1, Name "n: elements per edge"} ];

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};  // y = 0
Line(2) = {2, 3};  // x = 1
Line(3) = {3, 4};  // y = 1
Line(4) = {4, 1};  // x = 0
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};

// out[0]: top face (z = 1), out[1]: volume, out[2..5]: faces swept by curves 1..4.
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{n}; Recombine; };

Physical Volume("body", 1) = {out[1]};
Physical Surface("bottom", 2) = {1};       // z = 0
Physical Surface("top", 3) = {out[0]};     // z = 1
Physical Surface("left", 4) = {out[5]};    // x = 0
Physical Surface("right", 5) = {out[3]};   // x = 1
Physical Surface("front", 6) = {out[2]};   // y = 0
Physical Surface("back", 7) = {out[4]};    // y = 1
