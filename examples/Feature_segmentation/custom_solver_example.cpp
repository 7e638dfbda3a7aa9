// A user-written correlation clustering solver plugged into the segmentation. Any class
// with the copy constructor and the const operator() of the CorrelationClusteringSolver
// concept will do; this one is deliberately naive, to show what the default solver buys.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/defaults.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor        vertex_descriptor;

namespace FS = CGAL::Feature_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;

// Joins the endpoints of every edge of positive weight (union-find): no attracting edge
// is ever cut, but repelling edges inside a cluster are not cut either, which is why
// its cut cost is higher than that of a real solver.
struct Join_positive_edges
{
  std::size_t operator()(const FS::Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    labels.resize(g.number_of_nodes());
    for(std::size_t i = 0; i < labels.size(); ++i)
      labels[i] = i;
    auto find = [&labels](std::size_t i) {
      while(labels[i] != i)
        i = labels[i] = labels[labels[i]]; // path halving
      return i;
    };
    for(std::size_t e = 0; e < g.number_of_edges(); ++e)
      if(g.weight(e) > 0)
        labels[find(g.source(e))] = find(g.target(e));
    for(std::size_t i = 0; i < labels.size(); ++i)
      labels[i] = find(i);
    return FS::normalize_labels(labels); // the concept asks for labels 0..k-1
  }
};

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : FS_MESH_DIR "/fandisk.off";

  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a readable triangle mesh." << std::endl;
    return 1;
  }

  auto vertex_patch = mesh.add_property_map<vertex_descriptor, std::size_t>("v:patch").first;

  double custom_cost = 0, default_cost = 0;
  const std::size_t custom_patches =
    FS::segment_along_features(mesh, vertex_patch,
                               FS::parameters::alpha(FS::default_alpha)
                                              .solver(Join_positive_edges())
                                              .cut_cost_output(&custom_cost));
  const std::size_t default_patches =
    FS::segment_along_features(mesh, vertex_patch,
                               FS::parameters::alpha(FS::default_alpha).cut_cost_output(&default_cost));

  std::cout << "Join along positive edges: " << custom_patches << " patches, cut cost "
            << custom_cost << std::endl;
  std::cout << "Default solver (GAEC + KLj): " << default_patches << " patches, cut cost "
            << default_cost << std::endl;
  return 0;
}
