// SPDX-License-Identifier: GPL-3.0-or-later
// The read-only half of the editing engine: everything a segmentation computes once and
// no edit changes. The input is checked and indexed once; when it has creases, it is cut
// open along them and the copy (the working mesh) is indexed once, by the cut; the
// curvature, the features as first found, the per-face metrics, the vertex graph (with
// the crease ties appended as extra edges) and the solver. Built once, then shared by
// every state of the edit history (and by copies of the class) through a
// shared_ptr<const>.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_EDIT_PRECOMPUTATION_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_EDIT_PRECOMPUTATION_H

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>
#include <CGAL/Feature_segmentation/Watershed_distance.h>
#include <CGAL/Feature_segmentation/internal/crease_cut.h>
#include <CGAL/Feature_segmentation/internal/edge_alphas.h>
#include <CGAL/Feature_segmentation/internal/prepare_segmentation_data.h>
#include <CGAL/Feature_segmentation/internal/stage_times.h>

#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// On a CAD tessellation cut open along its creases (Crease_cut::cad), the crest
// lines' alpha_e is the global alpha minus this: at the default alpha they do not cut the
// B-rep faces, as alpha grows they do, so that alpha stays the granularity control on
// CAD parts.
constexpr double clean_crest_alpha_offset = 0.5;

template <typename TriangleMesh>
class Edit_precomputation
{
public:
  typedef typename Mesh_indexing<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename Mesh_indexing<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename Mesh_indexing<TriangleMesh>::face_descriptor face_descriptor;
  typedef std::function<std::size_t(const Correlation_clustering_graph&, std::vector<std::size_t>&)> Solver;

  // Checks and indexes `tm`, cuts it along its creases, prepares the data on the working
  // mesh; `times` receives the seconds of these stages.
  template <typename NamedParameters>
  Edit_precomputation(const TriangleMesh& tm, const NamedParameters& np, Stage_times& times)
    : opt(read_segmentation_options<TriangleMesh>(np)), parallel(parallel_requested<NamedParameters>())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    auto vpm = internal::vertex_point_map(tm, np);
    {
      Stage_timer timer(&times.mesh_check_and_indexing);
      check_input_mesh(tm, true, CGAL::parameters::vertex_point_map(vpm));
      input_idx = std::make_unique<Mesh_indexing<TriangleMesh> >(tm);
    }
    if(opt.crease_angle < 180)
    {
      Stage_timer timer(&times.creases);
      compute_crease_cut(*input_idx, vpm, opt.crease_angle, opt.crease_filter_iterations, opt.tangent_discontinuities,
                         opt.gamma, cut, parallel);
    }
    data = std::make_unique<Segmentation_data<TriangleMesh> >(cut.is_cut() ? *cut.working_idx : *input_idx);
    prepare(tm, np, times);
    set_face_corners();
    anisotropic = choose_parameter(get_parameter(np, internal_np::watershed_distance),
                                   Watershed_distance::ANISOTROPIC) == Watershed_distance::ANISOTROPIC;
    reduced = choose_parameter(get_parameter(np, internal_np::use_oversegmentation), true);
    // the default solver's Kernighan-Lin rounds on TBB's threads with the stages' (the
    // same result)
    Default_correlation_clustering_solver default_solver;
    default_solver.second().set_parallel(parallel);
    const auto s = choose_parameter(get_parameter(np, internal_np::solver), default_solver);
    solver = [s](const Correlation_clustering_graph& g, std::vector<std::size_t>& labels) { return s(g, labels); };
  }
  Edit_precomputation(const Edit_precomputation&) = delete;
  Edit_precomputation& operator=(const Edit_precomputation&) = delete;

  // The mesh every stage works on, and the indexing of the input.
  const Mesh_indexing<TriangleMesh>& working_indexing() const { return data->idx; }
  const TriangleMesh& working_mesh() const { return data->idx.mesh(); }
  const Mesh_indexing<TriangleMesh>& input_indexing() const { return cut.is_cut() ? *input_idx : data->idx; }

  std::size_t working_vertex(std::size_t input_vertex) const
  {
    return cut.is_cut() ? std::size_t(cut.working_vertex[input_vertex]) : input_vertex;
  }
  std::size_t working_vertex(vertex_descriptor v) const { return working_vertex(input_indexing().id(v)); }
  face_descriptor working_face(face_descriptor f) const
  {
    return cut.is_cut() ? data->idx.face_at(input_idx->id(f)) : f;
  }
  std::size_t working_edge(edge_descriptor e) const
  {
    if(!cut.is_cut()) return data->idx.id(e);
    return cut.working_halfedge[input_idx->halfedge_id(halfedge(e, input_idx->mesh()))] / 2;
  }
  // The ties of an input edge, as a range of indices into the weight terms (empty if it
  // is not a crease, or without cut).
  std::pair<std::size_t, std::size_t> ties_of(std::size_t input_edge) const
  {
    if(tie_begin.empty()) return { 0, 0 };
    return { first_tie + std::size_t(tie_begin[input_edge]), first_tie + std::size_t(tie_begin[input_edge + 1]) };
  }
  // The ties of the input edge of a working edge (a crease's ties), or the edge itself.
  std::pair<std::size_t, std::size_t> ties_of_working_edge(std::size_t e) const
  {
    return cut.is_cut() ? ties_of(cut.input_edge[e]) : std::make_pair(e, e);
  }
  bool is_crease_edge(edge_descriptor e) const { return cut.is_cut() && cut.is_crease[input_idx->id(e)] != 0; }
  // Whether every solve joins the patches of a few vertices into a neighbour
  // (join_small_patches()): on a mesh whose creases were looked for (crease_angle below
  // 180) and that is no clean tessellation (a noisy mesh or a smooth model).
  bool joins_small_patches() const { return opt.crease_angle < 180 && !cut.clean; }
  bool is_curvature_discontinuity_edge(edge_descriptor e) const
  {
    return cut.is_cut() && cut.is_crease[input_idx->id(e)] == 2;
  }

  // The feature edges: those of the working mesh (lines, user, sketches) and the creases
  // (each counted once, not per tie).
  std::size_t count_feature_edges(const Feature_terms& f) const
  {
    return std::size_t(std::count(f.is_feature_edge.begin(), f.is_feature_edge.begin() + first_tie, 1)) +
           cut.number_of_creases;
  }

  Segmentation_options opt;
  std::unique_ptr<Mesh_indexing<TriangleMesh> > input_idx;
  Crease_cut<TriangleMesh> cut;
  std::unique_ptr<Segmentation_data<TriangleMesh> > data; // on the working mesh; its features: the initial ones
  std::size_t first_tie = 0;          // index of the first tie in the weight terms
  std::vector<Compact_index> tie_begin; // per input edge: its ties, CSR (empty without cut)
  Feature_lines<TriangleMesh> lines;  // on the working mesh, without sketches and creases
  Edge_alphas alpha_e;                // the initial alpha_e of every edge and tie
  bool anisotropic = true, reduced = true;
  bool parallel = false;              // the stages that can run on TBB's threads do
  Solver solver;
  // per working face: the working ids of its corners, corner k the source of the k-th
  // halfedge from halfedge(f) (halfedge(f), its next, its previous)
  std::vector<std::array<std::uint32_t, 3> > face_corners;

private:
  void set_face_corners()
  {
    const Mesh_indexing<TriangleMesh>& idx = data->idx;
    const TriangleMesh& wm = idx.mesh();
    if(idx.number_of_vertices() > std::size_t((std::numeric_limits<std::uint32_t>::max)()))
      throw std::length_error("Feature_segmentation: more than 2^32 - 1 vertices");
    face_corners.resize(idx.number_of_faces());
    for_each_range(face_corners.size(), parallel, 16384, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        const auto h = halfedge(idx.face_at(f), wm);
        face_corners[f] = { std::uint32_t(idx.id(source(h, wm))), std::uint32_t(idx.id(source(next(h, wm), wm))),
                            std::uint32_t(idx.id(source(prev(h, wm), wm))) };
      }
    });
  }

  auto working_halfedge_at(std::size_t id) const
  {
    const auto h = halfedge(data->idx.edge_at(id / 2), data->idx.mesh());
    return (id % 2 == 0) ? h : opposite(h, data->idx.mesh());
  }

  // Whether the crest lines weigh less (Crease_cut::cad, detected feature lines, and not
  // crest_lines_on_clean_tessellations(true)).
  template <typename NamedParameters>
  bool weak_crests(const NamedParameters&) const
  {
    return cut.cad && !opt.crest_lines_on_clean_tessellations &&
           CGAL::parameters::is_default_parameter<NamedParameters, internal_np::feature_lines_t>::value;
  }

  // alpha_e on the feature edges of the working mesh that are no user feature edge
  // (`input_edge(e)`: the input mesh's edge of working edge e): a seam line's is raised
  // by Seam_thresholds::alpha_offset, a crest line's lowered by clean_crest_alpha_offset.
  template <typename NamedParameters, typename InputEdge>
  void weaken_crest_lines(std::vector<double>& a, const NamedParameters& np, InputEdge input_edge) const
  {
    const Segmentation_data<TriangleMesh>& d = *data;
    for(std::size_t e = 0; e < a.size(); ++e)
    {
      if(!d.features.is_feature_edge[e]) continue;
      if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::edge_is_feature_t>::value)
        if(get(CGAL::parameters::get_parameter(np, internal_np::edge_is_feature), input_edge(e))) continue;
      if(!d.is_seam_edge.empty() && d.is_seam_edge[e])
        a[e] += Seam_thresholds::alpha_offset;
      else
        a[e] -= clean_crest_alpha_offset;
    }
  }

  // The precomputation on the working mesh: the user's vertex point map, curvature map,
  // feature edges, feature lines and edge alphas, given for the input mesh, are carried
  // over to its cut copy; then the ties are appended to the weight terms as extra edges
  // of the vertex graph (feature edges with the crease's alpha).
  template <typename NamedParameters>
  void prepare(const TriangleMesh& tm, const NamedParameters& np, Stage_times& times)
  {
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::get_parameter_reference;
    using CGAL::parameters::is_default_parameter;
    Segmentation_data<TriangleMesh>& d = *data;
    if(!cut.is_cut())
    {
      prepare_segmentation_data(tm, np, opt, d, lines, false, &times); // checked above
      std::vector<double> a = edge_alphas(d, opt, np);
      // a CAD tessellation or a noisy mesh with no crease (Crease_cut::cad): its crest
      // lines weigh less all the same, as on a mesh cut open along its creases (below)
      if(weak_crests(np)) weaken_crest_lines(a, np, [&](std::size_t e) { return d.idx.edge_at(e); });
      alpha_e = Edge_alphas(a, opt.alpha);
      first_tie = d.edge_vertices.size();
      d.features.number_of_feature_edges = count_feature_edges(d.features);
      return;
    }
    const TriangleMesh& wm = *cut.mesh;
    // a mesh cut open along its creases: on a CAD tessellation (Crease_cut::cad) the
    // creases and the curvature discontinuities bound its B-rep faces, and crest lines
    // mostly cut its curved faces apart (on a noisy one, along the rulings of its
    // cylinders and round its tori)
    Segmentation_options o = opt;
    // crest lines on a CAD tessellation weigh less (weaken_crest_lines(); with
    // crest_lines_on_clean_tessellations(true) the full alpha, as the paper), and on a
    // clean one the seam lines join them, weighing alpha + Seam_thresholds::alpha_offset
    o.detect_seam_lines = weak_crests(np) && cut.clean && opt.tangent_discontinuities;
    const Mesh_indexing<TriangleMesh>& in = *input_idx;
    const Mesh_indexing<TriangleMesh>& wi = d.idx;
    auto wvpm = get_const_property_map(CGAL::vertex_point, wm);
    const Named_function_parameters<decltype(wvpm), CGAL::internal_np::vertex_point_t, NamedParameters> np1(wvpm, np);

    auto with_lines = [&](const auto& np3) {
      typedef std::decay_t<decltype(np3)> NP3;
      if constexpr(is_default_parameter<NamedParameters, internal_np::feature_lines_t>::value)
        prepare_segmentation_data(wm, np3, o, d, lines, false, &times); // made from the checked input
      else
      {
        Feature_lines<TriangleMesh> given = get_parameter_reference(np, internal_np::feature_lines);
        for(auto& l : given.lines)
          for(auto& p : l.points)
            p.halfedge = working_halfedge_at(cut.working_halfedge[in.halfedge_id(p.halfedge)]);
        const Named_function_parameters<Feature_lines<TriangleMesh>, internal_np::feature_lines_t, NP3> np4(given, np3);
        prepare_segmentation_data(wm, np4, o, d, lines, false, &times);
      }
    };
    auto with_features = [&](const auto& np2) {
      typedef std::decay_t<decltype(np2)> NP2;
      if constexpr(is_default_parameter<NamedParameters, internal_np::edge_is_feature_t>::value)
        with_lines(np2);
      else
      {
        auto user = get_parameter(np, internal_np::edge_is_feature);
        auto map = get(CGAL::dynamic_edge_property_t<bool>(), wm);
        for(std::size_t e = 0; e < wi.number_of_edges(); ++e)
          put(map, wi.edge_at(e), bool(get(user, in.edge_at(cut.input_edge[e]))));
        with_lines(Named_function_parameters<decltype(map), internal_np::edge_is_feature_t, NP2>(map, np2));
      }
    };
    if constexpr(is_default_parameter<NamedParameters, internal_np::principal_curvature_map_t>::value)
      with_features(np1);
    else
    {
      auto user = get_parameter(np, internal_np::principal_curvature_map);
      typedef typename boost::property_traits<decltype(user)>::value_type Curvature;
      auto map = get(CGAL::dynamic_vertex_property_t<Curvature>(), wm);
      for(std::size_t v = 0; v < wi.number_of_vertices(); ++v)
        put(map, wi.vertex_at(v), get(user, in.vertex_at(cut.input_vertex[v])));
      with_features(Named_function_parameters<decltype(map), internal_np::principal_curvature_map_t,
                                              std::decay_t<decltype(np1)> >(map, np1));
    }

    // alpha_e of the working edges, then the ties
    std::vector<double> a = d.default_alpha(opt.alpha);
    auto user_alpha = [&](std::size_t input_edge) {
      if constexpr(is_default_parameter<NamedParameters, internal_np::edge_alpha_t>::value)
        return opt.alpha;
      else
      {
        const double x = get(get_parameter(np, internal_np::edge_alpha), in.edge_at(input_edge));
        if(!std::isfinite(x)) throw Invalid_input("edge_alpha_map holds a value that is not a finite number");
        return x;
      }
    };
    if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_alpha_t>::value)
      for(std::size_t e = 0; e < a.size(); ++e) a[e] = user_alpha(cut.input_edge[e]);
    if(weak_crests(np)) weaken_crest_lines(a, np, [&](std::size_t e) { return in.edge_at(cut.input_edge[e]); });
    first_tie = d.edge_vertices.size();
    {
      std::vector<std::size_t> begin(in.number_of_edges() + 1, 0);
      for(const Crease_tie& t : cut.ties) ++begin[t.crease_edge + 1];
      for(std::size_t e = 0; e < in.number_of_edges(); ++e) begin[e + 1] += begin[e];
      tie_begin.assign(begin.begin(), begin.end());
    }
    {
      // exactly the room the ties take (a growing vector would keep up to twice that)
      const std::size_t total = first_tie + cut.ties.size();
      d.edge_vertices.reserve(total);
      d.features.similarity.reserve(total);
      d.features.award.reserve(total);
      d.features.is_feature_edge.reserve(total);
      a.reserve(total);
    }
    for(const Crease_tie& t : cut.ties) // in crease-edge order
    {
      d.edge_vertices.emplace_back(t.a, t.b);
      d.features.similarity.push_back(t.similarity);
      d.features.award.push_back(t.award);
      d.features.is_feature_edge.push_back(1);
      a.push_back(user_alpha(t.crease_edge));
    }
    d.features.number_of_feature_edges = count_feature_edges(d.features);
    alpha_e = Edge_alphas(a, opt.alpha);
  }
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_EDIT_PRECOMPUTATION_H
