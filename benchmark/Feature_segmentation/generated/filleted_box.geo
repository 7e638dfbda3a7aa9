// A box with every edge rounded: six planes, twelve cylindrical fillets and eight
// spherical corners, all meeting tangentially (a fillet-rounded housing).
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.6;
Mesh.MeshSizeFromCurvature = 16;
Box(1) = {0, 0, 0, 10, 6, 4};
Fillet{1}{1:12}{1.2}
