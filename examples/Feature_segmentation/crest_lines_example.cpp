// Principal curvatures, then the ridges and valleys they define (paper, Section 3.1).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor        vertex_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor          edge_descriptor;

namespace FS = CGAL::Feature_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : FS_MESH_DIR "/fandisk.off";

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a readable triangle mesh." << std::endl;
    return 1;
  }

  // The curvatures are kept in a property map so that they can be reused by later
  // stages (edge weights, segmentation) instead of being estimated again.
  Mesh::Property_map<vertex_descriptor, FS::Principal_curvatures<K> > curvature =
    mesh.add_property_map<vertex_descriptor, FS::Principal_curvatures<K> >("v:curvature").first;
  FS::estimate_principal_curvatures(mesh, curvature, FS::parameters::neighborhood_rings(2));

  FS::Feature_lines<Mesh> lines = FS::detect_crest_lines(mesh, curvature);

  Mesh::Property_map<edge_descriptor, bool> is_feature =
    mesh.add_property_map<edge_descriptor, bool>("e:is_feature", false).first;
  const std::size_t nb_feature_edges = FS::mark_feature_edges(mesh, lines, is_feature);

  std::cout << "This mesh contains " << lines.number_of_lines(FS::Feature_line_type::RIDGE)
            << " ridges and " << lines.number_of_lines(FS::Feature_line_type::VALLEY)
            << " valleys," << std::endl;
  std::cout << " crossing " << nb_feature_edges << " feature edges." << std::endl;
  if(!lines.lines.empty())
    std::cout << "The strongest line has " << lines.lines.front().points.size()
              << " points and strength " << lines.lines.front().strength << "." << std::endl;
  return 0;
}
