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
#include <CGAL/Feature_segmentation/internal/boundary_refinement_impl.h>
#include <CGAL/Feature_segmentation/internal/editing_engine.h>

#include <cmath>
#include <string>
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
/// | `set_alpha()` (global refine/coarsen) | the weights of G', the clustering of G' | the weights of G' (C) + a solve on G' |
/// | `add_to_alpha()`, `multiply_alpha()` (local) | the same, the clustering on the patches the region touches only | the region's edges + O(C) + a solve on those patches |
/// | `merge_patches()` | the patches (a constraint that later solves keep) | O(N) |
/// | `add_sketch()` | terms of the faces around the sketch, the oversegmentation inside the patches it touches, G', their clustering | O(F_p log F_p) for the F_p faces of those patches + O(E + F + V + C log C) + solve on those patches |
/// | `undo()`, `redo()` | nothing: moves along the history of states | O(1) |
///
/// E, F, V are the mesh's edges, faces and vertices, N the nodes of G' (oversegments),
/// C the mesh edges between two oversegments, whose weights sum to those of G'; G' is
/// much smaller than the mesh (6,453 nodes and 18,374 edges on rockerarm remeshed to
/// 196,566 faces, against 98,283 vertices and 294,849 edges). No edit but a sketch
/// visits every vertex or every edge of the mesh: the patches are kept per oversegment
/// (a vertex's patch is its oversegment's, read when asked: `patch()`,
/// `vertex_patches()`, `face_patches()`), and the `alpha_e` of the feature edges follow
/// alpha without being rewritten (a local edit writes those of its region only, copying
/// the chunks of 4096 edges it writes into and the table of chunks, one pointer per
/// 4096 edges).
///
/// Each edit makes a new state that shares with the one before every part the edit leaves
/// alone (a global alpha edit: everything but one patch id per oversegment; a local edit
/// also the chunks of per-edge parameters it writes; a merge the merge groups and the
/// patch ids; a sketch also the feature terms and G');
/// the history of states is bounded by memory (`set_undo_memory_limit()`), not by a
/// number of edits, and undo and redo are exact. A copy of the object shares the
/// precomputation and the states (it is cheap), and edits each copy on its own.
///
/// On a rough mesh (not a clean tessellation) with creases looked for, every solve (the
/// constructor's and each edit's) ends by joining each patch of at most ten vertices into
/// a neighbouring patch, as `segment_along_features()` does; a sketch or a local refine
/// on such a mesh cannot cut out a piece of fewer vertices.
///
/// A vertex that no face uses (isolated) is a patch of its own. If an edit throws (a
/// user solver, memory), nothing has changed: the new state is published only once
/// complete.
/// Local edits and sketches re-solve only the current patches they touch, so the other
/// patches keep their vertices (their ids may change: ids are renumbered in vertex order
/// after each edit).
///
/// \tparam TriangleMesh a model of `FaceListGraph`; the mesh must outlive the object and
///         stay unchanged.
template <typename TriangleMesh>
class Feature_aligned_segmentation
{
  typedef internal::Editing_engine<TriangleMesh> Engine;

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
  /// The seconds (wall clock) of each stage of the construction and of the last solve,
  /// for benchmarks and reports: `mesh_check_and_indexing`, `creases`, `curvature`,
  /// `feature_lines`, `weight_terms`, `oversegmentation` (of the construction, or of the
  /// last sketch), then of the last solve `graph` (the weights of G'), `solve` (the
  /// solver) and `labels` (the patch ids of the oversegments, numbered in vertex order),
  /// and `last_edit` (the whole last edit).
  typedef internal::Stage_times Stage_times;
  /// @}

  /// Precomputes and solves. The named parameters are those of
  /// `segment_along_features()` except the outputs (`face_patch_map`, `cut_cost_output`);
  /// the solver is kept for every later solve. `segment_along_features()` also says what
  /// each does with a value out of range.
  /// \param tm the mesh
  /// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{alpha} \cgalParamDescription{the global parameter \f$ \alpha \f$, the \f$
  ///   \alpha_e \f$ of the feature edges; useful range 0.5 to 1.0, larger values give more patches}
  ///   \cgalParamType{`double`, finite} \cgalParamDefault{`default_alpha` (0.6)} \cgalParamNEnd
  ///   \cgalParamNBegin{gamma} \cgalParamDescription{the anisotropy \f$ \gamma \f$ of the curvature
  ///   metric (Eq. 6), whose eigenvalues are 1 and \f$ 1/(1 + \gamma s)^2 \f$ with \f$ s = \vert
  ///   k_1 \vert - \vert k_2 \vert \f$, the curvatures being those of the mesh scaled to a largest
  ///   bounding-box side of 1} \cgalParamType{`double`, at least 0}
  ///   \cgalParamDefault{`default_gamma` (0.05)} \cgalParamNEnd
  ///   \cgalParamNBegin{edge_alpha_map} \cgalParamDescription{the \f$ \alpha_e \f$ of every edge,
  ///   overriding `alpha`} \cgalParamType{a class model of `ReadablePropertyMap` with
  ///   `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `double` (finite) as
  ///   value type} \cgalParamDefault{`alpha` on feature edges, 0 elsewhere} \cgalParamNEnd
  ///   \cgalParamNBegin{crease_angle} \cgalParamDescription{the edges whose faces bend by at least
  ///   this angle (in degrees) are creases: the segmentation runs on the mesh cut open along them;
  ///   180 or more: no creases (the paper's pipeline)} \cgalParamType{`double`, above 0}
  ///   \cgalParamDefault{`default_crease_angle` (20)} \cgalParamNEnd
  ///   \cgalParamNBegin{crease_filter_iterations} \cgalParamDescription{the rounds of bilateral
  ///   filtering of the face normals before the creases are found: none on a clean mesh, until the
  ///   normals are smooth (at most 10 rounds) on a smooth model, on a noisy one from 5 to all of
  ///   them as the noise grows; 0: the raw
  ///   dihedral angles} \cgalParamType{an integer type, 0 to 1000}
  ///   \cgalParamDefault{`default_crease_filter_iterations` (40)} \cgalParamNEnd
  ///   \cgalParamNBegin{tangent_discontinuities} \cgalParamDescription{whether, on a clean
  ///   tessellation of a CAD part, the curvature discontinuities (where a fillet meets a plane or a
  ///   wider curved face without a crease angle) join the creases, and seam lines (where two curved
  ///   faces meet and the smaller principal curvature steps) join the crest lines; on a noisy mesh,
  ///   or a rough one whose planes hold a fifth of its area, the borders of its planes (where a
  ///   plane meets a fillet or a curved face) join the creases, and so do the seams between
  ///   the pieces of its bent pipes (a cylinder running into a torus); on every rough mesh
  ///   (noisy or smooth) so do the seams between the pieces of its surfaces of revolution (a
  ///   cone running into a torus), and the creases that noise leaves inside one piece go}
  ///   \cgalParamType{`bool`}
  ///   \cgalParamDefault{`default_tangent_discontinuities` (`true`)} \cgalParamNEnd
  ///   \cgalParamNBegin{crest_lines_on_clean_tessellations} \cgalParamDescription{whether the crest
  ///   lines of a tessellation of a CAD part (a clean one, a noisy one, or one its creases cut
  ///   into pieces) get the full \f$ \alpha \f$ (the paper's features); if not, their
  ///   \f$ \alpha_e \f$ is \f$ \alpha \f$ minus 0.5, so that the creases and the curvature
  ///   discontinuities bound the patches}
  ///   \cgalParamType{`bool`} \cgalParamDefault{`default_crest_lines_on_clean_tessellations`
  ///   (`false`)} \cgalParamNEnd
  ///   \cgalParamNBegin{principal_curvature_map} \cgalParamDescription{the principal curvatures of
  ///   the vertices, used instead of estimating them} \cgalParamType{a class model of
  ///   `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key
  ///   type and `Principal_curvatures<GeomTraits>` as value type} \cgalParamDefault{estimated as by
  ///   `estimate_principal_curvatures()`, with `neighborhood_rings`, `neighborhood_radius` and
  ///   `concurrency_tag`} \cgalParamNEnd
  ///   \cgalParamNBegin{feature_lines} \cgalParamDescription{the feature lines to follow (e.g. the
  ///   user's), whose points place the dual vertices} \cgalParamType{`Feature_lines<TriangleMesh>`}
  ///   \cgalParamDefault{the detected crest lines (with `strength_threshold`, `umbilic_ratio`,
  ///   `detect_ridges` and `detect_valleys`)} \cgalParamNEnd
  ///   \cgalParamNBegin{edge_is_feature_map} \cgalParamDescription{the feature edges: with
  ///   `feature_lines`, the features are the union of these edges and the edges the lines cross;
  ///   alone, no crest lines are detected and a feature edge contributes its midpoint}
  ///   \cgalParamType{a class model of `ReadablePropertyMap` with
  ///   `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `bool` as value type}
  ///   \cgalParamDefault{the edges of the lines (those that `feature_lines`, or else the detected
  ///   crest lines, cross)} \cgalParamNEnd
  ///   \cgalParamNBegin{strength_threshold} \cgalParamDescription{the crest lines whose strength
  ///   (the integral of \f$ \vert k \vert \f$ along the line) is below it are dropped}
  ///   \cgalParamType{`double`, at least 0} \cgalParamDefault{`default_strength_threshold` (1.0)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{umbilic_ratio} \cgalParamDescription{the zero crossings near umbilics,
  ///   where \f$ \vert k \vert - \vert k_{other} \vert \leq \f$ `umbilic_ratio` \f$ \cdot \vert k
  ///   \vert \f$, are dropped: there the principal directions are noise} \cgalParamType{`double` in
  ///   [0, 1)} \cgalParamDefault{`0.1`} \cgalParamNEnd
  ///   \cgalParamNBegin{detect_ridges} \cgalParamDescription{whether ridges (maxima of `k_max`
  ///   along its direction) are detected} \cgalParamType{`bool`} \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{detect_valleys} \cgalParamDescription{whether valleys (minima of `k_min`
  ///   along its direction) are detected} \cgalParamType{`bool`} \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{neighborhood_rings} \cgalParamDescription{the number of rings of neighbours
  ///   of a vertex that the curvature fit takes: the scale of the features on coarse meshes}
  ///   \cgalParamType{an integer type, at least 1} \cgalParamDefault{`2`} \cgalParamNEnd
  ///   \cgalParamNBegin{neighborhood_radius} \cgalParamDescription{beyond the rings, the curvature
  ///   fit also takes the vertices within this fraction of the bounding-box diagonal whose normals
  ///   are within 30 degrees of the vertex normal: the scale of the features on fine meshes; 0:
  ///   rings only} \cgalParamType{`double` in [0, 1]}
  ///   \cgalParamDefault{`default_neighborhood_radius` (0.01)} \cgalParamNEnd
  ///   \cgalParamNBegin{concurrency_tag} \cgalParamDescription{a tag indicating whether the
  ///   curvature fits, the crease detection (the rounds of the normal filter, the gap test), the
  ///   terms of the edge weights and the default solver's Kernighan-Lin rounds run sequentially
  ///   or on TBB's threads (with the same results)}
  ///   \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
  ///   `CGAL::Parallel_if_available_tag`} \cgalParamDefault{`CGAL::Sequential_tag`} \cgalParamNEnd
  ///   \cgalParamNBegin{solver} \cgalParamDescription{the correlation clustering solver, stored by
  ///   copy} \cgalParamType{a model of `CorrelationClusteringSolver`}
  ///   \cgalParamDefault{`Default_correlation_clustering_solver` (GAEC followed by Kernighan-Lin
  ///   with joins)} \cgalParamNEnd
  ///   \cgalParamNBegin{use_oversegmentation} \cgalParamDescription{whether the clustering is
  ///   solved on the reduced graph G' of the watershed oversegmentation (`true`) or on the full
  ///   vertex graph} \cgalParamType{`bool`} \cgalParamDefault{`true`} \cgalParamNEnd
  ///   \cgalParamNBegin{watershed_distance} \cgalParamDescription{the distance whose watershed
  ///   makes the oversegmentation: anisotropic (dual edges of length Similarity(e)) or geodesic (of
  ///   length Award(e))} \cgalParamType{`Watershed_distance`}
  ///   \cgalParamDefault{`Watershed_distance::ANISOTROPIC`} \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map} \cgalParamDescription{a property map associating points
  ///   to the vertices of `tm`} \cgalParamType{a class model of `ReadablePropertyMap` with
  ///   `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as value
  ///   type} \cgalParamDefault{`get(CGAL::vertex_point, tm)`} \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits} \cgalParamDescription{an instance of a geometric traits class}
  ///   \cgalParamType{a class model of `Kernel`} \cgalParamDefault{the kernel of the point type,
  ///   deduced with `CGAL::Kernel_traits`} \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws Invalid_input on a bad mesh or a bad option value
  /// \pre the edits' faces are faces of the mesh (the null face throws `Invalid_input`)
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Feature_aligned_segmentation(const TriangleMesh& tm,
                                        const NamedParameters& np = CGAL::parameters::default_values())
    : m_engine(tm, np)
  {}

  /// \name Results
  /// @{

  /// The number of patches.
  std::size_t number_of_patches() const { return state().number_of_patches; }
  /// The patch of a vertex, in `0 .. number_of_patches()-1`. A vertex on a crease has a
  /// copy on each side of it in `working_mesh()`; this is the patch of the copy in the
  /// sector of its first face (`face_patches()` is exact along creases).
  std::size_t patch(vertex_descriptor v) const { return state().vertex_patch(pre().working_vertex(v)); }
  /// The patch of a face: the patch that covers most of its area under the boundaries of
  /// the current patches as `patch_boundaries()` gives them (unsmoothed), ties to the
  /// smallest id; the rule of `majority_face_patches()` and `face_patches(b, map)`,
  /// computed on the face alone. A face whose corners are in one patch is in that patch.
  /// A face next to a crease has its corners on its own side of the crease, so it never
  /// takes the patch across the crease.
  std::size_t patch(face_descriptor f) const
  {
    Engine::check_face(f);
    return m_engine.face_patch(state(), pre().working_indexing().id(pre().working_face(f)));
  }
  /// Writes the patch of every vertex (as `patch(vertex_descriptor)`) into a
  /// `WritablePropertyMap` from `vertex_descriptor`.
  template <typename VertexPatchMap>
  void vertex_patches(VertexPatchMap map) const
  {
    const internal::Edit_state& s = state();
    write_vertex_patches(map, [&s](std::size_t w) { return s.vertex_patch(w); });
  }
  /// Writes the patch of every face (as `patch(face_descriptor)`) into a
  /// `WritablePropertyMap` from `face_descriptor`. The patches are computed by TBB's
  /// threads when the class was built with `concurrency_tag(CGAL::Parallel_tag)` (the same
  /// patches at any thread count);
  /// the map is written by the calling thread.
  template <typename FacePatchMap>
  void face_patches(FacePatchMap map) const
  {
    typedef typename boost::property_traits<FacePatchMap>::value_type Id;
    const internal::Mesh_indexing<TriangleMesh>& in = pre().input_indexing();
    const std::vector<std::size_t> patch = m_engine.face_patches(state()); // working face f is input face f
    for(std::size_t f = 0; f < in.number_of_faces(); ++f)
      put(map, in.face_at(f), static_cast<Id>(patch[f]));
  }
  /// Writes the patch of every face as the boundaries `b` cut it: the patch covering most
  /// of its area (`majority_face_patches()`), into a `WritablePropertyMap` from
  /// `face_descriptor`. With `b` smoothed (`smooth_patch_boundaries()`), these are the
  /// patches of the final boundaries: a face the smoothed boundary leaves to one side
  /// takes that side, to within half a triangle. With `b` as `patch_boundaries()` gives
  /// it, they are those of `face_patches(map)`. Along a crease every face keeps its own
  /// side.
  /// \pre `b` was made by `patch_boundaries()` of this object in its current state
  template <typename FacePatchMap>
  void face_patches(const Patch_boundaries<TriangleMesh>& b, FacePatchMap map) const
  {
    CGAL_precondition(&b.mesh() == &working_mesh() &&
                      b.state().number_of_faces() == pre().working_indexing().number_of_faces());
    typedef typename boost::property_traits<FacePatchMap>::value_type Id;
    const internal::Mesh_indexing<TriangleMesh>& in = pre().input_indexing();
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
                      b.state().number_of_vertices() == pre().working_indexing().number_of_vertices());
    write_vertex_patches(map, [&b](std::size_t w) { return b.state().labels[w]; });
  }
  /// The cut cost (Eq. 1) of the current segmentation under the current weights (the
  /// crease ties included).
  double cut_cost() const
  {
    // the cut edges are the edges of G' between oversegments of two patches
    const internal::Edit_state& s = state();
    const internal::Reduced_graph& rg = s.reduction->rg;
    double cost = 0;
    for(std::size_t i = 0; i < rg.edges.size(); ++i)
      if((*s.segment_patch)[rg.edges[i].first] != (*s.segment_patch)[rg.edges[i].second])
        for(std::size_t k = rg.cross_begin[i]; k < rg.cross_begin[i + 1]; ++k) cost += s.weight(rg.cross[k]);
    return cost;
  }
  /// The global parameter alpha.
  double alpha() const { return state().alpha; }
  /// The parameter `alpha_e` of an edge (of a crease: that of its ties).
  double alpha(edge_descriptor e) const
  {
    const auto t = pre().ties_of(pre().input_indexing().id(e));
    return state().alpha_of(t.first != t.second ? t.first : pre().working_edge(e));
  }
  /// The weight `w(e) = Similarity(e) - alpha_e Award(e)` of an edge; of a crease edge,
  /// the weight of cutting along it (its two ties).
  double weight(edge_descriptor e) const
  {
    const auto t = pre().ties_of(pre().input_indexing().id(e));
    if(t.first == t.second) return state().weight(pre().working_edge(e));
    double w = 0;
    for(std::size_t i = t.first; i < t.second; ++i) w += state().weight(i);
    return w;
  }
  /// Whether an edge is a feature edge (a crease, or from the feature lines, the user or
  /// a sketch).
  bool is_feature_edge(edge_descriptor e) const
  {
    return is_crease_edge(e) || state().features->is_feature_edge[pre().working_edge(e)] != 0;
  }
  /// Whether an edge is a crease: its dihedral angle is at least `crease_angle`, or it is
  /// a curvature discontinuity (`is_curvature_discontinuity_edge()`), and it separates
  /// faces at one of its ends at least (a lone edge, whose two ends lie inside the
  /// surface, cuts nothing and is not a crease).
  bool is_crease_edge(edge_descriptor e) const { return pre().is_crease_edge(e); }
  /// Whether an edge is a crease found as a curvature discontinuity of a clean CAD
  /// tessellation (a seam where a fillet meets a plane without a crease angle; named
  /// parameter `tangent_discontinuities`) rather than by its dihedral angle.
  bool is_curvature_discontinuity_edge(edge_descriptor e) const { return pre().is_curvature_discontinuity_edge(e); }
  /// The number of feature edges: the creases and the edges of `working_mesh()` that
  /// the feature lines cross.
  std::size_t number_of_feature_edges() const { return state().features->number_of_feature_edges; }
  /// The number of crease edges.
  std::size_t number_of_crease_edges() const { return pre().cut.number_of_creases; }
  /// The mesh the segmentation works on: the input mesh, or when it has creases, a copy
  /// of it cut open along them (a vertex on a crease has one copy per side; the faces are
  /// those of the input, in the same order). `feature_lines()` and `patch_boundaries()`
  /// live on it; the patch boundaries along creases are borders of it, not curves.
  const TriangleMesh& working_mesh() const { return pre().working_mesh(); }
  /// The feature lines (detected or given) on `working_mesh()`, without the sketches and
  /// without the creases.
  const Feature_lines<TriangleMesh>& feature_lines() const { return pre().lines; }
  /// The boundaries between the current patches as curves on the surface, carrying the
  /// anisotropic metric of the weights, ready for `smooth_patch_boundaries()` and for the
  /// per-face patches of `face_patches.h`, on `working_mesh()`. Built from this object's
  /// precomputation (no curvature or feature recomputed); the result must not outlive
  /// this object.
  Patch_boundaries<TriangleMesh> patch_boundaries() const
  {
    return internal::make_patch_boundaries(*pre().data, *state().features, state().vertex_patches());
  }
  /// The number of oversegments (nodes of G').
  std::size_t number_of_oversegments() const { return state().reduction->os.number_of_segments; }
  /// The seconds of each stage of the construction and of the last edit (see `Stage_times`).
  const Stage_times& stage_times() const { return m_engine.stage_times(); }
  /// @}

  /// \name Edits
  /// Each returns the new number of patches.
  /// @{

  /// Global refinement (larger `a`) or coarsening: sets alpha to `a`. The `alpha_e` of
  /// every feature edge moves by `a - alpha()`, so local edits made before are kept as
  /// offsets (the authors' tool does the same). A feature edge's `alpha_e` is kept as
  /// its value at the construction's alpha, so setting alpha back to an earlier value
  /// gives back the same weights to the last bit.
  std::size_t set_alpha(double a)
  {
    if(!std::isfinite(a)) throw Invalid_input("alpha must be a finite number");
    return m_engine.set_alpha(a);
  }

  /// Local refinement (`delta > 0`) or coarsening (`delta < 0`): adds `delta` to the
  /// `alpha_e` of the feature edges of `faces` (a painted region), then re-solves the
  /// patches that the region touches.
  /// \tparam FaceRange a range of `face_descriptor`
  template <typename FaceRange>
  std::size_t add_to_alpha(const FaceRange& faces, double delta)
  {
    if(!std::isfinite(delta)) throw Invalid_input("the alpha increment must be a finite number");
    return m_engine.edit_region(faces, [delta](double a) { return a + delta; });
  }

  /// Local refinement or coarsening by a factor: multiplies the `alpha_e` of the feature
  /// edges of `faces` by `factor` (>= 0), then re-solves the patches the region touches.
  template <typename FaceRange>
  std::size_t multiply_alpha(const FaceRange& faces, double factor)
  {
    if(!(factor >= 0) || !std::isfinite(factor)) throw Invalid_input("the alpha factor must be a finite number >= 0");
    return m_engine.edit_region(faces, [factor](double a) { return a * factor; });
  }

  /// Merging: the patches that contain a vertex of `faces` become one patch, and stay
  /// together in later solves (until undone, or until a sketch redoes their region).
  template <typename FaceRange>
  std::size_t merge_patches(const FaceRange& faces)
  {
    return m_engine.merge_patches(faces);
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
  std::size_t add_sketch(const std::vector<Sketch_point>& sketch, double sketch_alpha = default_sketch_alpha)
  {
    if(!(sketch_alpha > 1) || !std::isfinite(sketch_alpha))
      throw Invalid_input("sketch_alpha must be a finite number > 1 (got " + std::to_string(sketch_alpha) + ")");
    if(sketch.size() < 2) return number_of_patches();
    const internal::Segmentation_data<TriangleMesh>& d = *pre().data;
    std::vector<internal::Sketch_input> in;
    for(const Sketch_point& sp : sketch)
    {
      const auto& p = sp.point;
      const Eigen::Vector3d q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      if(!q.allFinite()) throw Invalid_input("a sketch point has a NaN or infinite coordinate");
      Engine::check_face(sp.face);
      in.push_back({ d.idx.id(pre().working_face(sp.face)), q });
      // a point far from its face is a caller's mistake, and would make the walk endless
      if(internal::distance_to_face(d, in.back()) > 0.01 * d.diagonal)
        throw Invalid_input("a sketch point lies farther than 1% of the bounding-box diagonal from its face");
    }
    return m_engine.add_sketch(in, sketch_alpha);
  }
  /// @}

  /// \name History
  /// Every edit that changes something records a state; `undo()` and `redo()` move along
  /// them.
  /// @{

  /// Takes back the last edit, restoring its state exactly (no solve runs). Returns
  /// `false` when there is nothing to undo (no edit yet, or the older states were dropped
  /// to keep the history within `undo_memory_limit()`). The edit taken back can be made
  /// again with `redo()`.
  bool undo() { return m_engine.undo(); }
  /// Makes again the last edit taken back by `undo()`, restoring its result exactly
  /// (no solve runs). Returns `false` when there is nothing to redo.
  bool redo() { return m_engine.redo(); }
  /// The number of edits that `undo()` can take back.
  std::size_t number_of_undoable_edits() const { return history().number_of_undoable_edits(); }
  /// The number of undone edits that `redo()` can make again: every `undo()` adds one,
  /// every `redo()` takes one, and any other edit that records a state clears them.
  std::size_t number_of_redoable_edits() const { return history().number_of_redoable_edits(); }
  /// The number of edits recorded since construction, including those dropped from the
  /// history and those already undone: an edit that changed nothing (an empty region, a
  /// merge inside one patch) records none, so comparing this number before and after an
  /// edit tells whether `undo()` would take it back.
  std::size_t number_of_recorded_edits() const { return history().number_of_recorded_edits(); }
  /// The bytes that the history holds besides the current state: the parts of earlier
  /// (and undone) states that the current state does not share.
  std::size_t undo_memory() const { return history().memory(); }
  /// The most bytes `undo_memory()` may reach (default 256 MiB): after an edit, the
  /// oldest states are dropped until it fits, except that the state before the current
  /// one is always kept, so the last edit can always be undone.
  std::size_t undo_memory_limit() const { return history().memory_limit(); }
  /// Sets `undo_memory_limit()` and drops the states beyond it (undone states first).
  void set_undo_memory_limit(std::size_t bytes) { m_engine.history().set_memory_limit(bytes); }
  /// @}

private:
  const internal::Edit_precomputation<TriangleMesh>& pre() const { return m_engine.precomputation(); }
  const internal::Edit_state& state() const { return m_engine.state(); }
  const internal::Edit_history& history() const { return m_engine.history(); }

  // Writes patch_of(w) for the working vertex w of every input vertex.
  template <typename VertexPatchMap, typename PatchOf>
  void write_vertex_patches(VertexPatchMap map, const PatchOf& patch_of) const
  {
    typedef typename boost::property_traits<VertexPatchMap>::value_type Id;
    const internal::Mesh_indexing<TriangleMesh>& in = pre().input_indexing();
    for(std::size_t v = 0; v < in.number_of_vertices(); ++v)
      put(map, in.vertex_at(v), static_cast<Id>(patch_of(pre().working_vertex(v))));
  }

  Engine m_engine;
};

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_FEATURE_ALIGNED_SEGMENTATION_H
