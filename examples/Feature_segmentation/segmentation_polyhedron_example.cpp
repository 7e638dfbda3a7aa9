// The automatic segmentation of a Polyhedron_3, whose items carry no index or patch
// field: the outputs go into dynamic property maps, and the package indexes the mesh
// itself, so any FaceListGraph model works the same way.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <CGAL/Feature_segmentation/defaults.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>                 K;
typedef CGAL::Polyhedron_3<K>                          Polyhedron;
typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;

namespace FS = CGAL::Feature_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : FS_MESH_DIR "/fandisk.off";

  Polyhedron poly;
  if(!PMP::IO::read_polygon_mesh(filename, poly) || !CGAL::is_triangle_mesh(poly))
  {
    std::cerr << "Invalid input: " << filename << " is not a readable triangle mesh." << std::endl;
    return 1;
  }

  auto vertex_patch = get(CGAL::dynamic_vertex_property_t<std::size_t>(), poly);
  auto face_patch = get(CGAL::dynamic_face_property_t<std::size_t>(), poly);

  double cut_cost = 0;
  const std::size_t nb_patches =
    FS::segment_along_features(poly, vertex_patch,
                               FS::parameters::alpha(FS::default_alpha)
                                              .face_patch_map(face_patch)
                                              .cut_cost_output(&cut_cost));

  // The face patches are numbered 0 to nb_patches-1 like the vertex patches; count the
  // patches that got at least one face (a patch may hold only vertices, e.g. a corner).
  std::vector<bool> has_face(nb_patches, false);
  for(face_descriptor f : faces(poly))
    has_face[get(face_patch, f)] = true;

  std::cout << "The polyhedron is segmented into " << nb_patches << " patches (cut cost "
            << cut_cost << "), " << std::count(has_face.begin(), has_face.end(), true)
            << " of which hold faces." << std::endl;
  return 0;
}
