// SPDX-License-Identifier: GPL-3.0-or-later
// Pieces of one or two faces that the creases would cut out. On a coarse CAD
// tessellation (a small hole of a few segments, the fan of triangles where a fillet ends
// in a corner, the quads of a narrow fillet that turns by more than the crease angle
// from one quad to the next) a triangle or a quad can bend by more than the crease angle
// from every neighbour; cut along these creases it would be a patch of its own, which no
// B-rep face of the development data is (none of the 30 parts' ground-truth patches has
// fewer than three triangles, while the creases of ABC 00000026 cut out 249 quads of a
// narrow fillet). So few faces are no evidence of a surface of their own: they stay
// with the neighbour they bend least from, unless they are a quad bent strongly from
// every neighbour (a box's side). On a rough mesh (not a clean tessellation: noisy, or
// a smooth model), pieces of up to ten faces are cut out by noise far more often than
// by the part, and join whatever their bend.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_ISOLATED_CREASE_FACES_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_ISOLATED_CREASE_FACES_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/face_components.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The most faces of a piece that the creases would cut out and that is still joined to a
// neighbour (join_isolated_crease_faces): a quad's two triangles; a piece of more than
// one face is joined only across a crease of less than crease_piece_max_angle degrees
// (the quads of a hole of 8 segments bend by 45 degrees from each other, the sides of a
// hexagonal nut by 60 and those of a box by 90).
constexpr std::size_t crease_piece_max_faces = 2;
constexpr double crease_piece_max_angle = 60.;

// The same on a rough mesh (not a clean tessellation), where most small pieces are cut
// out by noise that survived the normal filter: pieces of up to 15 faces join their
// flattest neighbour whatever the angle (called with max_angle 180). On the 30
// development parts with noise along the normals of 0.1% and 0.3% of the diagonal
// pieces of up to 10 faces already remove two thirds of the surplus patches (a 60-degree
// bound: half the gain in F). Chosen over three noise realisations
// (evaluate_quality --noise-seeds 3): 12, 15 and 20 faces give the same means at 0.3%
// (0.915 against 0.904 with 10: a piece of 11 faces on the single-face torus ABC
// 00006566), 15 lies in the middle of that range, 20 loses a little at 0.1%.
constexpr std::size_t crease_noisy_piece_max_faces = 15;

// Joins the pieces that the creases (nonzero in `is_crease`) would cut out of the mesh of
// `idx` with at most `max_faces` faces to a neighbour: a piece is a set of faces connected
// through edges that are no crease; for each piece of at most `max_faces` faces that has
// a crease on its boundary (of less than `max_angle` degrees for a piece of more than
// one face), the crease flag of its boundary crease of smallest dihedral angle
// `angle` is cleared (the first in face order on a tie), and this is repeated on the
// larger pieces so made until none is left to join.
// Pieces are visited in the order of their first face, so the result does not depend on
// anything but the indexing. Returns the number of edges cleared.
template <typename TriangleMesh>
std::size_t join_isolated_crease_faces(const Mesh_indexing<TriangleMesh>& idx, const std::vector<double>& angle,
                                       std::vector<char>& is_crease,
                                       std::size_t max_faces = crease_piece_max_faces,
                                       double max_angle = crease_piece_max_angle)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces();
  std::size_t cleared = 0;
  std::vector<std::size_t> piece, size, weakest;
  for(bool changed = true; changed;)
  {
    changed = false;
    // the pieces, each named by its first face
    piece = face_components(idx, [&](std::size_t e) { return !is_crease[e]; });
    size.assign(nf, 0);
    for(std::size_t f = 0; f < nf; ++f) ++size[piece[f]];
    // the weakest boundary crease of every small piece
    weakest.assign(size.size(), idx.npos);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t id = piece[f];
      if(size[id] > max_faces) continue;
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
      {
        const std::size_t e = idx.edge_id(h);
        if(!is_crease[e] || idx.face_id(opposite(h, tm)) == idx.npos) continue;
        if(weakest[id] == idx.npos || angle[e] < angle[weakest[id]]) weakest[id] = e;
      }
    }
    for(std::size_t id = 0; id < size.size(); ++id)
      if(size[id] > 1 && weakest[id] != idx.npos && angle[weakest[id]] >= max_angle)
        weakest[id] = idx.npos;
    for(std::size_t id = 0; id < size.size(); ++id)
      if(weakest[id] != idx.npos && is_crease[weakest[id]])
      {
        is_crease[weakest[id]] = 0;
        ++cleared;
        changed = true;
      }
  }
  return cleared;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_ISOLATED_CREASE_FACES_H
