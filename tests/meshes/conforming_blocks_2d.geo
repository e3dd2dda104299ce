// A block on a base of the same width (1 x 0.5 each, 4 x 2 and 4 x 3
// cells), meshed as one conforming mesh: the two physical surfaces share
// the vertices of the interface, as a CAD part fragmented in Gmsh is.
// From file refuses it unless Split bodies = true, which gives each body
// its own copy of those vertices and names the interface 'block on base'
// and 'base on block' (tests/patch_test_split_2d.prm).
// Regenerate: gmsh -2 -format msh22 conforming_blocks_2d.geo -o conforming_blocks_2d.msh
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Point(5) = {1, 1, 0};
Point(6) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};   // the interface, shared
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};
Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};
Transfinite Curve {1, 3, 6} = 5;
Transfinite Curve {2, 4} = 3;
Transfinite Curve {5, 7} = 4;
Transfinite Surface {1, 2};
Recombine Surface {1, 2};
Physical Curve("base bottom", 1) = {1};
Physical Curve("base right", 2) = {2};
Physical Curve("base left", 4) = {4};
Physical Curve("block right", 5) = {5};
Physical Curve("block top", 6) = {6};
Physical Curve("block left", 7) = {7};
Physical Surface("base", 1) = {1};
Physical Surface("block", 2) = {2};
