// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh refined along the patch boundaries, written as a segmentation's PLY file
// straight from the refinement, without making the mesh first.

#ifndef CGAL_FEATURE_SEGMENTATION_IO_WRITE_REFINED_SEGMENTATION_H
#define CGAL_FEATURE_SEGMENTATION_IO_WRITE_REFINED_SEGMENTATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/IO/write_segmentation.h>
#include <CGAL/Feature_segmentation/face_patches.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationIO
/// What `write_PLY_refined_segmentation()` wrote.
struct Refined_segmentation_sizes
{
  std::size_t number_of_vertices = 0; ///< of the refined mesh
  std::size_t number_of_faces = 0;    ///< of the refined mesh
  std::size_t number_of_split_faces = 0; ///< faces of the input that were split
};

/// \ingroup PkgFeatureSegmentationIO
/// Writes the mesh refined along `boundaries` as an ASCII PLY file whose faces carry
/// their patch: the file that `write_PLY_segmentation(os, out, face_patch_map)` writes
/// after `refine_mesh_along_boundaries(boundaries, out, face_patch_map, np)` into an empty
/// `Surface_mesh`, byte for byte, without making the mesh. A refined mesh in memory
/// takes about twice the memory of the refinement it is made from (its halfedges), so
/// this is the way to write one when the mesh itself is not needed.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \param os the output stream
/// \param boundaries the boundaries
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{snapping_ratio}
///     \cgalParamDescription{a boundary point closer than this fraction of its edge's length to one of the
///                           edge's ends is snapped to that vertex; a new vertex inside a face has
///                           barycentric coordinates of at least this value}
///     \cgalParamType{`double` in [0, 0.5)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 0.5) throws `Invalid_input`. As for
///                     `refine_mesh_along_boundaries()`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return the sizes of the refined mesh and the number of input faces split; the
///         caller checks `os` for errors
///
/// \throws Invalid_input if `snapping_ratio` is outside [0, 0.5)
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Refined_segmentation_sizes write_PLY_refined_segmentation(std::ostream& os,
                                                          const Patch_boundaries<TriangleMesh>& boundaries,
                                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Refinement r = internal::refine_along_boundaries(boundaries.state(), internal::snapping_ratio(np));
  internal::write_PLY_segmentation_header(os, r.points.size(), r.triangles.size());
  internal::write_ordered_text(os, r.points.size(), [&](std::size_t i, std::string& text) {
    const auto& p = r.points[i];
    internal::append_PLY_vertex(text, p.x(), p.y(), p.z());
  });
  internal::write_ordered_text(os, r.triangles.size(), [&](std::size_t i, std::string& text) {
    const auto& t = r.triangles[i];
    const std::size_t indices[3] = { t[0], t[1], t[2] };
    internal::append_PLY_segmentation_face(text, 3, indices, static_cast<long long>(std::size_t(r.patches[i])));
  });
  Refined_segmentation_sizes sizes;
  sizes.number_of_vertices = r.points.size();
  sizes.number_of_faces = r.triangles.size();
  sizes.number_of_split_faces = r.split_faces;
  return sizes;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_IO_WRITE_REFINED_SEGMENTATION_H
