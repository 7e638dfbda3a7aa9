// The automatic segmentation: patches whose boundaries follow the salient crest lines.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/defaults.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor        vertex_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor          face_descriptor;

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

  Mesh::Property_map<vertex_descriptor, std::size_t> vertex_patch =
    mesh.add_property_map<vertex_descriptor, std::size_t>("v:patch").first;
  Mesh::Property_map<face_descriptor, std::size_t> face_patch =
    mesh.add_property_map<face_descriptor, std::size_t>("f:patch").first;

  // alpha weighs the reward for cutting along feature edges against the cost of a long
  // boundary: larger values give more patches (useful range 0.5 to 1.0).
  double cut_cost = 0;
  const std::size_t nb_patches =
    FS::segment_along_features(mesh, vertex_patch,
                               FS::parameters::alpha(FS::default_alpha)
                                              .face_patch_map(face_patch)
                                              .cut_cost_output(&cut_cost));

  std::size_t faces_in_patch_0 = 0;
  for(face_descriptor f : faces(mesh))
    if(get(face_patch, f) == 0)
      ++faces_in_patch_0;

  std::cout << "The mesh is segmented into " << nb_patches << " patches (cut cost "
            << cut_cost << ")." << std::endl;
  std::cout << "Patch 0 holds " << faces_in_patch_0 << " of " << num_faces(mesh) << " faces." << std::endl;
  return 0;
}
