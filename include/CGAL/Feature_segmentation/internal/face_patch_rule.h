// SPDX-License-Identifier: GPL-3.0-or-later
// From vertex patches to face patches: the rule shared by the free function, the editing
// class and the program (majority of the three vertices, else the smallest id).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_PATCH_RULE_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_PATCH_RULE_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The patch of a face from its vertices' patches: the majority; when the three differ,
// the smallest id.
inline std::size_t face_patch_from_vertices(std::size_t a, std::size_t b, std::size_t c)
{
  if(a == b || a == c) return a;
  if(b == c) return b;
  return (std::min)(a, (std::min)(b, c));
}

template <typename TriangleMesh, typename FacePatchMap>
void write_face_patches(const Mesh_indexing<TriangleMesh>& idx, const std::vector<std::size_t>& labels,
                        FacePatchMap face_patch)
{
  const TriangleMesh& tm = idx.mesh();
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    auto h = halfedge(idx.face_at(f), tm);
    put(face_patch, idx.face_at(f),
        static_cast<Id>(face_patch_from_vertices(labels[idx.id(source(h, tm))], labels[idx.id(target(h, tm))],
                                                 labels[idx.id(target(next(h, tm), tm))])));
  }
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_PATCH_RULE_H
