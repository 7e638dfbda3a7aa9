// Interactive use: precompute once, then refine globally and locally, merge, undo; each
// edit re-solves the reduced graph only.
#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/defaults.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace FS = CGAL::Feature_segmentation;

int main(int argc, char* argv[])
{
  const std::string filename = (argc > 1) ? argv[1] : std::string(FS_MESH_DIR) + "/fandisk.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from " << filename << std::endl;
    return 1;
  }

  // The edits move the alpha_e of the feature edges. fandisk is a clean CAD tessellation,
  // whose feature lines are by default its creases alone; the paper's crest lines give
  // the edits more to act on.
  FS::Feature_aligned_segmentation<Mesh> segmentation(
    mesh, FS::parameters::alpha(FS::default_alpha).crest_lines_on_clean_tessellations(true));
  std::cout << "alpha " << FS::default_alpha << ": " << segmentation.number_of_patches() << " patches, "
            << segmentation.number_of_oversegments() << " oversegments" << std::endl;

  // global refinement
  std::cout << "alpha 0.9: " << segmentation.set_alpha(0.9) << " patches" << std::endl;

  // local coarsening on the faces that look up (a painted region, say)
  std::vector<Mesh::Face_index> region;
  for(Mesh::Face_index f : faces(mesh))
    if(CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh).z() > 0.9)
      region.push_back(f);
  std::cout << "coarsen " << region.size() << " faces: "
            << segmentation.add_to_alpha(region, -0.3) << " patches" << std::endl;

  // merge whatever the region touches, then take it back
  std::cout << "merge: " << segmentation.merge_patches(region) << " patches" << std::endl;
  segmentation.undo();
  std::cout << "undo: " << segmentation.number_of_patches() << " patches, cut cost "
            << segmentation.cut_cost() << std::endl;

  auto face_patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch").first;
  segmentation.face_patches(face_patch);
  return 0;
}
