// The axisymmetric sections (x = r, y = z) of a shrink fit: a solid steel
// shaft of radius 10 and length 30, and a hub of outer radius 25 and length
// 10 on its middle, bored 0.01 smaller than the shaft (the interference
// the scene's first increment pushes out). Meshed apart, not matching along
// the fit (the hub's cells are finer). Quadrilaterals.
// Regenerate: gmsh -2 -format msh22 shrink_fit_2d.geo -o shrink_fit_2d.msh
interference = 0.01;
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {10, 30, 0};
Point(4) = {0, 30, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Transfinite Curve{1, 3} = 9;
Transfinite Curve{2, 4} = 25;
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
ri = 10 - interference;
Point(5) = {ri, 10, 0};
Point(6) = {25, 10, 0};
Point(7) = {25, 20, 0};
Point(8) = {ri, 20, 0};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Transfinite Curve{5} = 13 Using Progression 1.15;   // finer at the fit
Transfinite Curve{7} = 13 Using Progression 1 / 1.15;
Transfinite Curve{6, 8} = 12;
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Curve("shaft bottom", 1) = {1};
Physical Curve("shaft outer", 2) = {2};
Physical Curve("shaft top", 3) = {3};
Physical Curve("shaft axis", 4) = {4};
Physical Curve("hub bottom", 5) = {5};
Physical Curve("hub outer", 6) = {6};
Physical Curve("hub top", 7) = {7};
Physical Curve("hub bore", 8) = {8};
Physical Surface("shaft", 1) = {1};
Physical Surface("hub", 2) = {2};
