// SPDX-License-Identifier: GPL-3.0-or-later
// From vertex patches to face patches: the one rule of the package. A face takes the
// patch that covers most of its area under the boundaries: those of the labelling as
// computed (the class's patch(face) and face_patches(map), segment_along_features()'s
// face_patch_map) or smoothed (majority_face_patches(), the class's
// face_patches(boundaries, map)).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_PATCH_RULE_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_PATCH_RULE_H

#include <CGAL/assertions.h>

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The patch covering most of a triangle's area; ties go to the smallest id.
// `label[k]`, `corner[k]`: the patch and position of corner k; edge k joins corners k and
// k+1 (mod 3) and is cut when their patches differ; `edge_point[k]`: the boundary's
// point on edge k if it is cut; `x`: the boundary's point inside the face (if any edge
// is cut).
//
// A corner whose two edges are cut owns the quadrilateral (corner, point on its next
// edge, the face's point, point on its previous edge); the face's point lies inside the
// corner's angle, so the fan from the corner covers it. A corner with one cut edge shares
// the rest of the triangle with the other such corner (same patch).
inline std::size_t area_majority_patch(const std::array<std::size_t, 3>& label,
                                       const std::array<Eigen::Vector3d, 3>& corner,
                                       const std::array<Eigen::Vector3d, 3>& edge_point, const Eigen::Vector3d& x)
{
  typedef Eigen::Vector3d Vec3;
  if(label[0] == label[1] && label[1] == label[2]) return label[0];
  auto area = [](const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); };
  auto cut = [&](int k) { return label[k] != label[(k + 1) % 3]; };
  double rest = area(corner[0], corner[1], corner[2]);
  std::array<std::pair<std::size_t, double>, 3> owned;
  std::size_t rest_patch = label[0];
  int n = 0;
  for(int k = 0; k < 3; ++k)
  {
    const int next_edge = k, prev_edge = (k + 2) % 3;
    if(cut(next_edge) && cut(prev_edge))
    {
      const double a = area(corner[k], edge_point[next_edge], x) + area(corner[k], x, edge_point[prev_edge]);
      owned[n++] = { label[k], a };
      rest -= a;
    }
    else
      rest_patch = label[k];
  }
  CGAL_assertion(n == 1 || n == 3); // a through triangle has one such corner, a junction three
  if(n == 1) owned[n++] = { rest_patch, rest };
  std::size_t best = owned[0].first;
  double best_area = owned[0].second;
  for(int i = 1; i < n; ++i)
    if(owned[i].second > best_area || (owned[i].second == best_area && owned[i].first < best))
    {
      best = owned[i].first;
      best_area = owned[i].second;
    }
  return best;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_FACE_PATCH_RULE_H
