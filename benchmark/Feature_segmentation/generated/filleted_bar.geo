// A bar twenty times longer than wide with every edge rounded: planes, cylindrical
// fillets and spherical corners meeting tangentially.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.3;
Mesh.MeshSizeFromCurvature = 16;
Box(1) = {0, 0, 0, 30, 1.5, 1.5};
Fillet{1}{1:12}{0.4}
