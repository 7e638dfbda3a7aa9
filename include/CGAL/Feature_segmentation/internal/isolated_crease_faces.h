// SPDX-License-Identifier: GPL-3.0-or-later
// Faces that the creases would cut out alone. On a coarse CAD tessellation (a small hole
// of a few segments, the fan of triangles where a fillet ends in a corner) a triangle can
// bend by more than the crease angle from each of its three neighbours (or, at a border,
// from each neighbour it has); cut along them it would be a patch of one face, which no
// B-rep face of the development data is (none of the 30 parts' ground-truth patches is a
// single triangle). One face is no
// evidence of a surface of its own: it stays with the neighbour it bends least from.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_ISOLATED_CREASE_FACES_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_ISOLATED_CREASE_FACES_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>

#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// Clears, for every face of the mesh of `idx` whose edges are all creases (nonzero in
// `is_crease`) or border edges, at least one a crease, the crease flag of its crease edge
// of smallest dihedral angle `angle` (the first such edge around the face on a tie).
// Faces are visited in index order, and a cleared edge no longer isolates the face
// across it, so the result does not depend on anything but the indexing. Returns the
// number of edges cleared.
template <typename TriangleMesh>
std::size_t join_isolated_crease_faces(const Mesh_indexing<TriangleMesh>& idx, const std::vector<double>& angle,
                                       std::vector<char>& is_crease)
{
  const TriangleMesh& tm = idx.mesh();
  std::size_t cleared = 0;
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    std::size_t creases = 0, interior = 0, weakest = idx.npos;
    for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
    {
      if(is_border(opposite(h, tm), tm)) continue; // a border edge bounds the face too
      ++interior;
      const std::size_t e = idx.edge_id(h);
      if(!is_crease[e]) continue;
      ++creases;
      if(weakest == idx.npos || angle[e] < angle[weakest]) weakest = e;
    }
    if(creases > 0 && creases == interior)
    {
      is_crease[weakest] = 0;
      ++cleared;
    }
  }
  return cleared;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_ISOLATED_CREASE_FACES_H
