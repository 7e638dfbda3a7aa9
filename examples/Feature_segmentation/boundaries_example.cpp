// Smooth patch boundaries and exact per-face patches: segment, take the boundary curves,
// smooth them in the metric of the weights, then get face patches on the input mesh
// (majority of area) and on a refined mesh whose edges follow the boundaries.
#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/face_patches.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>

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

  // fandisk is a clean CAD tessellation: by default its patches are bounded by its creases
  // alone, borders of the working mesh; with the paper's crest lines some boundaries are
  // curves across the triangles, which the smoothing straightens
  FS::Feature_aligned_segmentation<Mesh> segmentation(
    mesh, FS::parameters::alpha(0.8).crest_lines_on_clean_tessellations(true));
  FS::Patch_boundaries<Mesh> boundaries = segmentation.patch_boundaries();
  std::cout << segmentation.number_of_patches() << " patches, " << boundaries.curves().size()
            << " boundary curves, " << boundaries.number_of_junctions() << " junctions" << std::endl;

  const FS::Boundary_smoothing_report report =
    FS::smooth_patch_boundaries(boundaries, FS::parameters::smoothing_iterations(10));
  std::cout << "anisotropic length " << report.energy.front() << " -> " << report.energy.back()
            << ", Euclidean length " << report.length.front() << " -> " << report.length.back()
            << " in " << report.number_of_iterations << " iterations" << std::endl;

  // (a) on the input mesh: the patch covering most of each face (the boundaries live on
  // the segmentation's working mesh, the mesh cut open along its creases; the class maps
  // its faces back to the input's)
  auto face_patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch").first;
  segmentation.face_patches(boundaries, face_patch);
  std::size_t moved = 0;
  for(Mesh::Face_index f : faces(mesh)) moved += (get(face_patch, f) != segmentation.patch(f));
  std::cout << moved << " faces take another patch than before smoothing" << std::endl;

  // (b) a refined mesh whose edges follow the boundaries, with exact face patches
  Mesh refined;
  auto refined_patch = refined.add_property_map<Mesh::Face_index, std::size_t>("f:patch").first;
  const std::size_t split = FS::refine_mesh_along_boundaries(boundaries, refined, refined_patch);
  std::cout << "refined mesh: " << num_faces(refined) << " faces (" << split << " input faces split)"
            << std::endl;
  return 0;
}
