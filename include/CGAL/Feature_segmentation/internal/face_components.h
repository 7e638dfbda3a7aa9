// SPDX-License-Identifier: GPL-3.0-or-later
// The connected sets of faces that chosen interior edges join (union-find), shared by the
// flat regions of the curvature discontinuities and the pieces of the CAD-tessellation
// test.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_COMPONENTS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_COMPONENTS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/union_find.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// Per face of the mesh of `idx`, the smallest face index of its component: faces are
// joined across the interior edges e with `join(e)`.
template <typename TriangleMesh, typename Join>
std::vector<std::size_t> face_components(const Mesh_indexing<TriangleMesh>& idx, Join join)
{
  const TriangleMesh& tm = idx.mesh();
  Smallest_root_union_find sets(idx.number_of_faces());
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, tm));
    if(f == idx.npos || g == idx.npos || !join(e)) continue;
    sets.unite(f, g);
  }
  return sets.roots();
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_COMPONENTS_H
