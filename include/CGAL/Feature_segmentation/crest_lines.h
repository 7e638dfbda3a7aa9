// SPDX-License-Identifier: GPL-3.0-or-later
// Crest lines (ridges and valleys) after Yoshizawa, Belyaev and Seidel 2005, "Fast and
// robust detection of crest lines on meshes": the feature lines whose strong parts the
// segmentation follows. detect_crest_lines() works from a curvature map the caller
// computed or supplied; detect_feature_lines() is the one-shot entry that estimates the
// curvature, detects the lines and marks the feature edges.

#ifndef CGAL_FEATURE_SEGMENTATION_CREST_LINES_H
#define CGAL_FEATURE_SEGMENTATION_CREST_LINES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/internal/crest_lines_impl.h>
#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationFeatureLines
/// The default of the named parameter `strength_threshold`: lines whose integral of
/// |curvature| along their length is below it are dropped. A straight crease of
/// dihedral angle theta spanning m edges has a strength of about theta * m / 2 at the
/// default curvature scale, so the default keeps creases a few edges long; the
/// spurious short lines of near-umbilic or noisy regions stay well below it.
constexpr double default_strength_threshold = 1.0;

namespace internal {

// The options of the crest lines, checked.
template <typename NamedParameters>
Crest_options read_crest_options(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Crest_options opt;
  opt.strength_threshold = choose_parameter(get_parameter(np, internal_np::strength_threshold),
                                            default_strength_threshold);
  opt.umbilic_ratio = choose_parameter(get_parameter(np, internal_np::umbilic_ratio), 0.1);
  opt.ridges = choose_parameter(get_parameter(np, internal_np::detect_ridges), true);
  opt.valleys = choose_parameter(get_parameter(np, internal_np::detect_valleys), true);
  if(!(opt.strength_threshold >= 0) || !std::isfinite(opt.strength_threshold))
    throw Invalid_input("strength_threshold must be a finite number >= 0 (got " +
                        std::to_string(opt.strength_threshold) + ")");
  if(!(opt.umbilic_ratio >= 0 && opt.umbilic_ratio < 1))
    throw Invalid_input("umbilic_ratio must be in [0, 1) (got " + std::to_string(opt.umbilic_ratio) + ")");

  return opt;
}

// detect_crest_lines() on a mesh already checked (check_input_mesh()) and indexed: what
// the segmentation's precomputation calls, so that the mesh is checked and indexed once.
template <typename TriangleMesh, typename VPM, typename VertexCurvatureMap>
Feature_lines<TriangleMesh> detect_crest_lines(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                               VertexCurvatureMap curvature_map, const Crest_options& opt,
                                               bool parallel = false)
{
  std::vector<Eigen::Vector3d> points(idx.number_of_vertices());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const auto& p = get(vpm, idx.vertex_at(i));
    points[i] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  Crest_line_detector<TriangleMesh> detector(idx, points);
  Feature_lines<TriangleMesh> result;
  std::vector<Crest_vertex_data> data(points.size());
  for(Feature_line_type type : {Feature_line_type::RIDGE, Feature_line_type::VALLEY})
  {
    if((type == Feature_line_type::RIDGE && !opt.ridges) || (type == Feature_line_type::VALLEY && !opt.valleys))
      continue;
    const bool ridge = (type == Feature_line_type::RIDGE);
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const auto c = get(curvature_map, idx.vertex_at(i));
      const auto& d = ridge ? c.d_max() : c.d_min();
      data[i].k = CGAL::to_double(ridge ? c.k_max() : c.k_min());
      data[i].k_other = CGAL::to_double(ridge ? c.k_min() : c.k_max());
      data[i].e = CGAL::to_double(ridge ? c.e_max() : c.e_min());
      data[i].t = Eigen::Vector3d(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z()));
    }
    detector.detect(type, data, opt, result, parallel);
  }
  detector.sort_lines(result);
  return result;
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationFeatureLines
/// Detects ridges and valleys from a vertex curvature map.
///
/// On every edge, the extremality coefficient `e` (the derivative of `k_max` along its
/// direction for ridges, of `k_min` for valleys) is tested for a zero crossing, the
/// direction at the second vertex being flipped when it opposes the first's (directions
/// are defined up to sign, and `e` flips with them). A crossing is a ridge point if `e`
/// decreases along the direction (a maximum of `k_max`) and, at the crossing, `k_max >
/// |k_min|`; a valley point if `e` increases (a minimum of `k_min`) and `k_min <
/// -|k_max|`. Crossings near umbilics (`|k| - |k_other| <= umbilic_ratio * |k|`) are
/// dropped, since there the directions are noise. Two crossings in a triangle are joined
/// by a segment (with three, the two strongest are); the segments are traced into
/// polylines, and each line's strength is the integral of |k| along it (Yoshizawa et al.).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexCurvatureMap a `ReadablePropertyMap` from `vertex_descriptor` to
///         `Principal_curvatures<GeomTraits>` (filled e.g. by `estimate_principal_curvatures()`)
/// \param tm the mesh (checked with `check_input_mesh()`)
/// \param curvature_map the curvatures
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{strength_threshold}
///     \cgalParamDescription{the crest lines whose strength (the integral of \f$ \vert k \vert \f$ along the
///                           line) is below it are dropped}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_strength_threshold` (1.0)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{umbilic_ratio}
///     \cgalParamDescription{the zero crossings near umbilics, where \f$ \vert k \vert - \vert k_{other}
///                           \vert \leq \f$ `umbilic_ratio` \f$ \cdot \vert k \vert \f$, are dropped: there
///                           the principal directions are noise}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 1) throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_ridges}
///     \cgalParamDescription{whether ridges (maxima of `k_max` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_valleys}
///     \cgalParamDescription{whether valleys (minima of `k_min` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t` must
///                     be available in `TriangleMesh`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return the lines, strongest first
/// \throws Invalid_input on a bad mesh or a bad option value
template <typename TriangleMesh, typename VertexCurvatureMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Feature_lines<TriangleMesh>
detect_crest_lines(const TriangleMesh& tm, VertexCurvatureMap curvature_map,
                   const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = internal::vertex_point_map(tm, np);
  const internal::Crest_options opt = internal::read_crest_options(np); // the options' errors first
  check_input_mesh(tm, true, CGAL::parameters::vertex_point_map(vpm));
  const internal::Mesh_indexing<TriangleMesh> idx(tm);
  return internal::detect_crest_lines(idx, vpm, curvature_map, opt);
}

/// \ingroup PkgFeatureSegmentationFeatureLines
/// One shot: estimates the principal curvatures (unless `principal_curvature_map` is
/// given), detects the crest lines, and marks the edges holding a feature point in
/// `edge_is_feature`.
///
/// \tparam EdgeIsFeatureMap a `ReadWritePropertyMap` from `edge_descriptor` to `bool`
/// \param tm the mesh (checked with `check_input_mesh()`)
/// \param edge_is_feature the output: `true` on the feature edges, `false` elsewhere
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{principal_curvature_map}
///     \cgalParamDescription{the principal curvatures of the vertices, used instead of estimating them}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and
///                    `Principal_curvatures<GeomTraits>` as value type}
///     \cgalParamDefault{estimated as by `estimate_principal_curvatures()`, with `neighborhood_rings`,
///                       `neighborhood_radius` and `concurrency_tag`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{strength_threshold}
///     \cgalParamDescription{the crest lines whose strength (the integral of \f$ \vert k \vert \f$ along the
///                           line) is below it are dropped}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_strength_threshold` (1.0)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{umbilic_ratio}
///     \cgalParamDescription{the zero crossings near umbilics, where \f$ \vert k \vert - \vert k_{other}
///                           \vert \leq \f$ `umbilic_ratio` \f$ \cdot \vert k \vert \f$, are dropped: there
///                           the principal directions are noise}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 1) throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_ridges}
///     \cgalParamDescription{whether ridges (maxima of `k_max` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_valleys}
///     \cgalParamDescription{whether valleys (minima of `k_min` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the number of rings of neighbours of a vertex that the curvature fit takes: the
///                           scale of the features on coarse meshes}
///     \cgalParamType{an integer type, at least 1}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{A value below 1 throws `Invalid_input`. Used only when `principal_curvature_map` is
///                     not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_radius}
///     \cgalParamDescription{beyond the rings, the curvature fit also takes the vertices within this fraction
///                           of the bounding-box diagonal whose normals are within 30 degrees of the vertex
///                           normal: the scale of the features on fine meshes; 0: rings only}
///     \cgalParamType{`double` in [0, 1]}
///     \cgalParamDefault{`default_neighborhood_radius` (0.01)}
///     \cgalParamExtra{A value outside [0, 1] throws `Invalid_input`. Used only when
///                     `principal_curvature_map` is not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{concurrency_tag}
///     \cgalParamDescription{a tag indicating whether the curvature fits run sequentially or on TBB's
///                           threads}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag`}
///     \cgalParamExtra{With `CGAL::Parallel_tag` the program must link TBB (e.g. `CGAL::TBB_support`);
///                     `tbb::global_control` bounds the number of threads. The result is the same at any
///                     thread count. Used only when `principal_curvature_map` is not given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t` must
///                     be available in `TriangleMesh`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type, deduced with `CGAL::Kernel_traits`}
///     \cgalParamExtra{The geometric traits class must be compatible with the vertex point type. Only its
///                     types are used (`FT`, `Point_3`, `Vector_3`: the value type of the curvature map is
///                     `Principal_curvatures<GeomTraits>`); the computations are done in `double`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return the lines, strongest first
template <typename TriangleMesh, typename EdgeIsFeatureMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Feature_lines<TriangleMesh>
detect_feature_lines(const TriangleMesh& tm, EdgeIsFeatureMap edge_is_feature,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  Feature_lines<TriangleMesh> lines;
  if constexpr(is_default_parameter<NamedParameters, internal_np::principal_curvature_map_t>::value)
  {
    auto cmap = get(CGAL::dynamic_vertex_property_t<Principal_curvatures<GT> >(), tm);
    estimate_principal_curvatures(tm, cmap, np);
    lines = detect_crest_lines(tm, cmap, np);
  }
  else
    lines = detect_crest_lines(tm, get_parameter(np, internal_np::principal_curvature_map), np);
  mark_feature_edges(tm, lines, edge_is_feature);
  return lines;
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_CREST_LINES_H
