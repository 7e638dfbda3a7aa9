// SPDX-License-Identifier: GPL-3.0-or-later
// The connected sets of faces that chosen interior edges join (union-find), shared by the
// flat regions of the curvature discontinuities and the pieces of the CAD-tessellation
// test.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_COMPONENTS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_COMPONENTS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>

#include <cstddef>
#include <numeric>
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
  const std::size_t nf = idx.number_of_faces();
  std::vector<std::size_t> parent(nf);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; }
    return x;
  };
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, tm));
    if(f == idx.npos || g == idx.npos || !join(e)) continue;
    const std::size_t a = find(f), b = find(g);
    if(a < b) parent[b] = a; else if(b < a) parent[a] = b;
  }
  for(std::size_t f = 0; f < nf; ++f) parent[f] = find(f);
  return parent;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_COMPONENTS_H
