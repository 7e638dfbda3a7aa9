// Downstream use of the package: curvature of a tetrahedron's subdivided sphere stand-in
// (an octahedron projected on the unit sphere) must be positive everywhere.
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <iostream>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main()
{
  Mesh m;
  auto px = m.add_vertex(K::Point_3(1, 0, 0)), nx = m.add_vertex(K::Point_3(-1, 0, 0));
  auto py = m.add_vertex(K::Point_3(0, 1, 0)), ny = m.add_vertex(K::Point_3(0, -1, 0));
  auto pz = m.add_vertex(K::Point_3(0, 0, 1)), nz = m.add_vertex(K::Point_3(0, 0, -1));
  m.add_face(px, py, pz); m.add_face(py, nx, pz); m.add_face(nx, ny, pz); m.add_face(ny, px, pz);
  m.add_face(py, px, nz); m.add_face(nx, py, nz); m.add_face(ny, nx, nz); m.add_face(px, ny, nz);
  auto curv = m.add_property_map<Mesh::Vertex_index,
                                 CGAL::Feature_segmentation::Principal_curvatures<K> >("v:curv").first;
  CGAL::Feature_segmentation::estimate_principal_curvatures(m, curv);
  for(auto v : m.vertices())
    if(!(curv[v].k1 > 0 && curv[v].k2 > 0)) { std::cerr << "non-positive curvature\n"; return 1; }
  std::cout << "downstream OK: k1 at a vertex = " << curv[*m.vertices().begin()].k1 << "\n";
  return 0;
}
