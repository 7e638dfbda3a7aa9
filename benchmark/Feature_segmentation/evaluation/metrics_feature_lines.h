// SPDX-License-Identifier: GPL-3.0-or-later
// The measures of metrics.h against the input feature lines, with no ground truth (part
// of the benchmarks, not of the installed package): how much strong feature-line length
// a patch boundary follows (coverage) and how much boundary runs away from every feature
// line (redundancy), on a face labelling or directly on boundary curves
// (`Patch_boundaries`, smoothed or not). Included by metrics.h.

#ifndef CGAL_FEATURE_SEGMENTATION_EVALUATION_FEATURE_LINES_H
#define CGAL_FEATURE_SEGMENTATION_EVALUATION_FEATURE_LINES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include "metrics_impl.h"

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationEvaluation
/// The default strength above which a feature line counts as strong in
/// `compare_with_feature_lines()`: lines of strength at least 10 (the integral of
/// |curvature| along the line, see `Feature_line::strength`) are the clear creases and
/// crest lines; the default pruning threshold `default_strength_threshold` keeps weaker ones.
constexpr double default_strong_feature_strength = 10.0;

/// \ingroup PkgFeatureSegmentationEvaluation
/// How the patch boundaries of a segmentation follow the feature lines it was meant to
/// follow, without a ground truth. Lengths are in the mesh's units.
struct Feature_line_scores
{
  double coverage = 1.;            ///< share of the strong feature-line length within the tolerance of a patch boundary (1 if no line is strong)
  double strong_length = 0.;       ///< total length of the strong feature lines
  double redundant_length = 0.;    ///< boundary length farther than the tolerance from every feature line
  double boundary_length = 0.;     ///< total length of the patch boundaries
  /// `redundant_length / boundary_length`, 0 without boundary.
  double redundancy_fraction() const { return boundary_length > 0 ? redundant_length / boundary_length : 0.; }
};

namespace internal {

// Coverage and redundancy of the segments `boundary` against `lines`: the body of both
// overloads of compare_with_feature_lines().
template <typename TriangleMesh, typename VertexPointMap>
Feature_line_scores compare_segments_with_feature_lines(const std::vector<Evaluation_segment>& boundary,
                                                        const TriangleMesh& tm, VertexPointMap vpm,
                                                        const Feature_lines<TriangleMesh>& lines, double tolerance,
                                                        double strong_strength)
{
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw Invalid_input("the boundary tolerance must be a finite number >= 0 (got " + std::to_string(tolerance) + ")");
  std::vector<Evaluation_segment> all, strong;
  for(const auto& l : lines.lines)
  {
    const std::size_t n = l.points.size();
    const std::size_t m = l.is_closed ? n : (n > 0 ? n - 1 : 0);
    for(std::size_t i = 0; i < m; ++i)
    {
      const Evaluation_segment s(to_evaluation_point(l.points[i].point(tm, vpm)),
                                 to_evaluation_point(l.points[(i + 1) % n].point(tm, vpm)));
      all.push_back(s);
      if(l.strength >= strong_strength) strong.push_back(s);
    }
  }
  const Segment_distance to_boundary(boundary), to_lines(all);
  Feature_line_scores s;
  s.strong_length = total_length(strong);
  s.boundary_length = total_length(boundary);
  if(s.strong_length > 0) s.coverage = matched_length(strong, to_boundary, tolerance) / s.strong_length;
  s.redundant_length = s.boundary_length - matched_length(boundary, to_lines, tolerance);
  return s;
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationEvaluation
/// Scores the patch boundaries of `face_patch` against feature lines (for example those
/// of `detect_crest_lines()`). Coverage: every segment of a strong line (strength at
/// least `strong_strength`) is covered when its midpoint lies within `tolerance` of a
/// patch-boundary edge; coverage is the covered share of the strong length. Redundancy:
/// the length of the patch-boundary edges whose midpoint is farther than `tolerance` from
/// every segment of every line in `lines` (weak ones included: a boundary along a weak
/// line is not invented), that is, boundary that no feature supports.
///
/// \tparam FacePatchMap a `ReadablePropertyMap` from `face_descriptor` to an integer type
/// \param tm the mesh (a model of `FaceListGraph`)
/// \param face_patch the patch of every face
/// \param lines the feature lines of `tm`
/// \param tolerance the distance tolerance, for example `default_boundary_tolerance(tm)`
/// \param strong_strength the strength from which a line is strong
/// \param np optional named parameters: `vertex_point_map`
/// \throws Invalid_input if `tolerance` is negative or not finite
template <typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Feature_line_scores compare_with_feature_lines(const TriangleMesh& tm, FacePatchMap face_patch,
                                               const Feature_lines<TriangleMesh>& lines, double tolerance,
                                               double strong_strength = default_strong_feature_strength,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  return internal::compare_segments_with_feature_lines(internal::patch_boundary_segments(tm, face_patch, vpm), tm,
                                                       vpm, lines, tolerance, strong_strength);
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// Scores boundary curves on the surface (from `compute_patch_boundaries()`, typically
/// after `smooth_patch_boundaries()`) against feature lines, as the face-labelling
/// overload does but on the curves' own segments (from a point inside a triangle to a
/// point on an edge, and back): coverage is the share of the strong lines' length whose
/// segments have their midpoint within `tolerance` of a curve segment, redundancy the
/// length of the curve segments whose midpoint is farther than `tolerance` from every line.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \param boundaries the curves, on the mesh `boundaries.mesh()`
/// \param lines the feature lines of that mesh
/// \param tolerance the distance tolerance, for example `default_boundary_tolerance(boundaries.mesh())`
/// \param strong_strength the strength from which a line is strong
/// \param np optional named parameters: `vertex_point_map` (where the lines' points are;
///        it should be the one the curves were computed with)
/// \throws Invalid_input if `tolerance` is negative or not finite
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Feature_line_scores compare_with_feature_lines(const Patch_boundaries<TriangleMesh>& boundaries,
                                               const Feature_lines<TriangleMesh>& lines, double tolerance,
                                               double strong_strength = default_strong_feature_strength,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const TriangleMesh& tm = boundaries.mesh();
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  return internal::compare_segments_with_feature_lines(internal::boundary_curve_segments(boundaries), tm, vpm, lines,
                                                       tolerance, strong_strength);
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_EVALUATION_FEATURE_LINES_H
