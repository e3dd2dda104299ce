// The bottom of a flat punch 1 wide, at y = 0.5 from x = 0.5 to 1.5: the
// surface of a rigid tool (line elements) for <Contact/Rigid tool/Surface
// mesh>, as the block of parameters/block_on_block_2d.prm has it. The line
// runs along +x, so its normal (to the right of the direction) points
// down, out of the punch. gmsh -1 -format msh2 flat_punch_2d.geo
Point(1) = {0.5, 0.5, 0, 1/16};
Point(2) = {1.5, 0.5, 0, 1/16};
Line(1) = {1, 2};
Physical Line("punch") = {1};
