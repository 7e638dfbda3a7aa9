// A thin plate with three round holes: six planes and three cylinders, all at 90 degrees.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.6;
Mesh.MeshSizeFromCurvature = 16;
Box(1) = {0, 0, 0, 20, 12, 1};
Cylinder(2) = {5, 6, -1, 0, 0, 3, 2};
Cylinder(3) = {12, 4, -1, 0, 0, 3, 1.5};
Cylinder(4) = {15, 8.5, -1, 0, 0, 3, 1};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2, 3, 4}; Delete; }
