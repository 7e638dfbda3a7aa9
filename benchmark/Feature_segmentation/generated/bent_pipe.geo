// A round pipe bent along a quarter arc: a straight cylinder, a torus section and a
// second straight cylinder, each meeting the next tangentially, and two annular ends.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.5;
Mesh.MeshSizeFromCurvature = 16;
Point(1) = {0, 0, 0};
Point(2) = {0, 0, 10};
Point(3) = {6, 0, 10};
Point(4) = {6, 0, 16};
Point(5) = {18, 0, 16};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Wire(1) = {1, 2, 3};
Disk(1) = {0, 0, 0, 1.5};
Disk(2) = {0, 0, 0, 1.1};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Extrude { Surface{1}; } Using Wire {1}
Delete { Surface{1}; }
