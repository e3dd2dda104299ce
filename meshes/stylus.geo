// A ball-ended stylus: a ball of radius 0.5 centred at (1, 1, 1) joined
// to a cylinder of the same radius above it, its lowest point at z = 0.5
// (the top of the slab of parameters/scratch_3d.prm). The surface of a rigid
// tool for <Contact/Rigid tool/Surface mesh>, as a binary STL whose normals
// point out of the volume. gmsh -2 -format stl stylus.geo
SetFactory("OpenCASCADE");
Sphere(1) = {1, 1, 1.0, 0.5};
Cylinder(2) = {1, 1, 1.0, 0, 0, 0.6, 0.5};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.MeshSizeMax = 0.06;
Mesh.MeshSizeMin = 0.02;
Mesh.Binary = 1;
