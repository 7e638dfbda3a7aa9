// A turned part: a cylinder, a cone, a thinner cylinder and a hemispherical end about
// the z axis; the cone meets the cylinders at 27 degrees, the sphere meets its cylinder
// tangentially, and the bottom is flat.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.4;
Mesh.MeshSizeFromCurvature = 16;
Cylinder(1) = {0, 0, 0, 0, 0, 6, 2};
Cone(2) = {0, 0, 6, 0, 0, 2, 2, 1};
Cylinder(3) = {0, 0, 8, 0, 0, 4, 1};
Sphere(4) = {0, 0, 12, 1};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2, 3, 4}; Delete; }
