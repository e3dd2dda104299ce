// The bracket of bracket_2d.geo as a 3D part: the same two outlines,
// meshed in quadrilaterals and extruded 1 deep in hexahedra (physical
// volumes "base" and "bracket", meshed apart). The bracket's foot (the
// finer side) carries the contact: Contact/Pairs = bracket foot : base top.
// Regenerate: gmsh -3 -format msh22 bracket_3d.geo -o bracket_3d.msh
Geometry.AutoCoherence = 0;   // keep the two bodies' points apart
h_base = 0.22;                // cells of the base, away from the foot
h_contact = 0.11;             // cells along the foot and under it (with
                              // h_base, an even number of triangles in
                              // each outline, which blossom needs)
layers = 5;                   // cells through the depth
Point(1) = {0, 0, 0, h_base};
Point(2) = {3, 0, 0, h_base};
Point(3) = {3, 1, 0, h_base};
Point(4) = {2.2, 1, 0, h_contact};
Point(5) = {1, 1, 0, h_contact};
Point(6) = {0, 1, 0, h_base};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Recombine Surface {1};

Point(11) = {1, 1, 0, h_contact / 2};
Point(12) = {2.2, 1, 0, h_contact / 2};
Point(13) = {2.2, 1.2, 0, h_contact};
Point(14) = {1.2, 1.2, 0, h_contact};
Point(15) = {1.2, 2, 0, h_contact};
Point(16) = {1, 2, 0, h_contact};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 16};
Line(16) = {16, 11};
Curve Loop(2) = {11, 12, 13, 14, 15, 16};
Plane Surface(2) = {2};
Recombine Surface {2};
// Both outlines first (the extrusions number new points after them).
base[] = Extrude {0, 0, 1} { Surface{1}; Layers{layers}; Recombine; };
// base[0]: the back (z = 1), base[1]: the volume, base[2..7]: the sides
// made from curves 1 to 6
bracket[] = Extrude {0, 0, 1} { Surface{2}; Layers{2 * layers}; Recombine; };

Physical Surface("base bottom", 1) = {base[2]};
Physical Surface("base sides", 2) = {base[3], base[7]};
Physical Surface("base top", 3) = {base[4], base[5], base[6]};
Physical Surface("base front", 4) = {1};
Physical Surface("base back", 5) = {base[0]};
Physical Surface("bracket foot", 6) = {bracket[2]};
Physical Surface("bracket top", 7) = {bracket[6]};
Physical Surface("bracket sides", 8) = {bracket[3], bracket[4], bracket[5], bracket[7]};
Physical Surface("bracket front", 9) = {2};
Physical Surface("bracket back", 10) = {bracket[0]};
Physical Volume("base", 1) = {base[1]};
Physical Volume("bracket", 2) = {bracket[1]};
Mesh.Algorithm = 6;              // frontal-Delaunay, then recombined
Mesh.RecombinationAlgorithm = 3; // blossom, full quadrilaterals
