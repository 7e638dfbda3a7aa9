// SPDX-License-Identifier: GPL-3.0-or-later
// The defaults of the segmentation's named parameters that programs, bindings and
// examples show to users; the curvature fit's and the crest lines' own defaults are
// default_neighborhood_radius (principal_curvatures.h) and default_strength_threshold
// (crest_lines.h).

#ifndef CGAL_FEATURE_SEGMENTATION_DEFAULTS_H
#define CGAL_FEATURE_SEGMENTATION_DEFAULTS_H

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default of the named parameter `alpha`: how strongly feature edges cut (the
/// paper's default). Larger values give more patches.
constexpr double default_alpha = 0.6;

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default of the named parameter `gamma`: the anisotropy of the curvature metric,
/// whose eigenvalues are 1 and 1/(1 + gamma s)^2 with s = |k1| - |k2| (the paper's 0.05).
constexpr double default_gamma = 0.05;

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default of the named parameter `crease_angle` (degrees): edges whose faces bend
/// by this much or more are creases. On the CAD parts of the evaluation no edge bends by
/// 15 to 30 degrees apart from the creases; 180 turns the creases off (the paper's
/// pipeline, crest lines only).
constexpr double default_crease_angle = 20.;

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default of the named parameter `crease_filter_iterations`: rounds of bilateral
/// filtering of the face normals before the creases of a rough (noisy) mesh are found:
/// the most a noisy mesh gets, from 5 rounds on light noise to all of them on heavy noise;
/// a clean tessellation is not filtered.
constexpr int default_crease_filter_iterations = 40;

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default of the named parameter `tangent_discontinuities`: on a clean tessellation
/// of a CAD part, the curvature discontinuities (a fillet meeting a plane or a wider
/// curved face without a crease) join the creases, and seam lines (two curved faces
/// meeting where the smaller principal curvature steps) join the crest lines; on a noisy
/// mesh, or a rough one whose planes hold a fifth of its area, the borders of its planes
/// join the creases, and so do the seams between the straight pieces and arcs of its
/// bent pipes; on every rough mesh (noisy or smooth) so do the seams between the pieces
/// (cylinders, cones, planes, tori, spheres) of its surfaces of revolution, and the
/// creases that noise leaves inside one piece go.
constexpr bool default_tangent_discontinuities = true;

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default of the named parameter `crest_lines_on_clean_tessellations`: the crest
/// lines of a tessellation of a CAD part (a clean one, a noisy one, or one that its
/// creases cut into pieces) weigh less than its creases (their `alpha_e` is alpha
/// minus 0.5) unless it is true.
constexpr bool default_crest_lines_on_clean_tessellations = false;

/// \ingroup PkgFeatureSegmentationSegmentation
/// The default `alpha_e` of the edges a sketch crosses
/// (`Feature_aligned_segmentation::add_sketch()`); a sketch's alpha must exceed 1.
constexpr double default_sketch_alpha = 2.;

} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_DEFAULTS_H
