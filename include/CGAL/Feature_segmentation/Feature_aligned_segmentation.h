// SPDX-License-Identifier: GPL-3.0-or-later
// The class for the precompute-and-reuse path (paper, Sections 3.3 and 4): it keeps the
// curvature, the feature lines, the Similarity and Award terms, the watershed
// oversegmentation and the reduced graph G', and answers the paper's edits (global and
// local refine/coarsen, feature sketching, merging, undo) by re-weighting and re-solving
// G' only, never redoing what an edit does not invalidate.

#ifndef CGAL_FEATURE_SEGMENTATION_FEATURE_ALIGNED_SEGMENTATION_H
#define CGAL_FEATURE_SEGMENTATION_FEATURE_ALIGNED_SEGMENTATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>
#include <CGAL/Feature_segmentation/Watershed_distance.h>
#include <CGAL/Feature_segmentation/internal/boundary_refinement_impl.h>
#include <CGAL/Feature_segmentation/internal/crease_cut.h>
#include <CGAL/Feature_segmentation/internal/face_patch_rule.h>
#include <CGAL/Feature_segmentation/internal/oversegmentation_impl.h>
#include <CGAL/Feature_segmentation/internal/prepare_segmentation_data.h>
#include <CGAL/Feature_segmentation/internal/sketch_walk.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationSegmentation
/// Feature-aligned segmentation with interactive edits.
///
/// The constructor does all the precomputation of `segment_along_features()` once:
/// curvature, feature lines, the terms Similarity and Award of every edge, the watershed
/// oversegmentation and the reduced graph G', then solves. Every edit changes the
/// per-edge parameters `alpha_e` (or the features, or merge constraints), re-weights G'
/// and re-solves, and returns the new number of patches:
///
/// | edit | what it recomputes | cost |
/// |---|---|---|
/// | `set_alpha()` (global refine/coarsen) | the weights of G', the clustering of G' | O(E + V) bookkeeping + solve on G' |
/// | `add_to_alpha()`, `multiply_alpha()` (local) | the same, the clustering on the patches the region touches only | O(E + V) bookkeeping + solve on those patches |
/// | `merge_patches()` | the labels (a constraint that later solves keep) | O(V) |
/// | `add_sketch()` | terms of the faces around the sketch, the oversegmentation inside the patches it touches, G', their clustering | O(F log F + E log E) + solve on those patches |
/// | `undo()` | restores the state before the last edit | O(E + V) (plus a copy of the features for a sketch) |
///
/// E, V, F are the mesh's edges, vertices and faces; G' is much smaller (6,453 nodes and
/// 18,374 edges on rockerarm remeshed to 196,566 faces, against 98,283 vertices and
/// 294,849 edges). The bookkeeping is a few linear passes over arrays: on that mesh an
/// alpha edit took a median of 13.9 ms in all (`bench_fig8`).
///
/// A vertex that no face uses (isolated) is a patch of its own. If an edit throws (a
/// user solver, memory), it is undone before the exception goes on: the object stays as
/// it was before the edit.
/// Local edits and sketches re-solve only the current patches they touch, so the other
/// patches keep their vertices (their ids may change: ids are renumbered in vertex order
/// after each edit).
///
/// \tparam TriangleMesh a model of `FaceListGraph`; the mesh must outlive the object and
///         stay unchanged.
template <typename TriangleMesh>
class Feature_aligned_segmentation
{
public:
  /// \name Types
  /// @{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor; ///< vertex type
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;     ///< edge type
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;     ///< face type
  /// The point type of the mesh's vertex point map.
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point_3;
  /// A point of a sketch: a point on the surface and the face that contains it.
  struct Sketch_point
  {
    face_descriptor face; ///< the face containing `point`
    Point_3 point;        ///< the point
  };
  /// @}

  /// Precomputes and solves. The named parameters are those of
  /// `segment_along_features()` except the outputs (`face_patch_map`, `cut_cost_output`);
  /// the solver is kept for every later solve.
  /// \throws Invalid_input on a bad mesh or a bad option value
  /// \pre the edits' faces are faces of the mesh (the null face throws `Invalid_input`)
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Feature_aligned_segmentation(const TriangleMesh& tm,
                                        const NamedParameters& np = CGAL::parameters::default_values())
    : m_opt(internal::read_segmentation_options<TriangleMesh>(np)),
      m_work(make_working(tm, np, m_opt)),
      m_data(m_work->cut.is_cut() ? *m_work->cut.working_idx : *m_work->input_idx)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    prepare(tm, np);
    m_anisotropic = choose_parameter(get_parameter(np, internal_np::watershed_distance),
                                     Watershed_distance::ANISOTROPIC) == Watershed_distance::ANISOTROPIC;
    m_reduced = choose_parameter(get_parameter(np, internal_np::use_oversegmentation), true);
    const auto solver = choose_parameter(get_parameter(np, internal_np::solver),
                                         Default_correlation_clustering_solver());
    m_solver = [solver](const Correlation_clustering_graph& g, std::vector<std::size_t>& labels) {
      return solver(g, labels);
    };
    m_state.alpha = m_opt.alpha;
    m_heavy = std::make_shared<Heavy>();
    build_oversegmentation_everywhere(*m_heavy);
    m_state.group.resize(m_heavy->os.number_of_segments);
    for(std::size_t s = 0; s < m_state.group.size(); ++s) m_state.group[s] = s;
    solve_all();
  }

  /// \name Results
  /// @{

  /// The number of patches.
  std::size_t number_of_patches() const { return m_state.number_of_patches; }
  /// The patch of a vertex, in `0 .. number_of_patches()-1`. A vertex on a crease has a
  /// copy on each side of it in `working_mesh()`; this is the patch of the copy in the
  /// sector of its first face (`face_patches()` is exact along creases).
  std::size_t patch(vertex_descriptor v) const { return m_state.labels[working_vertex(v)]; }
  /// The patch of a face: the majority of its corners' patches in `working_mesh()`, or the
  /// smallest when all three differ. A face next to a crease has its corners on its own
  /// side of the crease, so it never takes the patch across the crease.
  std::size_t patch(face_descriptor f) const
  {
    check_face(f);
    const TriangleMesh& tm = m_data.idx.mesh();
    auto h = halfedge(working_face(f), tm);
    const auto& l = m_state.labels;
    return internal::face_patch_from_vertices(l[m_data.idx.id(source(h, tm))], l[m_data.idx.id(target(h, tm))],
                                              l[m_data.idx.id(target(next(h, tm), tm))]);
  }
  /// Writes the patch of every vertex (as `patch(vertex_descriptor)`) into a
  /// `WritablePropertyMap` from `vertex_descriptor`.
  template <typename VertexPatchMap>
  void vertex_patches(VertexPatchMap map) const
  {
    typedef typename boost::property_traits<VertexPatchMap>::value_type Id;
    for(std::size_t v = 0; v < input_indexing().number_of_vertices(); ++v)
      put(map, input_indexing().vertex_at(v), static_cast<Id>(m_state.labels[working_vertex(v)]));
  }
  /// Writes the patch of every face (as `patch(face_descriptor)`) into a
  /// `WritablePropertyMap` from `face_descriptor`.
  template <typename FacePatchMap>
  void face_patches(FacePatchMap map) const
  {
    typedef typename boost::property_traits<FacePatchMap>::value_type Id;
    const internal::Mesh_indexing<TriangleMesh>& in = input_indexing();
    for(std::size_t f = 0; f < in.number_of_faces(); ++f)
      put(map, in.face_at(f), static_cast<Id>(patch(in.face_at(f))));
  }
  /// Writes the patch of every face as the boundaries `b` cut it: the patch covering most
  /// of its area (`majority_face_patches()`), into a `WritablePropertyMap` from
  /// `face_descriptor`. With `b` smoothed (`smooth_patch_boundaries()`), these are the
  /// patches of the final boundaries: a face the smoothed boundary leaves to one side
  /// takes that side, to within half a triangle, where the vertex majority of
  /// `face_patches(map)` zigzags along the unsmoothed cut. Along a crease every face
  /// keeps its own side, as in `face_patches(map)`.
  /// \pre `b` was made by `patch_boundaries()` of this object in its current state
  template <typename FacePatchMap>
  void face_patches(const Patch_boundaries<TriangleMesh>& b, FacePatchMap map) const
  {
    CGAL_precondition(&b.mesh() == &working_mesh() && b.state().number_of_faces() == m_data.idx.number_of_faces());
    typedef typename boost::property_traits<FacePatchMap>::value_type Id;
    const internal::Mesh_indexing<TriangleMesh>& in = input_indexing();
    // the faces of working_mesh() are those of the input, in the same order
    for(std::size_t f = 0; f < in.number_of_faces(); ++f)
      put(map, in.face_at(f), static_cast<Id>(internal::majority_patch(b.state(), f)));
  }
  /// Writes the patch of every vertex in the boundaries `b`, into a `WritablePropertyMap`
  /// from `vertex_descriptor`: after `smooth_patch_boundaries()`, a vertex next to a
  /// boundary may have moved to the neighbouring patch (see there). A vertex on a crease
  /// has the patch of its copy in the sector of its first face, as in `vertex_patches(map)`.
  /// \pre `b` was made by `patch_boundaries()` of this object in its current state
  template <typename VertexPatchMap>
  void vertex_patches(const Patch_boundaries<TriangleMesh>& b, VertexPatchMap map) const
  {
    CGAL_precondition(&b.mesh() == &working_mesh() &&
                      b.state().number_of_vertices() == m_data.idx.number_of_vertices());
    typedef typename boost::property_traits<VertexPatchMap>::value_type Id;
    for(std::size_t v = 0; v < input_indexing().number_of_vertices(); ++v)
      put(map, input_indexing().vertex_at(v), static_cast<Id>(b.state().labels[working_vertex(v)]));
  }
  /// The cut cost (Eq. 1) of the current segmentation under the current weights (the
  /// crease ties included).
  double cut_cost() const
  {
    double cost = 0;
    const auto& rg = m_heavy->rg;
    for(std::size_t e : rg.cross)
      if(m_state.labels[m_data.edge_vertices[e].first] != m_state.labels[m_data.edge_vertices[e].second])
        cost += weight(e);
    return cost;
  }
  /// The global parameter alpha.
  double alpha() const { return m_state.alpha; }
  /// The parameter `alpha_e` of an edge (of a crease: that of its ties).
  double alpha(edge_descriptor e) const
  {
    const auto t = ties_of(input_indexing().id(e));
    return t.first != t.second ? m_state.alpha_e[t.first] : m_state.alpha_e[working_edge(e)];
  }
  /// The weight `w(e) = Similarity(e) - alpha_e Award(e)` of an edge; of a crease edge,
  /// the weight of cutting along it (its two ties).
  double weight(edge_descriptor e) const
  {
    const auto t = ties_of(input_indexing().id(e));
    if(t.first == t.second) return weight(working_edge(e));
    double w = 0;
    for(std::size_t i = t.first; i < t.second; ++i) w += weight(i);
    return w;
  }
  /// Whether an edge is a feature edge (a crease, or from the feature lines, the user or
  /// a sketch).
  bool is_feature_edge(edge_descriptor e) const
  {
    return is_crease_edge(e) || m_data.is_feature_edge[working_edge(e)] != 0;
  }
  /// Whether an edge is a crease: its dihedral angle is at least `crease_angle`.
  bool is_crease_edge(edge_descriptor e) const
  {
    return m_work->cut.is_cut() && m_work->cut.is_crease[input_indexing().id(e)] != 0;
  }
  /// The number of feature edges: the creases and the edges of `working_mesh()` that
  /// the feature lines cross.
  std::size_t number_of_feature_edges() const { return m_data.number_of_feature_edges; }
  /// The number of crease edges.
  std::size_t number_of_crease_edges() const { return m_work->cut.number_of_creases; }
  /// The mesh the segmentation works on: the input mesh, or when it has creases, a copy
  /// of it cut open along them (a vertex on a crease has one copy per side; the faces are
  /// those of the input, in the same order). `feature_lines()` and `patch_boundaries()`
  /// live on it; the patch boundaries along creases are borders of it, not curves.
  const TriangleMesh& working_mesh() const { return m_data.idx.mesh(); }
  /// The feature lines (detected or given) on `working_mesh()`, without the sketches and
  /// without the creases.
  const Feature_lines<TriangleMesh>& feature_lines() const { return m_lines; }
  /// The boundaries between the current patches as curves on the surface, carrying the
  /// anisotropic metric of the weights, ready for `smooth_patch_boundaries()` and for the
  /// per-face patches of `face_patches.h`, on `working_mesh()`. Built from this object's
  /// precomputation (no curvature or feature recomputed); the result must not outlive
  /// this object.
  Patch_boundaries<TriangleMesh> patch_boundaries() const
  {
    return internal::make_patch_boundaries(m_data, m_state.labels);
  }
  /// The number of oversegments (nodes of G').
  std::size_t number_of_oversegments() const { return m_heavy->os.number_of_segments; }
  /// The number of edits that `undo()` can take back.
  std::size_t number_of_undoable_edits() const { return m_undo.size(); }
  /// The number of edits recorded for `undo()` since construction, including those
  /// dropped beyond `maximum_undo_depth` and those already undone: an edit that changed
  /// nothing (an empty region, a merge inside one patch) records none, so comparing this
  /// number before and after an edit tells whether `undo()` would take it back.
  std::size_t number_of_recorded_edits() const { return m_recorded; }
  /// @}

  /// \name Edits
  /// Each returns the new number of patches.
  /// @{

  /// Global refinement (larger `a`) or coarsening: sets alpha to `a`. The `alpha_e` of
  /// every feature edge moves by `a - alpha()`, so local edits made before are kept as
  /// offsets (the authors' tool does the same).
  std::size_t set_alpha(double a)
  {
    if(!std::isfinite(a)) throw Invalid_input("alpha must be a finite number");
    push_undo();
    transaction([&] {
      const double shift = a - m_state.alpha;
      for(std::size_t e = 0; e < m_state.alpha_e.size(); ++e)
        if(m_data.is_feature_edge[e]) m_state.alpha_e[e] += shift;
      m_state.alpha = a;
      solve_all();
    });
    return number_of_patches();
  }

  /// Local refinement (`delta > 0`) or coarsening (`delta < 0`): adds `delta` to the
  /// `alpha_e` of the feature edges of `faces` (a painted region), then re-solves the
  /// patches that the region touches.
  /// \tparam FaceRange a range of `face_descriptor`
  template <typename FaceRange>
  std::size_t add_to_alpha(const FaceRange& faces, double delta)
  {
    if(!std::isfinite(delta)) throw Invalid_input("the alpha increment must be a finite number");
    return edit_region(faces, [delta](double a) { return a + delta; });
  }

  /// Local refinement or coarsening by a factor: multiplies the `alpha_e` of the feature
  /// edges of `faces` by `factor` (>= 0), then re-solves the patches the region touches.
  template <typename FaceRange>
  std::size_t multiply_alpha(const FaceRange& faces, double factor)
  {
    if(!(factor >= 0) || !std::isfinite(factor)) throw Invalid_input("the alpha factor must be a finite number >= 0");
    return edit_region(faces, [factor](double a) { return a * factor; });
  }

  /// Merging: the patches that contain a vertex of `faces` become one patch, and stay
  /// together in later solves (until undone, or until a sketch redoes their region).
  template <typename FaceRange>
  std::size_t merge_patches(const FaceRange& faces)
  {
    std::set<std::size_t> touched = patches_of(faces);
    if(touched.size() < 2) return number_of_patches();
    push_undo();
    std::size_t target_group = std::size_t(-1);
    std::vector<char> in(m_state.group.size(), 0);
    const auto& seg = m_heavy->os.vertex_segment;
    for(std::size_t v = 0; v < seg.size(); ++v)
      if(touched.count(m_state.labels[v]))
      {
        in[seg[v]] = 1;
        target_group = (std::min)(target_group, m_state.group[seg[v]]);
      }
    std::vector<char> group_in(m_state.group.size(), 0);
    for(std::size_t s = 0; s < in.size(); ++s) if(in[s]) group_in[m_state.group[s]] = 1;
    for(std::size_t s = 0; s < m_state.group.size(); ++s)
      if(group_in[m_state.group[s]]) m_state.group[s] = target_group;
    const std::size_t merged = *touched.begin();
    for(std::size_t& l : m_state.labels) if(touched.count(l)) l = merged;
    m_state.number_of_patches = normalize_labels(m_state.labels);
    m_discarded_redo.clear(); // a merge cannot fail
    return number_of_patches();
  }

  /// Feature sketching: `sketch` is a polyline on the surface. The edges it crosses
  /// become feature edges with `alpha_e = max(alpha_e, sketch_alpha)`, the weights
  /// around them are updated, the oversegmentation is recomputed inside the current
  /// patches that the sketch touches (their merge constraints are released), and those
  /// patches are re-solved.
  ///
  /// The paper uses `alpha_e = 1`; but where the surface is flat, Similarity equals
  /// Award, so `alpha_e = 1` gives a weight of exactly 0 and nothing asks for the cut (the
  /// authors' tool raises the Award of sketched edges instead). The default 2 gives
  /// `w(e) = -Award(e)` on flat ground and more negative weights on features.
  /// \param sketch the polyline, at least two points
  /// \param sketch_alpha the `alpha_e` of the crossed edges, finite and > 1
  /// \return the new number of patches
  std::size_t add_sketch(const std::vector<Sketch_point>& sketch, double sketch_alpha = 2.0)
  {
    if(!(sketch_alpha > 1) || !std::isfinite(sketch_alpha))
      throw Invalid_input("sketch_alpha must be a finite number > 1 (got " + std::to_string(sketch_alpha) + ")");
    if(sketch.size() < 2) return number_of_patches();
    const TriangleMesh& tm = m_data.idx.mesh();
    std::vector<internal::Sketch_input> in;
    for(const Sketch_point& sp : sketch)
    {
      const auto& p = sp.point;
      const Eigen::Vector3d q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      if(!q.allFinite()) throw Invalid_input("a sketch point has a NaN or infinite coordinate");
      check_face(sp.face);
      in.push_back({m_data.idx.id(working_face(sp.face)), q});
      // a point far from its face is a caller's mistake, and would make the walk endless
      if(internal::distance_to_face(m_data, in.back()) > 0.01 * m_data.diagonal)
        throw Invalid_input("a sketch point lies farther than 1% of the bounding-box diagonal from its face");
    }
    const std::vector<internal::Sketch_crossing> crossings = internal::walk_sketch(m_data, in);
    if(crossings.empty()) return number_of_patches();
    push_undo(true);
    transaction([&] {
      auto heavy = std::make_shared<Heavy>(*m_heavy);
      std::vector<std::size_t> faces;
      std::set<std::size_t> touched;
      for(const internal::Sketch_crossing& c : crossings)
      {
        m_data.point_sum[c.edge] += c.point;
        ++m_data.point_count[c.edge];
        m_data.is_feature_edge[c.edge] = 1;
        m_state.alpha_e[c.edge] = (std::max)(m_state.alpha_e[c.edge], sketch_alpha);
        auto h = halfedge(m_data.idx.edge_at(c.edge), tm);
        for(auto hh : {h, opposite(h, tm)})
          if(!is_border(hh, tm)) faces.push_back(m_data.idx.face_id(hh));
        touched.insert(m_state.labels[m_data.edge_vertices[c.edge].first]);
        touched.insert(m_state.labels[m_data.edge_vertices[c.edge].second]);
      }
      std::sort(faces.begin(), faces.end());
      faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
      m_data.terms.update_faces(m_data.idx, m_data.vin, m_data.is_feature_edge, m_data.point_sum,
                                m_data.point_count, faces);
      count_feature_edges();
      // redo the oversegmentation inside the touched patches
      std::vector<char> region(m_state.labels.size(), 0);
      for(std::size_t v = 0; v < region.size(); ++v) region[v] = touched.count(m_state.labels[v]) ? 1 : 0;
      const internal::Oversegmentation local =
        m_reduced ? internal::compute_oversegmentation(m_data, m_anisotropic, &region)
                  : singleton_oversegmentation(&region);
      std::vector<std::size_t> renum(heavy->os.number_of_segments, std::size_t(-1));
      std::vector<std::size_t> new_group;
      std::size_t k = 0;
      for(std::size_t v = 0; v < region.size(); ++v)
      {
        if(region[v]) continue;
        std::size_t& r = renum[heavy->os.vertex_segment[v]];
        if(r == std::size_t(-1)) { r = k++; new_group.push_back(m_state.group[heavy->os.vertex_segment[v]]); }
      }
      // groups outside keep their constraints (ids compacted below); new segments are free
      const std::size_t first_new = k;
      for(std::size_t v = 0; v < region.size(); ++v)
        heavy->os.vertex_segment[v] = region[v] ? first_new + local.vertex_segment[v]
                                                : renum[heavy->os.vertex_segment[v]];
      heavy->os.number_of_segments = first_new + local.number_of_segments;
      std::vector<std::size_t> group_renum(m_state.group.size() + local.number_of_segments, std::size_t(-1));
      std::size_t ng = 0;
      for(std::size_t& g : new_group)
      {
        if(group_renum[g] == std::size_t(-1)) group_renum[g] = ng++;
        g = group_renum[g];
      }
      for(std::size_t s = 0; s < local.number_of_segments; ++s) new_group.push_back(ng++);
      m_state.group.swap(new_group);
      heavy->rg.build(heavy->os.vertex_segment, heavy->os.number_of_segments, m_data.edge_vertices);
      m_heavy = heavy;
      solve_patches(touched, /*vertex_region=*/&region);
    });
    return number_of_patches();
  }

  /// The most edits `undo()` keeps: each record holds the per-edge parameters and the
  /// labels (some 3 MB on a 200k-face mesh), so older records are dropped.
  static constexpr std::size_t maximum_undo_depth = 64;

  /// Takes back the last edit, restoring the labels exactly. Returns `false` when there
  /// is nothing to undo (no edit yet, or `maximum_undo_depth` edits already undone).
  /// The edit taken back can be made again with `redo()`.
  bool undo()
  {
    if(m_undo.empty()) return false;
    Undo_record& r = m_undo.back();
    m_redo.push_back(snapshot(r.features != nullptr));
    restore(std::move(r));
    m_undo.pop_back();
    return true;
  }

  /// The number of undone edits that `redo()` can make again: every `undo()` adds one,
  /// every `redo()` takes one, and any other edit that records an undo step clears them.
  std::size_t number_of_redoable_edits() const { return m_redo.size(); }

  /// Makes again the last edit taken back by `undo()`, restoring its result exactly
  /// (no solve runs). Returns `false` when there is nothing to redo.
  bool redo()
  {
    if(m_redo.empty()) return false;
    Undo_record& r = m_redo.back();
    m_undo.push_back(snapshot(r.features != nullptr));
    restore(std::move(r));
    m_redo.pop_back();
    return true;
  }
  /// @}

private:
  typedef Eigen::Vector3d Vec3;

  // What a sketch changes besides the light state: shared between the current state and
  // the undo records that predate no sketch (copy on write).
  struct Heavy
  {
    internal::Oversegmentation os;
    internal::Reduced_graph rg;
  };
  struct State
  {
    double alpha = internal::Segmentation_options().alpha;
    std::vector<double> alpha_e;
    std::vector<std::size_t> group;  // merge constraints: oversegments of a group stay together
    std::vector<std::size_t> labels; // per vertex
    std::size_t number_of_patches = 0;
  };
  struct Feature_copy
  {
    std::vector<char> is_feature_edge;
    std::vector<Vec3> point_sum;
    std::vector<int> point_count;
    std::vector<Vec3> dual_vertices;
    std::vector<double> similarity, award;
    std::size_t number_of_feature_edges = 0;
  };
  struct Undo_record
  {
    State state;
    std::shared_ptr<Heavy> heavy;
    std::unique_ptr<Feature_copy> features; // only for a sketch
  };

  double weight(std::size_t e) const { return m_data.weight(e, m_state.alpha_e[e]); }

  // The current state, for an undo or a redo record (the features only for a sketch).
  Undo_record snapshot(bool with_features) const
  {
    Undo_record r;
    r.state = m_state;
    r.heavy = m_heavy;
    if(with_features)
    {
      r.features.reset(new Feature_copy{m_data.is_feature_edge, m_data.point_sum, m_data.point_count,
                                        m_data.terms.dual_vertices, m_data.terms.similarity,
                                        m_data.terms.award, m_data.number_of_feature_edges});
    }
    return r;
  }

  void restore(Undo_record&& r)
  {
    m_state = std::move(r.state);
    m_heavy = r.heavy;
    if(r.features)
    {
      m_data.is_feature_edge = std::move(r.features->is_feature_edge);
      m_data.point_sum = std::move(r.features->point_sum);
      m_data.point_count = std::move(r.features->point_count);
      m_data.terms.dual_vertices = std::move(r.features->dual_vertices);
      m_data.terms.similarity = std::move(r.features->similarity);
      m_data.terms.award = std::move(r.features->award);
      m_data.number_of_feature_edges = r.features->number_of_feature_edges;
    }
  }

  // Called by an edit before it changes anything: records the state for undo() and
  // forgets what redo() could make again (a new edit starts a new branch of history).
  void push_undo(bool with_features = false)
  {
    m_undo.push_back(snapshot(with_features));
    ++m_recorded;
    if(m_undo.size() > maximum_undo_depth)
      m_undo.erase(m_undo.begin());
    m_discarded_redo.swap(m_redo); // given back by transaction() if the edit fails
    m_redo.clear();
  }

  internal::Oversegmentation singleton_oversegmentation(const std::vector<char>* region) const
  {
    internal::Oversegmentation os;
    os.vertex_segment.assign(m_data.idx.number_of_vertices(), std::size_t(-1));
    for(std::size_t v = 0; v < os.vertex_segment.size(); ++v)
      if(region == nullptr || (*region)[v]) os.vertex_segment[v] = os.number_of_segments++;
    return os;
  }

  void build_oversegmentation_everywhere(Heavy& h) const
  {
    h.os = m_reduced ? internal::compute_oversegmentation(m_data, m_anisotropic) : singleton_oversegmentation(nullptr);
    h.rg.build(h.os.vertex_segment, h.os.number_of_segments, m_data.edge_vertices);
  }

  template <typename FaceRange>
  std::set<std::size_t> patches_of(const FaceRange& faces) const
  {
    const TriangleMesh& tm = m_data.idx.mesh();
    std::set<std::size_t> touched;
    for(face_descriptor f : faces)
    {
      check_face(f);
      for(auto h : CGAL::halfedges_around_face(halfedge(working_face(f), tm), tm))
        touched.insert(m_state.labels[m_data.idx.id(target(h, tm))]);
    }
    return touched;
  }

  template <typename FaceRange, typename Change>
  std::size_t edit_region(const FaceRange& faces, Change change)
  {
    const TriangleMesh& tm = m_data.idx.mesh();
    std::set<std::size_t> touched = patches_of(faces);
    if(touched.empty()) return number_of_patches();
    push_undo();
    transaction([&] {
      std::vector<char> done(m_state.alpha_e.size(), 0);
      for(face_descriptor f : faces)
        for(auto h : CGAL::halfedges_around_face(halfedge(working_face(f), tm), tm))
        {
          const std::size_t e = m_data.idx.edge_id(h);
          const auto t = m_work->cut.is_cut() ? ties_of(m_work->cut.input_edge[e]) : std::make_pair(e, e);
          for(std::size_t i = t.first; i < t.second; ++i) // a crease's ties
            if(!done[i]) { done[i] = 1; m_state.alpha_e[i] = change(m_state.alpha_e[i]); }
          if(!m_data.is_feature_edge[e] || done[e]) continue;
          done[e] = 1;
          m_state.alpha_e[e] = change(m_state.alpha_e[e]);
        }
      solve_patches(touched, nullptr);
    });
    return number_of_patches();
  }

  // Clusters the groups of oversegments whose `in_region` is set; the others keep their
  // labels. Nodes of the solved graph are merge groups (a constraint never cut).
  //
  // The labels are built aside and swapped in only once the solver has returned, so a
  // solver that throws leaves the state as it was (`transaction()` then undoes the edit).
  void solve(const std::vector<char>* group_in_region)
  {
    const Heavy& h = *m_heavy;
    const std::size_t ngroups = m_state.group.empty() ? 0 : *std::max_element(m_state.group.begin(), m_state.group.end()) + 1;
    std::vector<std::size_t> node(ngroups, std::size_t(-1));
    std::size_t n = 0;
    for(std::size_t g = 0; g < ngroups; ++g)
      if(group_in_region == nullptr || (*group_in_region)[g]) node[g] = n++;
    Correlation_clustering_graph graph(n);
    for(std::size_t i = 0; i < h.rg.edges.size(); ++i)
    {
      const std::size_t a = node[m_state.group[h.rg.edges[i].first]], b = node[m_state.group[h.rg.edges[i].second]];
      if(a == std::size_t(-1) || b == std::size_t(-1) || a == b) continue;
      double sum = 0;
      for(std::size_t k = h.rg.cross_begin[i]; k < h.rg.cross_begin[i + 1]; ++k) sum += weight(h.rg.cross[k]);
      graph.add_edge(a, b, sum);
    }
    std::vector<std::size_t> lab;
    m_solver(graph, lab);
    CGAL_postcondition(lab.size() == n);
    const bool everything = (group_in_region == nullptr);
    const std::size_t offset = everything ? 0 : m_state.number_of_patches;
    std::vector<std::size_t> labels = everything ? std::vector<std::size_t>(h.os.vertex_segment.size(), 0)
                                                 : m_state.labels;
    for(std::size_t v = 0; v < labels.size(); ++v)
    {
      const std::size_t nd = node[m_state.group[h.os.vertex_segment[v]]];
      if(nd != std::size_t(-1)) labels[v] = offset + lab[nd];
    }
    m_state.number_of_patches = normalize_labels(labels);
    m_state.labels.swap(labels);
  }

  void solve_all() { solve(nullptr); }

  // Runs an edit whose undo record has just been pushed; if it throws (a user solver,
  // memory), the edit is undone before the exception goes on, so the object stays valid.
  template <typename Edit>
  void transaction(Edit edit)
  {
    try { edit(); }
    catch(...)
    {
      restore(std::move(m_undo.back()));
      m_undo.pop_back();
      m_redo.swap(m_discarded_redo);
      --m_recorded; // the edit did not happen
      throw;
    }
    m_discarded_redo.clear();
  }

  void check_face(face_descriptor f) const
  {
    if(f == boost::graph_traits<TriangleMesh>::null_face())
      throw Invalid_input("a face of the edit is the null face");
  }

  // Re-solves the patches in `touched` (given by label; or by `vertex_region` after a
  // sketch, whose segments are new).
  void solve_patches(const std::set<std::size_t>& touched, const std::vector<char>* vertex_region)
  {
    const std::size_t ngroups = *std::max_element(m_state.group.begin(), m_state.group.end()) + 1;
    std::vector<char> in(ngroups, 0);
    const auto& seg = m_heavy->os.vertex_segment;
    for(std::size_t v = 0; v < seg.size(); ++v)
      if(vertex_region != nullptr ? (*vertex_region)[v] != 0 : touched.count(m_state.labels[v]) != 0)
        in[m_state.group[seg[v]]] = 1;
    solve(&in);
  }

  // The input's indexing and crease cut; shared by copies (never changed after
  // construction), so the working mesh that m_data refers to stays where it is. The
  // input is checked and indexed once, here; the working mesh, made from it, is indexed
  // once by the cut; m_data copies the indexing of the mesh it works on.
  struct Working
  {
    std::unique_ptr<internal::Mesh_indexing<TriangleMesh> > input_idx;
    internal::Crease_cut<TriangleMesh> cut;
  };

  template <typename NamedParameters>
  static std::shared_ptr<const Working> make_working(const TriangleMesh& tm, const NamedParameters& np,
                                                     const internal::Segmentation_options& opt)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    auto vpm = internal::vertex_point_map(tm, np);
    auto w = std::make_shared<Working>();
    check_input_mesh(tm, true, CGAL::parameters::vertex_point_map(vpm));
    w->input_idx = std::make_unique<internal::Mesh_indexing<TriangleMesh> >(tm);
    if(opt.crease_angle >= 180) return w;
    typedef typename std::decay<decltype(choose_parameter<CGAL::Sequential_tag>(
      get_parameter(np, internal_np::concurrency_tag)))>::type Concurrency_tag;
    internal::compute_crease_cut(*w->input_idx, vpm, opt.crease_angle, opt.crease_filter_iterations,
                                 opt.tangent_discontinuities, opt.gamma, w->cut,
                                 std::is_convertible<Concurrency_tag, CGAL::Parallel_tag>::value);
    return w;
  }

  const internal::Mesh_indexing<TriangleMesh>& input_indexing() const
  {
    return m_work->cut.is_cut() ? *m_work->input_idx : m_data.idx;
  }
  std::size_t working_vertex(std::size_t input_vertex) const
  {
    return m_work->cut.is_cut() ? m_work->cut.working_vertex[input_vertex] : input_vertex;
  }
  std::size_t working_vertex(vertex_descriptor v) const { return working_vertex(input_indexing().id(v)); }
  face_descriptor working_face(face_descriptor f) const
  {
    return m_work->cut.is_cut() ? m_data.idx.face_at(m_work->input_idx->id(f)) : f;
  }
  std::size_t working_edge(edge_descriptor e) const
  {
    if(!m_work->cut.is_cut()) return m_data.idx.id(e);
    const internal::Mesh_indexing<TriangleMesh>& in = *m_work->input_idx;
    return m_work->cut.working_halfedge[in.halfedge_id(halfedge(e, in.mesh()))] / 2;
  }
  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor working_halfedge_at(std::size_t id) const
  {
    const auto h = halfedge(m_data.idx.edge_at(id / 2), m_data.idx.mesh());
    return (id % 2 == 0) ? h : opposite(h, m_data.idx.mesh());
  }
  // The ties of an input edge, as a range of indices into the weight terms (empty if it
  // is not a crease, or without cut).
  std::pair<std::size_t, std::size_t> ties_of(std::size_t input_edge) const
  {
    if(m_tie_begin.empty()) return { 0, 0 };
    return { m_first_tie + m_tie_begin[input_edge], m_first_tie + m_tie_begin[input_edge + 1] };
  }

  // The precomputation on the working mesh: the user's vertex point map, curvature map,
  // feature edges, feature lines and edge alphas, given for the input mesh, are carried
  // over to its cut copy; then the ties are appended to the weight terms as extra edges
  // of the vertex graph (feature edges with the crease's alpha).
  template <typename NamedParameters>
  void prepare(const TriangleMesh& tm, const NamedParameters& np)
  {
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::get_parameter_reference;
    using CGAL::parameters::is_default_parameter;
    if(!m_work->cut.is_cut())
    {
      internal::prepare_segmentation_data(tm, np, m_opt, m_data, m_lines, false); // checked by make_working
      m_state.alpha_e = internal::edge_alphas(m_data, m_opt, np);
      m_first_tie = m_data.edge_vertices.size();
      count_feature_edges();
      return;
    }
    const TriangleMesh& wm = *m_work->cut.mesh;
    const internal::Crease_cut<TriangleMesh>& cut = m_work->cut;
    // a clean tessellation cut open: its B-rep faces are bounded by the creases and the
    // curvature discontinuities, and crest lines mostly cut its curved faces apart
    // (crest_lines_on_clean_tessellations(false) leaves them out)
    internal::Segmentation_options opt = m_opt;
    opt.detect_crest_lines = !cut.clean || m_opt.crest_lines_on_clean_tessellations;
    const internal::Mesh_indexing<TriangleMesh>& in = *m_work->input_idx;
    const internal::Mesh_indexing<TriangleMesh>& wi = m_data.idx;
    auto wvpm = get_const_property_map(CGAL::vertex_point, wm);
    const Named_function_parameters<decltype(wvpm), CGAL::internal_np::vertex_point_t, NamedParameters> np1(wvpm, np);

    auto with_lines = [&](const auto& np3) {
      typedef std::decay_t<decltype(np3)> NP3;
      if constexpr(is_default_parameter<NamedParameters, internal_np::feature_lines_t>::value)
        internal::prepare_segmentation_data(wm, np3, opt, m_data, m_lines, false); // made from the checked input
      else
      {
        Feature_lines<TriangleMesh> lines = get_parameter_reference(np, internal_np::feature_lines);
        for(auto& l : lines.lines)
          for(auto& p : l.points)
            p.halfedge = working_halfedge_at(cut.working_halfedge[in.halfedge_id(p.halfedge)]);
        const Named_function_parameters<Feature_lines<TriangleMesh>, internal_np::feature_lines_t, NP3> np4(lines, np3);
        internal::prepare_segmentation_data(wm, np4, opt, m_data, m_lines, false);
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
    std::vector<double> alpha_e = m_data.default_alpha(m_opt.alpha);
    auto user_alpha = [&](std::size_t input_edge) {
      if constexpr(is_default_parameter<NamedParameters, internal_np::edge_alpha_t>::value)
        return m_opt.alpha;
      else
      {
        const double a = get(get_parameter(np, internal_np::edge_alpha), in.edge_at(input_edge));
        if(!std::isfinite(a)) throw Invalid_input("edge_alpha_map holds a value that is not a finite number");
        return a;
      }
    };
    if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_alpha_t>::value)
      for(std::size_t e = 0; e < alpha_e.size(); ++e) alpha_e[e] = user_alpha(cut.input_edge[e]);
    m_first_tie = m_data.edge_vertices.size();
    m_tie_begin.assign(in.number_of_edges() + 1, 0);
    for(const internal::Crease_tie& t : cut.ties) ++m_tie_begin[t.crease_edge + 1];
    for(std::size_t e = 0; e < in.number_of_edges(); ++e) m_tie_begin[e + 1] += m_tie_begin[e];
    for(const internal::Crease_tie& t : cut.ties) // in crease-edge order
    {
      m_data.edge_vertices.emplace_back(t.a, t.b);
      m_data.terms.similarity.push_back(t.similarity);
      m_data.terms.award.push_back(t.award);
      m_data.is_feature_edge.push_back(1);
      alpha_e.push_back(user_alpha(t.crease_edge));
    }
    count_feature_edges();
    m_state.alpha_e.swap(alpha_e);
  }

  // The feature edges: those of the working mesh (lines, user, sketches) and the creases
  // (each counted once, not per tie).
  void count_feature_edges()
  {
    m_data.number_of_feature_edges =
      std::size_t(std::count(m_data.is_feature_edge.begin(), m_data.is_feature_edge.begin() + m_first_tie, 1)) +
      m_work->cut.number_of_creases;
  }

  internal::Segmentation_options m_opt;
  std::shared_ptr<const Working> m_work;
  internal::Segmentation_data<TriangleMesh> m_data;
  std::size_t m_first_tie = 0;           // index of the first tie in the weight terms
  std::vector<std::size_t> m_tie_begin;  // per input edge: its ties, CSR (empty without cut)
  Feature_lines<TriangleMesh> m_lines;
  bool m_anisotropic = true, m_reduced = true;
  std::function<std::size_t(const Correlation_clustering_graph&, std::vector<std::size_t>&)> m_solver;
  State m_state;
  std::shared_ptr<Heavy> m_heavy;
  std::vector<Undo_record> m_undo;
  std::vector<Undo_record> m_redo;
  std::vector<Undo_record> m_discarded_redo; // m_redo while an edit runs, kept in case it fails
  std::size_t m_recorded = 0;
};

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_FEATURE_ALIGNED_SEGMENTATION_H
