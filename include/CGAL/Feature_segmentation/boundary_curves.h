// SPDX-License-Identifier: GPL-3.0-or-later
// The boundaries of a vertex labelling as curves on the surface (paper, Section 3.1 and
// Fig. 3(c)): polylines through the dual vertices of the triangles and the points where
// they cross the cut edges, split at junctions and at the mesh border, each with the two
// patches on its sides. The same structure is what smooth_boundaries.h smooths and what
// face_patches.h turns into per-face patches.

#ifndef CGAL_FEATURE_SEGMENTATION_BOUNDARY_CURVES_H
#define CGAL_FEATURE_SEGMENTATION_BOUNDARY_CURVES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/internal/boundary_state.h>
#include <CGAL/Feature_segmentation/internal/prepare_segmentation_data.h>

#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationBoundaries
/// How a boundary curve ends.
enum class Boundary_end
{
  JUNCTION, ///< in a triangle whose three vertices lie in three different patches
  BORDER,   ///< on a border edge of the mesh
  CLOSED    ///< the curve is closed (both ends of a closed curve have this type)
};

/// \ingroup PkgFeatureSegmentationBoundaries
/// A point of a boundary curve, located on the surface of the mesh.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
template <typename TriangleMesh>
struct Boundary_point
{
  /// the halfedge type of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  /// The face holding the point and its barycentric coordinates, with CGAL's convention
  /// (`Polygon_mesh_processing::construct_point()` turns it into a point): the first
  /// coordinate goes with `source(halfedge(f, tm), tm)`, the second with
  /// `target(halfedge(f, tm), tm)`, the third with `target(next(halfedge(f, tm), tm), tm)`.
  Polygon_mesh_processing::Face_location<TriangleMesh, double> location;
  /// For a point on an edge (where a curve crosses a cut edge, or ends on the border):
  /// the halfedge of that edge whose face is `location.first`; otherwise
  /// `boost::graph_traits<TriangleMesh>::null_halfedge()`.
  halfedge_descriptor halfedge = boost::graph_traits<TriangleMesh>::null_halfedge();
  /// For a point on an edge: its position `(1 - t) source(halfedge) + t target(halfedge)`,
  /// with `0 < t < 1`; `0` otherwise.
  double t = 0;
  /// The point's Cartesian coordinates (as doubles).
  std::array<double, 3> point = { { 0., 0., 0. } };

  /// Whether the point lies on an edge.
  bool is_on_edge() const { return halfedge != boost::graph_traits<TriangleMesh>::null_halfedge(); }
};

/// \ingroup PkgFeatureSegmentationBoundaries
/// One boundary curve: a polyline on the surface between two patches.
///
/// The points alternate between a point inside a triangle and a point on an edge that
/// the curve crosses. A curve that ends at a junction starts or ends with the junction's
/// point inside its triangle; one that ends on the border, with a point on a border edge.
/// A closed curve starts on an edge and does not repeat its first point at the end.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
template <typename TriangleMesh>
struct Boundary_curve
{
  /// the points, in order along the curve
  std::vector<Boundary_point<TriangleMesh> > points;
  /// The patch on the left of the curve (walking along it, the surface's normal up;
  /// faces are counterclockwise seen from that side).
  std::size_t left_patch = 0;
  /// the patch on the right of the curve
  std::size_t right_patch = 0;
  /// how the curve starts
  Boundary_end front = Boundary_end::CLOSED;
  /// how the curve ends
  Boundary_end back = Boundary_end::CLOSED;

  /// Whether the curve is closed.
  bool is_closed() const { return front == Boundary_end::CLOSED; }

  /// The Euclidean length of the polyline (with the closing segment of a closed curve).
  double length() const
  {
    double s = 0;
    const std::size_t n = points.size();
    for(std::size_t i = 0; i + 1 < n + (is_closed() ? 1 : 0); ++i)
    {
      const auto &a = points[i].point, &b = points[(i + 1) % n].point;
      s += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
    return s;
  }
};

/// \ingroup PkgFeatureSegmentationBoundaries
/// The boundaries between the patches of a vertex labelling: curves on the surface, and
/// the per-triangle anisotropic metric of the edge weights in which they are measured
/// and smoothed.
///
/// The boundary of a labelling is the dual of its cut edges (the edges whose two
/// vertices lie in different patches; paper, Fig. 3(c)). A triangle whose vertices lie in
/// two patches has two cut edges, and the boundary passes through it; one whose vertices
/// lie in three patches has three, and it is a junction. The boundary inside a triangle
/// joins the triangle's point (initially its dual vertex, as defined by the weights) to a
/// point on each of its cut edges. The curves are the maximal pieces of this network
/// between junctions and border edges; pieces without such ends are closed curves.
///
/// Objects are made by `compute_patch_boundaries()`, changed by
/// `smooth_patch_boundaries()` and read by `majority_face_patches()` and
/// `refine_mesh_along_boundaries()`. They keep a pointer to the mesh, which must outlive
/// them and not change.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
template <typename TriangleMesh>
class Patch_boundaries
{
public:
  /// a point of a curve
  typedef Boundary_point<TriangleMesh> Point;
  /// a curve
  typedef Boundary_curve<TriangleMesh> Curve;

  /// \cond SKIP_IN_MANUAL
  typedef internal::Boundary_state<TriangleMesh> State;
  explicit Patch_boundaries(State state) : m_state(std::move(state)) { update(); }
  State& state() { return m_state; }
  const State& state() const { return m_state; }
  // Rebuilds the curves after the state changed.
  void update()
  {
    const TriangleMesh& tm = m_state.mesh();
    m_curves.clear();
    for(const internal::Boundary_path& p : m_state.paths())
    {
      Curve c;
      c.left_patch = p.left;
      c.right_patch = p.right;
      c.front = end_type(p.front);
      c.back = end_type(p.back);
      for(const auto& n : p.nodes)
      {
        Point q;
        typename State::Vec3 x;
        if(n.on_edge)
        {
          const auto h0 = m_state.edge_halfedge[n.id];
          q.halfedge = (n.halfedge == 0) ? h0 : opposite(h0, tm);
          q.t = (n.halfedge == 0) ? m_state.edge_t[n.id] : 1 - m_state.edge_t[n.id];
          const std::size_t f = m_state.edge_faces[n.id][n.halfedge];
          CGAL_assertion(f != State::npos);
          const std::size_t s = m_state.edge_vertices[n.id][n.halfedge], t = m_state.edge_vertices[n.id][1 - n.halfedge];
          std::array<double, 3> w = { 0., 0., 0. };
          for(int k = 0; k < 3; ++k)
          {
            if(m_state.face_vertices[f][k] == s) w[k] = 1 - q.t;
            if(m_state.face_vertices[f][k] == t) w[k] = q.t;
          }
          q.location = { m_state.face_list[f], w };
          x = m_state.edge_point(n.id);
        }
        else
        {
          x = m_state.face_x[n.id];
          q.location = { m_state.face_list[n.id], m_state.barycentric(n.id, x) };
        }
        q.point = { x.x(), x.y(), x.z() };
        c.points.push_back(q);
      }
      m_curves.push_back(c);
    }
  }
  /// \endcond

  /// The curves, in a deterministic order: first those that start at junctions (by
  /// face), then those that start on the border (by edge), then the closed ones.
  const std::vector<Curve>& curves() const { return m_curves; }

  /// The number of distinct patch ids among the vertices.
  std::size_t number_of_patches() const
  {
    std::vector<std::size_t> ids = m_state.labels;
    std::sort(ids.begin(), ids.end());
    return std::size_t(std::unique(ids.begin(), ids.end()) - ids.begin());
  }

  /// The number of junctions (triangles whose vertices lie in three patches).
  std::size_t number_of_junctions() const
  {
    std::size_t n = 0;
    std::array<std::size_t, 3> c;
    for(std::size_t f = 0; f < m_state.number_of_faces(); ++f)
      if(m_state.cut_edges(f, c) == 3) ++n;
    return n;
  }

  /// The pairs of adjacent patches `(i, j)`, `i < j`, sorted: the pairs of patches that
  /// share a curve.
  std::vector<std::pair<std::size_t, std::size_t> > adjacent_patches() const
  {
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    for(const Curve& c : m_curves)
      pairs.emplace_back((std::min)(c.left_patch, c.right_patch), (std::max)(c.left_patch, c.right_patch));
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  }

  /// The total Euclidean length of the boundaries.
  double length() const { return m_state.total_energy(false); }

  /// The total length of the boundaries in the anisotropic metric of the edge weights
  /// (the energy that `smooth_patch_boundaries()` lowers).
  double anisotropic_length() const { return m_state.total_energy(true); }

  /// Writes the patch of every vertex. After `smooth_patch_boundaries()`, vertices near
  /// a boundary may have changed patch (see there); otherwise these are the input ids.
  /// \tparam VertexPatchMap a `WritablePropertyMap` from `vertex_descriptor` to an integer type
  template <typename VertexPatchMap>
  void write_vertex_patches(VertexPatchMap vertex_patch_map) const
  {
    typedef typename boost::property_traits<VertexPatchMap>::value_type Id;
    for(std::size_t v = 0; v < m_state.number_of_vertices(); ++v)
      put(vertex_patch_map, m_state.vertex_list[v], static_cast<Id>(m_state.labels[v]));
  }

  /// The mesh.
  const TriangleMesh& mesh() const { return m_state.mesh(); }

private:
  static Boundary_end end_type(internal::Boundary_path::End e)
  {
    return e == internal::Boundary_path::JUNCTION ? Boundary_end::JUNCTION
         : e == internal::Boundary_path::BORDER   ? Boundary_end::BORDER
                                                  : Boundary_end::CLOSED;
  }

  State m_state;
  std::vector<Curve> m_curves;
};

namespace internal {

// For callers that hold the segmentation's precomputed data (the segmentation class):
// boundaries of `labels` (one per vertex id of data.idx) without recomputing curvatures,
// features and metrics; `features` are data.features or those of an edit state.
template <typename TriangleMesh>
Patch_boundaries<TriangleMesh> make_patch_boundaries(const Segmentation_data<TriangleMesh>& data,
                                                     const Feature_terms& features,
                                                     const std::vector<std::size_t>& labels)
{
  return Patch_boundaries<TriangleMesh>(
    Boundary_state<TriangleMesh>(data.idx, data.points, data.metrics, labels, features.dual_vertices));
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationBoundaries
/// Computes the boundaries between the patches of a vertex labelling, as curves on the
/// surface (see `Patch_boundaries`).
///
/// The points inside the triangles are the dual vertices of the edge weights (the
/// triangle's centroid, or the centroid of its feature points); a cut edge's point is
/// where the shortest path between the dual vertices of its two triangles through the
/// edge crosses it (where the unfolded dual segment crosses the edge, when it does),
/// kept at least 1/1000 of the edge's length from its ends; on a border edge, its
/// midpoint. The metric is the per-triangle anisotropic metric of the weights (see
/// `compute_edge_weights()`), computed from the same named parameters on `tm` as it is
/// (this function does not cut the mesh open along its creases, as the segmentation
/// does: pass the same `feature_lines` and `principal_curvature_map` for the same
/// metric).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexPatchMap a `ReadablePropertyMap` from `vertex_descriptor` to an integer
///         type with non-negative values (the output of `segment_along_features()`, or
///         any labelling: patches need not be connected)
/// \param tm the mesh (checked with `check_input_mesh()`: throws `Invalid_input`)
/// \param vertex_patch_map the patch of every vertex
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{gamma}
///     \cgalParamDescription{the anisotropy \f$ \gamma \f$ of the curvature metric (Eq. 6), whose eigenvalues
///                           are 1 and \f$ 1/(1 + \gamma s)^2 \f$ with \f$ s = \vert k_1 \vert - \vert k_2
///                           \vert \f$, the curvatures being those of the mesh scaled to a largest
///                           bounding-box side of 1}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_gamma` (0.05)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{principal_curvature_map}
///     \cgalParamDescription{the principal curvatures of the vertices, used instead of estimating them}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and
///                    `Principal_curvatures<GeomTraits>` as value type}
///     \cgalParamDefault{estimated as by `estimate_principal_curvatures()`, with `neighborhood_rings`,
///                       `neighborhood_radius` and `concurrency_tag`}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{feature_lines}
///     \cgalParamDescription{the feature lines to follow (e.g. the user's), whose points place the dual
///                           vertices}
///     \cgalParamType{`Feature_lines<TriangleMesh>`}
///     \cgalParamDefault{the detected crest lines (with `strength_threshold`, `umbilic_ratio`,
///                       `detect_ridges` and `detect_valleys`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{edge_is_feature_map}
///     \cgalParamDescription{the feature edges: with `feature_lines`, the features are the union of these
///                           edges and the edges the lines cross; alone, no crest lines are detected and a
///                           feature edge contributes its midpoint}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::edge_descriptor` as key type and `bool` as value
///                    type}
///     \cgalParamDefault{the edges of the lines (those that `feature_lines`, or else the detected crest
///                       lines, cross)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{strength_threshold}
///     \cgalParamDescription{the crest lines whose strength (the integral of \f$ \vert k \vert \f$ along the
///                           line) is below it are dropped}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`default_strength_threshold` (1.0)}
///     \cgalParamExtra{A negative or non-finite value throws `Invalid_input`. Used only when neither
///                     `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{umbilic_ratio}
///     \cgalParamDescription{the zero crossings near umbilics, where \f$ \vert k \vert - \vert k_{other}
///                           \vert \leq \f$ `umbilic_ratio` \f$ \cdot \vert k \vert \f$, are dropped: there
///                           the principal directions are noise}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{`0.1`}
///     \cgalParamExtra{A value outside [0, 1) throws `Invalid_input`. Used only when neither `feature_lines`
///                     nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_ridges}
///     \cgalParamDescription{whether ridges (maxima of `k_max` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Used only when neither `feature_lines` nor `edge_is_feature_map` is given.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{detect_valleys}
///     \cgalParamDescription{whether valleys (minima of `k_min` along its direction) are detected}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Used only when neither `feature_lines` nor `edge_is_feature_map` is given.}
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
///     \cgalParamDescription{a tag indicating whether the curvature fits and the terms of the faces and edges
///                           (their metrics, Similarity and Award) run sequentially or on TBB's threads}
///     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`}
///     \cgalParamDefault{`CGAL::Sequential_tag`}
///     \cgalParamExtra{With `CGAL::Parallel_tag` the program must link TBB (e.g. `CGAL::TBB_support`);
///                     `tbb::global_control` bounds the number of threads. The result is the same at any
///                     thread count.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{alpha}
///     \cgalParamDescription{the global parameter \f$ \alpha \f$ of the segmentation: only checked here, the
///                           result does not depend on it}
///     \cgalParamType{`double`, finite}
///     \cgalParamDefault{`default_alpha` (0.6)}
///     \cgalParamExtra{A non-finite value throws `Invalid_input`. `edge_alpha_map` is not read.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_angle}
///     \cgalParamDescription{the crease angle of the segmentation (in degrees): only checked here; this
///                           function works on `tm` as it is, not cut open along its creases}
///     \cgalParamType{`double`, above 0}
///     \cgalParamDefault{`default_crease_angle` (20)}
///     \cgalParamExtra{A value that is not a finite number above 0 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crease_filter_iterations}
///     \cgalParamDescription{the rounds of the segmentation's normal filter before its creases are found:
///                           only checked here; this function works on `tm` as it is, not cut open along its
///                           creases}
///     \cgalParamType{an integer type, 0 to 1000}
///     \cgalParamDefault{`default_crease_filter_iterations` (40)}
///     \cgalParamExtra{A value outside 0 to 1000 throws `Invalid_input`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{tangent_discontinuities}
///     \cgalParamDescription{the segmentation's option that makes the curvature discontinuities of CAD
///                           tessellations creases: read, but without effect here; this function works on
///                           `tm` as it is, not cut open along its creases}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_tangent_discontinuities` (`true`)}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{crest_lines_on_clean_tessellations}
///     \cgalParamDescription{the segmentation's option that gives the crest lines of CAD tessellations the
///                           full \f$ \alpha \f$: read, but without effect here; this function works on `tm`
///                           as it is, not cut open along its creases}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`default_crest_lines_on_clean_tessellations` (`false`)}
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
/// \return the boundaries; `tm` must outlive them
///
/// \throws Invalid_input if a patch id is negative
template <typename TriangleMesh, typename VertexPatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Patch_boundaries<TriangleMesh> compute_patch_boundaries(const TriangleMesh& tm, VertexPatchMap vertex_patch_map,
                                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Segmentation_options opt = internal::read_segmentation_options<TriangleMesh>(np);
  internal::Segmentation_data<TriangleMesh> data(tm);
  Feature_lines<TriangleMesh> lines;
  internal::prepare_segmentation_data(tm, np, opt, data, lines);
  std::vector<std::size_t> labels(data.idx.number_of_vertices());
  for(std::size_t v = 0; v < labels.size(); ++v)
  {
    const auto id = get(vertex_patch_map, data.idx.vertex_at(v));
    if constexpr(std::is_signed<std::decay_t<decltype(id)> >::value)
      if(id < 0)
        throw Invalid_input("vertex_patch_map holds a negative patch id (" + std::to_string(id) + ")");
    labels[v] = static_cast<std::size_t>(id);
  }
  return internal::make_patch_boundaries(data, data.features, labels);
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_BOUNDARY_CURVES_H
