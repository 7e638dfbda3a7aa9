// SPDX-License-Identifier: GPL-3.0-or-later
// Quality measures of a mesh segmentation, for the benchmarks and their tests (part of
// the benchmarks, not of the installed package): the cut
// cost of Eq. 1 and the patch count; against a ground-truth face labelling, boundary
// precision, recall and F-score within a distance tolerance, the Rand index and the
// over- and under-segmentation counts; against the input feature lines, with no ground
// truth, how much strong feature-line length a patch boundary follows (coverage) and how
// much boundary runs away from every feature line (redundancy).
//
// What each measure is computed on:
// - cut cost: a vertex labelling and the edge weights (the objective of the solver);
// - boundary precision/recall/F-score, Rand index, over/under-segmentation, coverage and
//   redundancy: a face labelling, so that segmentations from any method (this
//   package's, CGAL's sharp-edge segmentation, variational shape approximation) are
//   scored the same way; the boundary is then the chain of mesh edges between faces of
//   different patches. For this package, the face labelling is either the vertex
//   majority of `segment_along_features()`'s `face_patch_map`, or, after
//   `smooth_patch_boundaries()`, the majority-area patches of `majority_face_patches()`;
// - boundary precision/recall/F-score, coverage and redundancy also directly on boundary
//   curves (`Patch_boundaries`, smoothed or not): the curves' own segments, which cross
//   the triangles, are scored against the reference's edge chains or the feature lines;
//   this is what a user of the smoothed boundaries gets, without the staircase of a face
//   labelling.
//
// The measures against the feature lines (coverage, redundancy) are in
// metrics_feature_lines.h, included here.

#ifndef CGAL_FEATURE_SEGMENTATION_EVALUATION_H
#define CGAL_FEATURE_SEGMENTATION_EVALUATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include "metrics_impl.h"
#include "metrics_feature_lines.h"

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationEvaluation
/// The default distance tolerance of the boundary measures, as a fraction of the
/// diagonal of the mesh's bounding box (1%).
constexpr double default_relative_boundary_tolerance = 0.01;

/// \ingroup PkgFeatureSegmentationEvaluation
/// The default significance of `compare_partitions()`: a patch counts as a piece of a
/// reference patch when it holds at least 10% of that reference patch's area.
constexpr double default_significant_overlap = 0.1;

/// \ingroup PkgFeatureSegmentationEvaluation
/// The length of the diagonal of the bounding box of `tm`'s vertices.
/// \param tm the mesh (a model of `VertexListGraph`)
/// \param np optional named parameters: `vertex_point_map`
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
double bounding_box_diagonal(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool first = true;
  for(auto v : vertices(tm))
  {
    const internal::Evaluation_point p = internal::to_evaluation_point(get(vpm, v));
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = first ? p[i] : (std::min)(lo[i], p[i]);
      hi[i] = first ? p[i] : (std::max)(hi[i], p[i]);
    }
    first = false;
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// The default boundary tolerance of `tm`: `default_relative_boundary_tolerance` times
/// `bounding_box_diagonal()`.
/// \param tm the mesh
/// \param np optional named parameters: `vertex_point_map`
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
double default_boundary_tolerance(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  return default_relative_boundary_tolerance * bounding_box_diagonal(tm, np);
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// The number of distinct patch ids among the faces of `tm`.
/// \tparam FacePatchMap a `ReadablePropertyMap` from `face_descriptor` to an integer type
/// \param tm the mesh (a model of `FaceListGraph`)
/// \param face_patch the patch of every face
template <typename TriangleMesh, typename FacePatchMap>
std::size_t number_of_patches(const TriangleMesh& tm, FacePatchMap face_patch)
{
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  std::unordered_set<Id> ids;
  for(auto f : faces(tm)) ids.insert(get(face_patch, f));
  return ids.size();
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// The cut cost of a vertex labelling (paper, Eq. 1): the sum of the weights of the edges
/// whose two vertices have different patches. With the weights of
/// `compute_edge_weights()`, lower is better; it is the quantity the correlation
/// clustering minimises.
/// \tparam VertexPatchMap a `ReadablePropertyMap` from `vertex_descriptor` to an integer type
/// \tparam EdgeWeightMap a `ReadablePropertyMap` from `edge_descriptor` to a floating-point type
/// \param tm the mesh (a model of `EdgeListGraph`)
/// \param vertex_patch the patch of every vertex
/// \param weight the weight `w(e)` of every edge
template <typename TriangleMesh, typename VertexPatchMap, typename EdgeWeightMap>
double cut_cost(const TriangleMesh& tm, VertexPatchMap vertex_patch, EdgeWeightMap weight)
{
  double cost = 0;
  for(auto e : edges(tm))
  {
    auto h = halfedge(e, tm);
    if(get(vertex_patch, source(h, tm)) != get(vertex_patch, target(h, tm)))
      cost += CGAL::to_double(get(weight, e));
  }
  return cost;
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// Derives a vertex labelling from a face labelling, so that `cut_cost()` can score
/// methods that label faces: every vertex takes the patch held by most of its incident
/// faces, the smallest id on a tie. An isolated vertex gets `isolated_id`.
/// \tparam FacePatchMap a `ReadablePropertyMap` from `face_descriptor` to an integer type
/// \tparam VertexPatchMap a `WritablePropertyMap` from `vertex_descriptor` to the same type
/// \param tm the mesh (a model of `FaceListGraph`)
/// \param face_patch the patch of every face
/// \param vertex_patch the output
/// \param isolated_id the patch of a vertex without incident face
template <typename TriangleMesh, typename FacePatchMap, typename VertexPatchMap>
void vertex_patches_from_face_patches(const TriangleMesh& tm, FacePatchMap face_patch, VertexPatchMap vertex_patch,
                                      typename boost::property_traits<FacePatchMap>::value_type isolated_id = 0)
{
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  std::map<Id, std::size_t> count;
  for(auto v : vertices(tm))
  {
    count.clear();
    for(auto f : faces_around_target(halfedge(v, tm), tm))
      if(f != boost::graph_traits<TriangleMesh>::null_face()) ++count[get(face_patch, f)];
    Id best = isolated_id;
    std::size_t best_count = 0;
    for(const auto& c : count) // ascending ids: the first maximum is the smallest id
      if(c.second > best_count) { best = c.first; best_count = c.second; }
    put(vertex_patch, v, best);
  }
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// Boundary precision and recall of a segmentation against a reference. Lengths are in
/// the mesh's units.
struct Boundary_scores
{
  double precision = 1.;        ///< share of the boundary length within the tolerance of the reference boundary (1 if there is no boundary)
  double recall = 1.;           ///< share of the reference boundary length within the tolerance of the boundary (1 if the reference has none)
  double f_score = 1.;          ///< harmonic mean of precision and recall (0 if both are 0)
  double boundary_length = 0.;  ///< total length of the segmentation's boundary
  double reference_length = 0.; ///< total length of the reference boundary
};

namespace internal {

// Precision and recall of the segments `mine` against the segments `theirs`: the body of
// both overloads of compare_boundaries().
inline Boundary_scores compare_boundary_segments(const std::vector<Evaluation_segment>& mine,
                                                 const std::vector<Evaluation_segment>& theirs, double tolerance)
{
  const Segment_distance to_mine(mine), to_theirs(theirs);
  Boundary_scores s;
  s.boundary_length = total_length(mine);
  s.reference_length = total_length(theirs);
  if(s.boundary_length > 0) s.precision = matched_length(mine, to_theirs, tolerance) / s.boundary_length;
  if(s.reference_length > 0) s.recall = matched_length(theirs, to_mine, tolerance) / s.reference_length;
  s.f_score = (s.precision + s.recall > 0) ? 2 * s.precision * s.recall / (s.precision + s.recall) : 0.;
  return s;
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationEvaluation
/// Scores the patch boundaries of `face_patch` against those of `reference_face_patch`
/// on the same mesh. A patch boundary is the set of edges whose two faces have different
/// patches (border edges are not boundaries). A boundary edge is matched when its
/// midpoint lies within `tolerance` of an edge of the other boundary; precision is the
/// matched share of the segmentation's boundary length, recall the matched share of the
/// reference boundary length (edges weighted by their length, so that the scores do not
/// depend on the mesh's resolution).
///
/// \tparam FacePatchMap, ReferenceFacePatchMap `ReadablePropertyMap`s from
///         `face_descriptor` to integer types
/// \param tm the mesh (a model of `FaceListGraph`)
/// \param face_patch the patch of every face: the segmentation scored
/// \param reference_face_patch the patch of every face in the reference (the ground truth)
/// \param tolerance the distance tolerance, in the mesh's units, for example
///        `default_boundary_tolerance(tm)` (1% of the bounding-box diagonal)
/// \param np optional named parameters: `vertex_point_map`
/// \throws Invalid_input if `tolerance` is negative or not finite
template <typename TriangleMesh, typename FacePatchMap, typename ReferenceFacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_scores compare_boundaries(const TriangleMesh& tm, FacePatchMap face_patch,
                                   ReferenceFacePatchMap reference_face_patch, double tolerance,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw Invalid_input("the boundary tolerance must be a finite number >= 0 (got " + std::to_string(tolerance) + ")");
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  return internal::compare_boundary_segments(internal::patch_boundary_segments(tm, face_patch, vpm),
                                             internal::patch_boundary_segments(tm, reference_face_patch, vpm),
                                             tolerance);
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// The share of the area of `tm` that lies within `tolerance` of the patch boundary of
/// `reference_face_patch` (a face counts, with its whole area, when its centroid does):
/// about the boundary precision that a boundary drawn anywhere on the surface gets by
/// chance. Where it is close to 1, as on a part whose faces are all narrower than twice
/// the tolerance, precision tells little, and a segmentation cut into many small patches
/// (high recall) gets a high F-score; the patch count and the number of small patches
/// tell it apart. 0 if the reference has no boundary or the mesh no area.
///
/// \tparam ReferenceFacePatchMap a `ReadablePropertyMap` from `face_descriptor` to an integer type
/// \param tm the mesh (a model of `FaceListGraph`)
/// \param reference_face_patch the patch of every face in the reference (the ground truth)
/// \param tolerance the distance tolerance of compare_boundaries(), in the mesh's units
/// \param np optional named parameters: `vertex_point_map`
/// \throws Invalid_input if `tolerance` is negative or not finite
template <typename TriangleMesh, typename ReferenceFacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double boundary_band_share(const TriangleMesh& tm, ReferenceFacePatchMap reference_face_patch, double tolerance,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw Invalid_input("the boundary tolerance must be a finite number >= 0 (got " + std::to_string(tolerance) + ")");
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  const internal::Segment_distance to_boundary(internal::patch_boundary_segments(tm, reference_face_patch, vpm));
  double within = 0., total = 0.;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const internal::Evaluation_point a = internal::to_evaluation_point(get(vpm, source(h, tm))),
                                     b = internal::to_evaluation_point(get(vpm, target(h, tm))),
                                     c = internal::to_evaluation_point(get(vpm, target(next(h, tm), tm)));
    const double area = std::sqrt(CGAL::squared_area(a, b, c));
    total += area;
    if(to_boundary.is_within(CGAL::centroid(a, b, c), tolerance)) within += area;
  }
  return total > 0 ? within / total : 0.;
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// Scores boundary curves on the surface (from `compute_patch_boundaries()`, typically
/// after `smooth_patch_boundaries()`) against the patch boundaries of the reference face
/// labelling `reference_face_patch` of the same mesh, as the face-labelling overload does,
/// but on the curves themselves: the pieces of a curve are its segments (from a point
/// inside a triangle to a point on an edge, and back), each matched when its midpoint
/// lies within `tolerance` of a reference boundary edge; a reference edge is matched when
/// its midpoint lies within `tolerance` of a curve segment. Precision and recall are the
/// matched shares of the curves' length and of the reference length.
///
/// Unlike the face-labelling overload, which sees the boundary as a chain of mesh edges
/// (a staircase across the triangles a smooth curve cuts), this scores the curves a user
/// of the boundaries draws, exports or refines the mesh along.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam ReferenceFacePatchMap a `ReadablePropertyMap` from `face_descriptor` to an integer type
/// \param boundaries the curves, on the mesh `boundaries.mesh()`
/// \param reference_face_patch the patch of every face of that mesh in the reference (the ground truth)
/// \param tolerance the distance tolerance, in the mesh's units, for example
///        `default_boundary_tolerance(boundaries.mesh())`
/// \param np optional named parameters: `vertex_point_map` (of the reference's edges;
///        it should be the one the curves were computed with)
/// \throws Invalid_input if `tolerance` is negative or not finite
template <typename TriangleMesh, typename ReferenceFacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_scores compare_boundaries(const Patch_boundaries<TriangleMesh>& boundaries,
                                   ReferenceFacePatchMap reference_face_patch, double tolerance,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw Invalid_input("the boundary tolerance must be a finite number >= 0 (got " + std::to_string(tolerance) + ")");
  const TriangleMesh& tm = boundaries.mesh();
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  return internal::compare_boundary_segments(internal::boundary_curve_segments(boundaries),
                                             internal::patch_boundary_segments(tm, reference_face_patch, vpm),
                                             tolerance);
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// The Rand index of two labellings of the same elements, each element weighted: the
/// weighted share of the pairs of distinct elements on which the labellings agree (both
/// put the two elements in one patch, or both separate them). A pair `(i, j)` weighs
/// `weights[i] * weights[j]`; with unit weights this is the classical Rand index
/// (Rand 1971), computed from the contingency table in linear time. 1 means identical
/// partitions.
/// \tparam LabelA, LabelB integer types
/// \param a, b the labellings (same size, at least two elements)
/// \param weights one non-negative weight per element (empty: all weights 1)
/// \pre `a.size() == b.size()` and `weights` is empty or of the same size
template <typename LabelA, typename LabelB>
double rand_index(const std::vector<LabelA>& a, const std::vector<LabelB>& b,
                  const std::vector<double>& weights = std::vector<double>())
{
  CGAL_precondition(a.size() == b.size());
  CGAL_precondition(weights.empty() || weights.size() == a.size());
  const std::vector<double> w = weights.empty() ? std::vector<double>(a.size(), 1.) : weights;
  std::size_t na = 0, nb = 0;
  const std::vector<std::size_t> ca = internal::compact_labels(a, na), cb = internal::compact_labels(b, nb);
  const internal::Contingency_table t(ca, na, cb, nb, w);
  // Weight of the unordered pairs of distinct elements inside groups of total weight W
  // made of elements whose squared weights sum to Q: (W^2 - Q) / 2, summed over groups.
  double same_ab = 0, same_a = 0, same_b = 0;
  for(const auto& c : t.cells) same_ab += c.second * c.second;
  for(double r : t.row) same_a += r * r;
  for(double c : t.column) same_b += c * c;
  const double q = t.sum_of_squared_weights;
  const double pairs = (t.total * t.total - q) / 2;
  if(!(pairs > 0)) return 1.;
  same_ab = (same_ab - q) / 2;
  same_a = (same_a - q) / 2;
  same_b = (same_b - q) / 2;
  // agreements = pairs together in both + pairs apart in both
  const double agree = same_ab + (pairs - same_a - same_b + same_ab);
  return agree / pairs;
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// How a segmentation's patches relate to reference patches.
struct Partition_scores
{
  double rand_index = 1.;             ///< area-weighted Rand index of the face labellings
  std::size_t over_segmentation = 0;  ///< extra pieces: sum over reference patches of (significant pieces - 1)
  std::size_t under_segmentation = 0; ///< merges: sum over patches of (reference patches it significantly covers - 1)
};

/// \ingroup PkgFeatureSegmentationEvaluation
/// Compares two face labellings given as vectors (one label and one weight per face).
/// A patch `P` is a significant piece of a reference patch `R` when the weight of
/// `P` and `R`'s common faces is at least `significant_overlap` times `R`'s weight.
/// `over_segmentation` sums, over the reference patches, the number of their significant
/// pieces minus one (a reference patch split in three counts 2); `under_segmentation`
/// sums, over the patches, the number of reference patches of which they are a
/// significant piece, minus one (one patch spanning three reference patches counts 2).
/// Both are 0 for identical partitions; a single patch against `n` reference patches
/// gives `under_segmentation == n - 1`.
/// \param labels the label of every element: the segmentation scored
/// \param reference the reference label of every element (the ground truth)
/// \param weights the weight of every element (for faces: their areas)
/// \param significant_overlap the share of a reference patch's weight that makes a piece significant
/// \pre the three vectors have the same size; `0 < significant_overlap <= 1`
template <typename Label, typename ReferenceLabel>
Partition_scores compare_partitions(const std::vector<Label>& labels, const std::vector<ReferenceLabel>& reference,
                                    const std::vector<double>& weights,
                                    double significant_overlap = default_significant_overlap)
{
  CGAL_precondition(labels.size() == reference.size() && weights.size() == labels.size());
  CGAL_precondition(significant_overlap > 0 && significant_overlap <= 1);
  Partition_scores s;
  s.rand_index = rand_index(labels, reference, weights);
  std::size_t na = 0, nb = 0;
  const std::vector<std::size_t> ca = internal::compact_labels(labels, na), cb = internal::compact_labels(reference, nb);
  const internal::Contingency_table t(ca, na, cb, nb, weights);
  std::vector<std::size_t> pieces_of_reference(nb, 0), references_of_patch(na, 0);
  for(const auto& c : t.cells)
  {
    const std::size_t i = c.first / nb, j = c.first % nb;
    if(c.second > 0 && c.second >= significant_overlap * t.column[j])
    {
      ++pieces_of_reference[j];
      ++references_of_patch[i];
    }
  }
  for(std::size_t k : pieces_of_reference) s.over_segmentation += (k > 1) ? k - 1 : 0;
  for(std::size_t k : references_of_patch) s.under_segmentation += (k > 1) ? k - 1 : 0;
  return s;
}

/// \ingroup PkgFeatureSegmentationEvaluation
/// Compares the face labelling `face_patch` of `tm` with the reference labelling
/// `reference_face_patch` (a ground truth), every face weighted by its area: the
/// area-weighted Rand index and the over- and under-segmentation counts of the vector
/// overload of `compare_partitions()`.
/// \tparam FacePatchMap, ReferenceFacePatchMap `ReadablePropertyMap`s from
///         `face_descriptor` to integer types
/// \param tm the mesh (a model of `FaceListGraph`)
/// \param face_patch the patch of every face: the segmentation scored
/// \param reference_face_patch the patch of every face in the reference (the ground truth)
/// \param significant_overlap the share of a reference patch's area that makes a piece significant
/// \param np optional named parameters: `vertex_point_map`
template <typename TriangleMesh, typename FacePatchMap, typename ReferenceFacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Partition_scores compare_partitions(const TriangleMesh& tm, FacePatchMap face_patch,
                                    ReferenceFacePatchMap reference_face_patch,
                                    double significant_overlap = default_significant_overlap,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = CGAL::Feature_segmentation::internal::vertex_point_map(tm, np);
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  typedef typename boost::property_traits<ReferenceFacePatchMap>::value_type Reference_id;
  std::vector<Id> a;
  std::vector<Reference_id> b;
  std::vector<double> w;
  for(auto f : faces(tm))
  {
    a.push_back(get(face_patch, f));
    b.push_back(get(reference_face_patch, f));
    auto h = halfedge(f, tm);
    w.push_back(std::sqrt(CGAL::to_double(internal::Evaluation_kernel::Triangle_3(
      internal::to_evaluation_point(get(vpm, source(h, tm))), internal::to_evaluation_point(get(vpm, target(h, tm))),
      internal::to_evaluation_point(get(vpm, target(next(h, tm), tm)))).squared_area())));
  }
  return compare_partitions(a, b, w, significant_overlap);
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_EVALUATION_H
