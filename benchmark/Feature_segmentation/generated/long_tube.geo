// A tube twenty times longer than wide: outer and inner cylinders and two annular ends
// bent by 90 degrees from them.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.5;
Mesh.MeshSizeFromCurvature = 16;
Cylinder(1) = {0, 0, 0, 40, 0, 0, 1};
Cylinder(2) = {0, 0, 0, 40, 0, 0, 0.75};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
