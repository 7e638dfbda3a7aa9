// SPDX-License-Identifier: GPL-3.0-or-later
// The choice of distance for the watershed oversegmentation (paper, Section 3.3), a
// named-parameter value shared by the free function and the editing class.

#ifndef CGAL_FEATURE_SEGMENTATION_WATERSHED_DISTANCE_H
#define CGAL_FEATURE_SEGMENTATION_WATERSHED_DISTANCE_H

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationSegmentation
/// The distance whose watershed makes the oversegmentation (paper, Section 3.3).
enum class Watershed_distance
{
  ANISOTROPIC, ///< dual edges of length Similarity(e): the paper's choice, the default
  GEODESIC     ///< dual edges of Euclidean length Award(e), as Mitani-Suzuki and Levy et al.
};

} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_WATERSHED_DISTANCE_H
