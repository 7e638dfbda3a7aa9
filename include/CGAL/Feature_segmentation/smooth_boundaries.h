// SPDX-License-Identifier: GPL-3.0-or-later
// Smoothing of the patch boundaries (paper, Section 3.1, third step, Fig. 3(d)): the
// boundary curves are shortened in the anisotropic metric of the edge weights, so that
// they stay on the features and become straight away from them, in the spirit of the
// iterative energy minimisation of Nieser, Schulz and Polthier (2010).

#ifndef CGAL_FEATURE_SEGMENTATION_SMOOTH_BOUNDARIES_H
#define CGAL_FEATURE_SEGMENTATION_SMOOTH_BOUNDARIES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/internal/boundary_smoothing_impl.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationBoundaries
/// The default number of iterations of `smooth_patch_boundaries()`.
constexpr int default_smoothing_iterations = 20;

/// \ingroup PkgFeatureSegmentationBoundaries
/// What `smooth_patch_boundaries()` did.
struct Boundary_smoothing_report
{
  /// The total length of the boundaries in the anisotropic metric (the energy): before
  /// the smoothing (index 0), then after every iteration. Never increasing.
  std::vector<double> energy;
  /// The total Euclidean length of the boundaries, at the same times as `energy`.
  std::vector<double> length;
  /// The number of iterations run.
  std::size_t number_of_iterations = 0;
  /// The number of vertex moves (a vertex changing patch) that were kept.
  std::size_t number_of_vertex_moves = 0;
  /// Whether the iterations stopped on the tolerance (rather than on their number).
  bool converged = false;
};

/// \ingroup PkgFeatureSegmentationBoundaries
/// Smooths patch boundaries: lowers their total length in the anisotropic metric of the
/// edge weights, in which a curve along a salient feature is short, so that the curves
/// settle on the features and become straight (geodesic) in featureless regions.
///
/// The energy is the length of the boundary in every triangle, measured in that
/// triangle's metric (Eq. 4 and 6), summed. An iteration visits, in a fixed order:
/// - every triangle's point: on a triangle the boundary passes through, the midpoint of
///   its two edge points, where the boundary inside it is straight; at a junction, the
///   Fermat-Weber point of its three edge points in the triangle's metric (Weiszfeld's
///   iteration), at least 1/1000 (in barycentric coordinates) inside the triangle;
/// - every cut edge's point: it slides along its edge, at least 1/1000 of the edge's
///   length from the ends, to the minimum of the boundary's length in the edge's two
///   triangles (one for a border edge: a curve's end on the border slides along the
///   border edge), by golden-section search; this energy is convex along the edge;
/// - every vertex that had a cut edge in the input: it moves to the other patch when
///   this lowers the length of the boundary around it (the boundary then passes on the
///   other side of it), provided its ring holds exactly two patches, each as one
///   contiguous run.
///
/// After the points' visits, the displacement of the whole iteration is extrapolated
/// (factors 2, 4, ..., 64) and the best extrapolation kept if it lowers the energy: a
/// boundary shifting sideways as a whole gains little per point, and would otherwise
/// take many iterations.
///
/// Every change is kept only if it lowers the length of the pieces of boundary it
/// touches (Gauss-Seidel with an acceptance test), so the energy never rises. The vertex
/// move rule guarantees that no patch, junction, curve or adjacency between patches
/// appears or disappears, and curves never cross themselves or each other (they remain
/// the dual of a vertex labelling, with points strictly inside edges and triangles).
/// Boundaries move by at most about one ring of triangles from the input ones, so small
/// closed curves do not shrink away.
///
/// Compared with Nieser, Schulz and Polthier, "Patch layout from feature graphs"
/// (Computer-Aided Design 42(3), 2010), which relaxes the boundary polylines by moving
/// each node along the surface to shorten its segments in a metric, and with the paper's
/// authors' tool (three Jacobi iterations of a gradient step and a projection onto the
/// triangles around the node's face, nodes at the dual vertices, curve ends of valence
/// one fixed), this implementation: keeps an explicit point on every crossed edge so that
/// curves are exact polylines on the surface; minimises exactly per point (a convex
/// problem per point) instead of a gradient step, and accepts a change only when the
/// energy drops, which makes the energy monotone; lets junctions move to their
/// Fermat-Weber point and border ends slide along the border; and changes the patch of a
/// vertex (which is how a boundary crosses a vertex) only under the topological test above.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \param boundaries the boundaries, from `compute_patch_boundaries()`; changed in place
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{smoothing_iterations}
///     \cgalParamDescription{the largest number of iterations}
///     \cgalParamType{an integer type, at least 0}
///     \cgalParamDefault{`default_smoothing_iterations` (20)}
///     \cgalParamExtra{The authors' tool runs 3 Jacobi iterations; Gauss-Seidel with extrapolation converges
///                     much faster per iteration, but a boundary that has to shift sideways as a whole, e.g.
///                     onto a crease a triangle away, takes about 20. A negative value throws
///                     `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{smoothing_tolerance}
///     \cgalParamDescription{stop when an iteration lowers the energy by at most this fraction of it; 0 runs
///                           all the iterations unless the energy stops changing}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`1e-4`}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return the energy and length after every iteration
///
/// \throws Invalid_input if `smoothing_iterations` is negative or
///         `smoothing_tolerance` is negative or not finite
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_smoothing_report smooth_patch_boundaries(Patch_boundaries<TriangleMesh>& boundaries,
                                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto iterations =
    choose_parameter(get_parameter(np, internal_np::smoothing_iterations), default_smoothing_iterations);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::smoothing_tolerance), 1e-4);
  bool negative = false;
  if constexpr(std::is_signed<std::decay_t<decltype(iterations)> >::value) negative = iterations < 0;
  if(negative)
    throw Invalid_input("smoothing_iterations must be >= 0 (got " + std::to_string(iterations) + ")");
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw Invalid_input("smoothing_tolerance must be a finite number >= 0 (got " + std::to_string(tolerance) + ")");

  internal::Boundary_smoother<TriangleMesh> smoother(boundaries.state());
  const internal::Boundary_smoothing_result r = smoother.run(static_cast<std::size_t>(iterations), tolerance);
  boundaries.update();
  Boundary_smoothing_report report;
  report.energy = r.energy;
  report.length = r.length;
  report.number_of_iterations = r.iterations;
  report.number_of_vertex_moves = r.vertex_moves;
  report.converged = r.converged;
  return report;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_SMOOTH_BOUNDARIES_H
