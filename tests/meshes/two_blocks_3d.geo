// The two bodies of parameters/block_on_block_3d.prm as one Gmsh file: a
// base 2 x 2 x 0.5 (12 x 12 x 3 cells) and a block 1 x 1 x 0.5 (8 x 8 x 4
// cells) on it, meshed apart, with the names Geometry/Stacked blocks gives
// them (front: y = 0, left: x = 0).
// Regenerate: gmsh -3 -format msh22 two_blocks_3d.geo -o two_blocks_3d.msh
Geometry.AutoCoherence = 0;   // keep the two bodies' points apart
Macro MakeBox
  // a box [x0, x0 + lx] x [y0, y0 + ly] x [z0, z0 + lz] with n cells in each direction
  p = newp;
  Point(p) = {x0, y0, z0};
  Point(p + 1) = {x0 + lx, y0, z0};
  Point(p + 2) = {x0 + lx, y0 + ly, z0};
  Point(p + 3) = {x0, y0 + ly, z0};
  l = newl;
  Line(l) = {p, p + 1};          // front
  Line(l + 1) = {p + 1, p + 2};  // right
  Line(l + 2) = {p + 2, p + 3};  // back
  Line(l + 3) = {p + 3, p};      // left
  Transfinite Curve {l, l + 2} = nx + 1;
  Transfinite Curve {l + 1, l + 3} = ny + 1;
  c = newll;
  Curve Loop(c) = {l, l + 1, l + 2, l + 3};
  s = news;
  Plane Surface(s) = {c};
  Transfinite Surface {s};
  Recombine Surface {s};
  out[] = Extrude {0, 0, lz} { Surface{s}; Layers{nz}; Recombine; };
  // out[0]: top, out[1]: volume, out[2..5]: front, right, back, left
Return

x0 = 0; y0 = 0; z0 = 0; lx = 2; ly = 2; lz = 0.5; nx = 12; ny = 12; nz = 3;
Call MakeBox;
Physical Surface("base bottom", 1) = {s};
Physical Surface("base top", 2) = {out[0]};
Physical Surface("base front", 3) = {out[2]};
Physical Surface("base right", 4) = {out[3]};
Physical Surface("base back", 5) = {out[4]};
Physical Surface("base left", 6) = {out[5]};
Physical Volume("base", 1) = {out[1]};

x0 = 0.5; y0 = 0.5; z0 = 0.5; lx = 1; ly = 1; lz = 0.5; nx = 8; ny = 8; nz = 4;
Call MakeBox;
Physical Surface("block bottom", 7) = {s};
Physical Surface("block top", 8) = {out[0]};
Physical Surface("block front", 9) = {out[2]};
Physical Surface("block right", 10) = {out[3]};
Physical Surface("block back", 11) = {out[4]};
Physical Surface("block left", 12) = {out[5]};
Physical Volume("block", 2) = {out[1]};
