// SPDX-License-Identifier: GPL-3.0-or-later
// Resolves the named parameters shared by the weights, the segmentation and the editing
// class into a filled Segmentation_data: the user's curvature map or an estimate, the
// user's feature edges or lines or detected crest lines, then Similarity and Award.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_PREPARE_SEGMENTATION_DATA_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_PREPARE_SEGMENTATION_DATA_H

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/internal/Segmentation_data.h>
#include <CGAL/Feature_segmentation/internal/seam_lines.h>
#include <CGAL/Feature_segmentation/internal/stage_times.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

template <typename TriangleMesh, typename NamedParameters>
Segmentation_options read_segmentation_options(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Segmentation_options opt;
  opt.alpha = choose_parameter(get_parameter(np, internal_np::alpha), opt.alpha);
  opt.gamma = choose_parameter(get_parameter(np, internal_np::gamma), opt.gamma);
  opt.crease_angle = choose_parameter(get_parameter(np, internal_np::crease_angle), opt.crease_angle);
  opt.crease_filter_iterations =
    choose_parameter(get_parameter(np, internal_np::crease_filter_iterations), opt.crease_filter_iterations);
  opt.tangent_discontinuities =
    choose_parameter(get_parameter(np, internal_np::tangent_discontinuities), opt.tangent_discontinuities);
  opt.crest_lines_on_clean_tessellations = choose_parameter(
    get_parameter(np, internal_np::crest_lines_on_clean_tessellations), opt.crest_lines_on_clean_tessellations);
  opt.check();
  return opt;
}

// Fills `data` (constructed on `tm`) from the named parameters; `lines_out` receives the
// feature lines used (detected or the user's), empty when only an edge map was given.
// The curvature fit and the crest lines work on data.idx, the one indexing of `tm`;
// `check_mesh` false: the caller has checked `tm` (or built it from a checked mesh).
// `times`, if given, receives the seconds of the curvature, feature and term stages.
template <typename TriangleMesh, typename NamedParameters>
void prepare_segmentation_data(const TriangleMesh& tm, const NamedParameters& np,
                               const Segmentation_options& opt,
                               Segmentation_data<TriangleMesh>& data,
                               Feature_lines<TriangleMesh>& lines_out, bool check_mesh = true,
                               Stage_times* times = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  using CGAL::parameters::is_default_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = vertex_point_map(tm, np);

  CGAL_precondition(&data.idx.mesh() == &tm);
  if(check_mesh) check_input_mesh(tm, true, CGAL::parameters::vertex_point_map(vpm));

  auto own_curvature = get(CGAL::dynamic_vertex_property_t<Principal_curvatures<GT> >(), tm);
  auto own_features = get(CGAL::dynamic_edge_property_t<bool>(), tm);

  auto with_curvature = [&](auto cmap) {
    Stage_timer timer(times != nullptr ? &times->feature_lines : nullptr);
    data.set_geometry(vpm, cmap);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::feature_lines_t>::value)
    {
      lines_out = get_parameter_reference(np, internal_np::feature_lines);
      mark_feature_edges(tm, lines_out, own_features);
      if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_feature_t>::value)
      {
        // both given: the union of the user's edges and the lines' edges
        auto user = get_parameter(np, internal_np::edge_is_feature);
        for(auto e : edges(tm)) if(get(user, e)) put(own_features, e, true);
      }
      data.set_features(own_features, lines_out);
    }
    else if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_feature_t>::value)
    {
      lines_out.lines.clear();
      data.set_features(get_parameter(np, internal_np::edge_is_feature), lines_out);
    }
    else
    {
      if(opt.detect_crest_lines) lines_out = detect_crest_lines(data.idx, vpm, cmap, read_crest_options(np), parallel_requested<NamedParameters>());
      else lines_out.lines.clear();
      data.is_seam_edge.clear();
      if(opt.detect_seam_lines)
      {
        Feature_lines<TriangleMesh> seams = detect_seam_lines(data.idx, vpm, cmap, parallel_requested<NamedParameters>());
        data.is_seam_edge.assign(data.idx.number_of_edges(), 0);
        for(const auto& l : seams.lines)
          for(const auto& fp : l.points) data.is_seam_edge[data.idx.edge_id(fp.halfedge)] = 1;
        for(auto& l : seams.lines) lines_out.lines.push_back(std::move(l));
      }
      mark_feature_edges(tm, lines_out, own_features);
      data.set_features(own_features, lines_out);
    }
  };

  if constexpr(is_default_parameter<NamedParameters, internal_np::principal_curvature_map_t>::value)
  {
    {
      Stage_timer timer(times != nullptr ? &times->curvature : nullptr);
      estimate_principal_curvatures(data.idx, own_curvature, np);
    }
    with_curvature(own_curvature);
  }
  else
    with_curvature(get_parameter(np, internal_np::principal_curvature_map));

  Stage_timer timer(times != nullptr ? &times->weight_terms : nullptr);
  data.compute_terms(opt.gamma, parallel_requested<NamedParameters>());
}

// alpha_e of every edge: from `edge_alpha_map` if given, else alpha on feature edges
// and 0 elsewhere (paper, Eq. 3 and Section 4.1).
template <typename TriangleMesh, typename NamedParameters>
std::vector<double> edge_alphas(const Segmentation_data<TriangleMesh>& data,
                                const Segmentation_options& opt, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  std::vector<double> alpha_e = data.default_alpha(opt.alpha);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_alpha_t>::value)
  {
    auto amap = get_parameter(np, internal_np::edge_alpha);
    for(std::size_t e = 0; e < alpha_e.size(); ++e)
    {
      alpha_e[e] = get(amap, data.idx.edge_at(e));
      if(!std::isfinite(alpha_e[e]))
        throw Invalid_input("edge_alpha_map holds a value that is not a finite number");
    }
  }
  return alpha_e;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_PREPARE_SEGMENTATION_DATA_H
