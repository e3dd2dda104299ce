// The two bodies of parameters/block_on_block_2d.prm as one Gmsh file: a
// base 2 x 0.5 (24 x 6 cells) and a block 1 x 0.5 (16 x 8 cells) on it,
// meshed apart (their vertices at the interface are distinct), with the
// names Geometry/Stacked blocks gives them. The same bodies from a file
// must give the same forces (tests/comparisons.cmake, two_blocks_from_file_2d).
// Regenerate: gmsh -2 -format msh22 two_blocks_2d.geo -o two_blocks_2d.msh
Geometry.AutoCoherence = 0;   // keep the two bodies' points apart
Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 0.5, 0};
Point(4) = {0, 0.5, 0};
Point(5) = {0.5, 0.5, 0};
Point(6) = {1.5, 0.5, 0};
Point(7) = {1.5, 1, 0};
Point(8) = {0.5, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve {1, 3} = 25;
Transfinite Curve {2, 4} = 7;
Transfinite Curve {5, 7} = 17;
Transfinite Curve {6, 8} = 9;
Transfinite Surface {1, 2};
Recombine Surface {1, 2};
Physical Curve("base bottom", 1) = {1};
Physical Curve("base right", 2) = {2};
Physical Curve("base top", 3) = {3};
Physical Curve("base left", 4) = {4};
Physical Curve("block bottom", 5) = {5};
Physical Curve("block right", 6) = {6};
Physical Curve("block top", 7) = {7};
Physical Curve("block left", 8) = {8};
Physical Surface("base", 1) = {1};
Physical Surface("block", 2) = {2};
