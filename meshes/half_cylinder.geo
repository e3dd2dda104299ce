// A 3D half cylinder (a roller cut along its axis) of radius 1 and length
// 1: the half disc of half_disc.geo extruded along z; hexahedra. The curved
// face touches the plane y = 0 along the line x = 0.
// Regenerate: gmsh -3 -format msh22 half_cylinder.geo -o half_cylinder.msh
R = 1;
L = 1;
h_far = 0.3;
h_contact = 0.06;
Point(1) = {0, R, 0, h_far};
Point(2) = {-R, R, 0, h_far};
Point(3) = {0, 0, 0, h_contact};
Point(4) = {R, R, 0, h_far};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Recombine Surface {1};
out[] = Extrude {0, 0, L} { Surface{1}; Layers{8}; Recombine; };
// out[0]: the far end, out[1]: the body, out[2..4]: the sides from curves 1..3
Physical Surface("curved", 1) = {out[2], out[3]};
Physical Surface("top", 2) = {out[4]};
Physical Surface("front", 3) = {1};
Physical Surface("back", 4) = {out[0]};
Physical Volume("body", 1) = {out[1]};
Mesh.Algorithm = 6;            // frontal-Delaunay, then recombined
Mesh.SubdivisionAlgorithm = 1;
