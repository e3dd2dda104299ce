// The section of an O-ring in the r-z half plane of an axisymmetric scene
// (x = r, y = z): a disc of radius 1 about (10, -0.4), a ring of cord
// diameter 2 and mean diameter 20, resting on the groove's back wall. Its
// surface in four named arcs, by the angle from +x (the bore, where
// parameters/o_ring_axisymmetric.prm squeezes it): "bore side" -50..40 degrees (against the rigid bore, the
// obstacle), "pressure side" 40..135 (where the sealed fluid presses),
// "groove side" 135..300 (against the groove's bottom and back wall, the
// rigid tool), "extrusion side" 300..310 (the short arc between, in front
// of the gap between the shaft and the bore, in contact with neither: a
// vertex may belong to one contact only).
// Regenerate: gmsh -2 -format msh22 o_ring_section.geo -o o_ring_section.msh
a = 1;
rc = 10;
zc = -0.4;
h = 0.16;          // before the subdivision into quadrilaterals of about 0.08
Point(1) = {rc, zc, 0, h};
angles[] = {-50, 40, 135, 220, 300};
For i In {0 : 4}
  Point(10 + i) = {rc + a * Cos(angles[i] * Pi / 180), zc + a * Sin(angles[i] * Pi / 180), 0, h};
EndFor
Circle(1) = {10, 1, 11};
Circle(2) = {11, 1, 12};
Circle(3) = {12, 1, 13};
Circle(4) = {13, 1, 14};
Circle(5) = {14, 1, 10};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Physical Curve("bore side", 1) = {1};
Physical Curve("pressure side", 2) = {2};
Physical Curve("groove side", 3) = {3, 4};
Physical Curve("extrusion side", 4) = {5};
Physical Surface("ring", 1) = {1};
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;            // frontal-Delaunay, then recombined
Mesh.SubdivisionAlgorithm = 1; // all quadrilaterals
