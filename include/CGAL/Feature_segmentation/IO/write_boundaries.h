// SPDX-License-Identifier: GPL-3.0-or-later
// Writer for patch boundaries (boundary_curves.h): CGAL's polylines text format, the
// format of the feature lines' writer, so that the same viewers and readers take both.
// Points are written at full double precision.

#ifndef CGAL_FEATURE_SEGMENTATION_IO_WRITE_BOUNDARIES_H
#define CGAL_FEATURE_SEGMENTATION_IO_WRITE_BOUNDARIES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/IO/write_feature_lines.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>

#include <array>
#include <ostream>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

inline void write_coordinates(std::ostream& os, const std::array<double, 3>& p)
{
  write_double(os, p[0]);
  os.put(' ');
  write_double(os, p[1]);
  os.put(' ');
  write_double(os, p[2]);
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationIO
/// Writes the curves of `boundaries` in CGAL's polylines format: one line of text per
/// curve, `n x1 y1 z1 ... xn yn zn`, in the order of `boundaries.curves()`; a closed
/// curve repeats its first point at the end (so `n` is one more than its number of
/// points), as `write_polylines()` does for closed feature lines. Coordinates at full
/// double precision.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \param os the output stream
/// \param boundaries the boundaries, from `compute_patch_boundaries()` (smoothed or not)
/// \return `true` if the stream is still good after writing
template <typename TriangleMesh>
bool write_boundary_polylines(std::ostream& os, const Patch_boundaries<TriangleMesh>& boundaries)
{
  for(const Boundary_curve<TriangleMesh>& curve : boundaries.curves())
  {
    const bool repeat_first = curve.is_closed() && !curve.points.empty();
    os << curve.points.size() + (repeat_first ? 1 : 0);
    for(const Boundary_point<TriangleMesh>& p : curve.points)
    {
      os << ' ';
      internal::write_coordinates(os, p.point);
    }
    if(repeat_first)
    {
      os << ' ';
      internal::write_coordinates(os, curve.points.front().point);
    }
    os << '\n';
  }
  return os.good();
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_IO_WRITE_BOUNDARIES_H
