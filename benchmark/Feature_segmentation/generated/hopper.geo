// A hopper: a wide cylindrical bin over a cone that narrows into a spout; the cone
// meets both cylinders at 34 degrees.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.6;
Mesh.MeshSizeFromCurvature = 16;
Cylinder(1) = {0, 0, 6, 0, 0, 3, 5};
Cone(2) = {0, 0, 0, 0, 0, 6, 1, 5};
Cylinder(3) = {0, 0, -3, 0, 0, 3, 1};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; }
