// SPDX-License-Identifier: GPL-3.0-or-later
// Principal curvatures, principal directions and the curvature derivatives that crest
// lines need, estimated at the vertices of a triangle mesh. This is the first stage of
// the pipeline: the anisotropic metric of the edge weights uses k1, k2, d1, d2, and the
// crest lines use the extremality coefficients.

#ifndef CGAL_FEATURE_SEGMENTATION_PRINCIPAL_CURVATURES_H
#define CGAL_FEATURE_SEGMENTATION_PRINCIPAL_CURVATURES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/internal/curvature_fitting.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cmath>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationCurvature
/// The principal curvatures at a vertex, ordered by absolute value as the paper's
/// anisotropic metric uses them, with their directions and derivatives.
///
/// Signs: a curvature is positive where the surface bends away from its normal, the
/// normal being given by the face orientation (outward on a positively oriented closed
/// mesh): a sphere of radius r has k1 = k2 = 1/r.
///
/// \tparam GeomTraits a model of `Kernel`
template <typename GeomTraits>
struct Principal_curvatures
{
  typedef typename GeomTraits::FT FT;             ///< number type
  typedef typename GeomTraits::Vector_3 Vector_3; ///< vector type

  FT k1 = FT(0);       ///< the principal curvature of largest absolute value
  FT k2 = FT(0);       ///< the other principal curvature, `|k2| <= |k1|`
  Vector_3 d1 = Vector_3(0, 0, 0); ///< unit principal direction of `k1`, tangent to the surface
  Vector_3 d2 = Vector_3(0, 0, 0); ///< unit principal direction of `k2`; `d1`, `d2` and the normal are orthonormal
  FT dk1 = FT(0);      ///< derivative of the curvature `k1` along `d1` (an extremality coefficient)
  FT dk2 = FT(0);      ///< derivative of the curvature `k2` along `d2`

  /// `|k1| - |k2|`, the anisotropy `s` of the paper's metric (Eq. 6).
  FT anisotropy() const { return CGAL::abs(k1) - CGAL::abs(k2); }
  /// `true` when `k1` is the larger of the two signed curvatures.
  bool k1_is_max() const { return k1 >= k2; }
  /// The larger signed principal curvature, `k_max` of the crest-line literature.
  FT k_max() const { return k1_is_max() ? k1 : k2; }
  /// The smaller signed principal curvature, `k_min`.
  FT k_min() const { return k1_is_max() ? k2 : k1; }
  /// The direction of `k_max`.
  const Vector_3& d_max() const { return k1_is_max() ? d1 : d2; }
  /// The direction of `k_min`.
  const Vector_3& d_min() const { return k1_is_max() ? d2 : d1; }
  /// The extremality coefficient `e_max`: derivative of `k_max` along `d_max`.
  FT e_max() const { return k1_is_max() ? dk1 : dk2; }
  /// The extremality coefficient `e_min`: derivative of `k_min` along `d_min`.
  FT e_min() const { return k1_is_max() ? dk2 : dk1; }
};

/// \ingroup PkgFeatureSegmentationCurvature
/// The default of the named parameter `neighborhood_radius`: 1% of the bounding box
/// diagonal. On the meshes of the paper and the CAD parts of the evaluation (mean edge
/// 0.4% to 1.6% of the diagonal) two rings reach about as far, so the rings decide
/// there; on finer tessellations the radius decides, and CGAL's fandisk gives 20
/// patches at 13k, 207k and 828k faces (25 to 29 at 828k with rings only).
constexpr double default_neighborhood_radius = 0.01;

namespace internal {

// True if the named parameters ask for CGAL::Parallel_tag (concurrency_tag).
template <typename NamedParameters>
constexpr bool parallel_requested()
{
  typedef typename std::decay<decltype(CGAL::parameters::choose_parameter<CGAL::Sequential_tag>(
    CGAL::parameters::get_parameter(std::declval<const NamedParameters&>(), internal_np::concurrency_tag)))>::type Tag;
  return std::is_convertible<Tag, CGAL::Parallel_tag>::value;
}

// The options of the curvature fit, checked.
struct Curvature_settings
{
  unsigned int rings = 2;
  double radius = default_neighborhood_radius; // a fraction of the diagonal
};

template <typename NamedParameters>
Curvature_settings read_curvature_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int rings = choose_parameter(get_parameter(np, internal_np::neighborhood_rings), 2);
  if(rings < 1)
    throw Invalid_input("neighborhood_rings must be at least 1 (got " + std::to_string(rings) + ")");
  const double radius = choose_parameter(get_parameter(np, internal_np::neighborhood_radius),
                                         default_neighborhood_radius);
  if(!(radius >= 0) || !(radius <= 1))
    throw Invalid_input("neighborhood_radius must be a number in [0, 1] (a fraction of the bounding box "
                        "diagonal; got " + std::to_string(radius) + ")");
  return { static_cast<unsigned int>(rings), radius };
}

// estimate_principal_curvatures() on a mesh already checked (check_input_mesh()) and
// indexed: what the segmentation's precomputation calls, so that the mesh is checked and
// indexed once.
template <typename TriangleMesh, typename VertexCurvatureMap, typename NamedParameters>
void estimate_principal_curvatures(const Mesh_indexing<TriangleMesh>& idx, VertexCurvatureMap curvature_map,
                                   const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const TriangleMesh& tm = idx.mesh();
  VPM vpm = internal::vertex_point_map(tm, np);
  const Curvature_settings settings = read_curvature_settings(np);
  constexpr bool parallel = parallel_requested<NamedParameters>();
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!parallel, "concurrency_tag(CGAL::Parallel_tag()) needs TBB (CGAL_LINKED_WITH_TBB)");
#endif
  Curvature_fitting<TriangleMesh, VPM, GT> fitting(idx, vpm, parallel);
  fitting.estimate(settings.rings, settings.radius * fitting.geometry().bounding_box_diagonal(), parallel);
  fitting.write(curvature_map);
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationCurvature
/// Estimates, at every vertex of `tm`, the principal curvatures, their directions and
/// their derivatives along their directions, and writes them into `curvature_map`.
///
/// Method. At each vertex, a cubic height function over the tangent plane of the vertex
/// normal (angle-weighted average of the face normals) is fitted in the least-squares
/// sense to the positions and normals of the vertices within `neighborhood_rings` rings
/// (Goldfeather and Interrante 2004); its Hessian gives the curvatures and directions.
/// The neighbourhood is a piece of surface, not only a ring count: beyond the rings, it
/// takes the vertices reached through edges within `neighborhood_radius` times the
/// bounding box diagonal whose normals are within 30 degrees of the vertex normal (so it
/// does not wrap round a thin wall), thinned evenly to 32 neighbours when larger. A
/// finer tessellation of the same shape is thus fitted over the same surface and gives
/// the same crest lines. Where the radius spans 3 mean edge lengths or more, the search
/// beyond the rings goes over connected clusters of vertices, sized so that the ball
/// holds about 16 of them, each standing for one of its vertices, so that its cost does
/// not grow with the resolution.
/// The derivatives follow Yoshizawa, Belyaev and Seidel 2005: the gradient of the signed
/// fields `k_max` and `k_min`, linear over each triangle, is averaged over the faces
/// around the vertex (weighted by area) and projected on the direction. Using positions
/// and normals, the fit stays well posed on CAD meshes with large flat triangles, where
/// position-only jet fitting fails. The neighbourhood size is the scale of the features:
/// one or two rings keep sharp features sharp (octaflower), more rings smooth noise.
///
/// Degenerate (zero-area) faces take no part in normals and gradients. A vertex with
/// fewer than two neighbours in its neighbourhood gets zero curvatures.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexCurvatureMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key and
///         `Principal_curvatures<GeomTraits>` as value
/// \param tm a triangle mesh (checked with `check_input_mesh()`: throws `Invalid_input`)
/// \param curvature_map the output
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the number of rings of neighbours of a vertex that the curvature fit takes:
///                           the scale of the features on coarse meshes}
///     \cgalParamType{an integer type, at least 1}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{A value below 1 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{neighborhood_radius}
///     \cgalParamDescription{beyond the rings, the curvature fit also takes the vertices within this
///                           fraction of the bounding-box diagonal whose normals are within 30 degrees of
///                           the vertex normal: the scale of the features on fine meshes; 0: rings only}
///     \cgalParamType{`double` in [0, 1]}
///     \cgalParamDefault{`default_neighborhood_radius` (0.01)}
///     \cgalParamExtra{A value outside [0, 1] throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{concurrency_tag}
///     \cgalParamDescription{a tag indicating whether the curvature fits (with the vertex normals and
///                           the derivatives along the principal directions) run sequentially or on TBB's
///                           threads}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag`}
///     \cgalParamExtra{With `CGAL::Parallel_tag` the program must link TBB (e.g. `CGAL::TBB_support`);
///                     `tbb::global_control` bounds the number of threads. The result is the same at any
///                     thread count.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
///                     must be available in `TriangleMesh`.}
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
template <typename TriangleMesh, typename VertexCurvatureMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void estimate_principal_curvatures(const TriangleMesh& tm,
                                   VertexCurvatureMap curvature_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;

  VPM vpm = internal::vertex_point_map(tm, np);
  internal::read_curvature_settings(np); // the options' errors before the mesh's
  check_input_mesh(tm, true, CGAL::parameters::vertex_point_map(vpm));
  const internal::Mesh_indexing<TriangleMesh> idx(tm);
  internal::estimate_principal_curvatures(idx, curvature_map, np);
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_PRINCIPAL_CURVATURES_H
