// SPDX-License-Identifier: GPL-3.0-or-later
// Named parameters of the Feature_segmentation package. CGAL's list of named parameters
// is closed (one X-macro list), so the package's own options (alpha, gamma, the edge
// alpha map, the solver, ...) get their own tags here. The pack type below derives from
// CGAL::Named_function_parameters, so every CGAL function accepts it, and it offers both
// CGAL's named parameters and the package's as chainable members:
//   CGAL::Feature_segmentation::parameters::alpha(0.8).vertex_point_map(vpm).gamma(0.1)
// A plain CGAL pack (CGAL::parameters::vertex_point_map(vpm)) is accepted too.

#ifndef CGAL_FEATURE_SEGMENTATION_PARAMETERS_H
#define CGAL_FEATURE_SEGMENTATION_PARAMETERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Feature_segmentation {
namespace internal_np {

#ifndef DOXYGEN_RUNNING
#define FS_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL/Feature_segmentation/internal/parameters_interface.h>
#undef FS_add_named_parameter
#endif

} // namespace internal_np

/// \ingroup PkgFeatureSegmentationNamedParameters
/// A named parameter pack: CGAL's pack extended with the package's own options. Users
/// do not name this type; they build packs with the functions of
/// `CGAL::Feature_segmentation::parameters`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// \cond SKIP_IN_MANUAL
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_pack;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : Cgal_pack() {}
  Named_function_parameters(const T& v) : Cgal_pack(v) {}
  Named_function_parameters(const T& v, const Base& b) : Cgal_pack(v, b) {}

#ifndef DOXYGEN_RUNNING
#define CGAL_add_named_parameter(X, Y, Z)                                        \
  template <typename K>                                                          \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const   \
  {                                                                              \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);   \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define FS_add_named_parameter(X, Y, Z)                                          \
  template <typename K>                                                          \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const         \
  {                                                                              \
    return Named_function_parameters<K, internal_np::X, self>(k, *this);         \
  }
#include <CGAL/Feature_segmentation/internal/parameters_interface.h>
#undef FS_add_named_parameter
#endif
  /// \endcond
};

/// \ingroup PkgFeatureSegmentationNamedParameters
/// Functions that start a named parameter pack, one per option (CGAL's and the
/// package's); `default_values()` is the empty pack.
namespace parameters {

using CGAL::parameters::default_values;
using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::is_default_parameter;

#ifndef DOXYGEN_RUNNING
#define CGAL_add_named_parameter(X, Y, Z)                                        \
  template <typename K>                                                          \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)               \
  {                                                                              \
    return Named_function_parameters<K, CGAL::internal_np::X>(k);                \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define FS_add_named_parameter(X, Y, Z)                                          \
  template <typename K>                                                          \
  Named_function_parameters<K, internal_np::X> Z(const K& k)                     \
  {                                                                              \
    return Named_function_parameters<K, internal_np::X>(k);                      \
  }
#include <CGAL/Feature_segmentation/internal/parameters_interface.h>
#undef FS_add_named_parameter
#endif

} // namespace parameters

namespace internal {

// The vertex point map of the named parameters (`vertex_point_map`), or the mesh's own.
template <typename TriangleMesh, typename NamedParameters>
typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type
vertex_point_map(const TriangleMesh& tm, const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                            get_const_property_map(CGAL::vertex_point, tm));
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_PARAMETERS_H
