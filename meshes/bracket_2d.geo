// A steel angle bracket pressed into a softer base, as two bodies meshed
// apart in one file (physical surfaces "base" and "bracket"): the base is
// 3 x 1, the bracket's foot 1.2 x 0.2 lies on it from x = 1 to 2.2, its
// upright 0.2 wide rises to y = 2. The bracket (the finer mesh) carries the
// contact: Contact/Pairs = bracket foot : base top. Unstructured
// quadrilaterals, finer where the foot meets the base.
// Regenerate: gmsh -2 -format msh22 bracket_2d.geo -o bracket_2d.msh
Geometry.AutoCoherence = 0;   // keep the two bodies' points apart
h_base = 0.12;                // cells of the base, away from the foot
h_contact = 0.05;             // cells along the foot and under it
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

Point(11) = {1, 1, 0, h_contact};
Point(12) = {2.2, 1, 0, h_contact};
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

Physical Curve("base bottom", 1) = {1};
Physical Curve("base sides", 2) = {2, 6};
Physical Curve("base top", 3) = {3, 4, 5};
Physical Curve("bracket foot", 4) = {11};
Physical Curve("bracket top", 5) = {15};
Physical Curve("bracket sides", 6) = {12, 13, 14, 16};
Physical Surface("base", 1) = {1};
Physical Surface("bracket", 2) = {2};
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;              // frontal-Delaunay, then recombined
Mesh.RecombinationAlgorithm = 3; // blossom, full quadrilaterals (no
                                 // subdivision: its cells took 70 times the
                                 // Krylov iterations)
