// The groove an O-ring sits in, cut into a shaft (the rigid tool of
// parameters/o_ring_axisymmetric.prm), in the r-z half plane (x = r,
// y = z): the shaft's surface at r = 10.5, the groove's bottom at r = 9
// and its walls at z = -1.4 (the back wall the fluid pushes the ring
// against) and z = 1.4, a groove 1.5 deep and 2.8 wide for a cord of 2.
// The line runs along +z, down into the groove and out again, so that its
// normal (to the right of the direction) points out of the shaft.
// Regenerate: gmsh -1 -format msh22 o_ring_groove.geo -o o_ring_groove.msh
h = 0.05;
Point(1) = {10.5, -3, 0, 4 * h};
Point(2) = {10.5, -1.4, 0, h};
Point(3) = {9, -1.4, 0, h};
Point(4) = {9, 1.4, 0, h};
Point(5) = {10.5, 1.4, 0, h};
Point(6) = {10.5, 3, 0, 4 * h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Physical Line("groove") = {1, 2, 3, 4, 5};
