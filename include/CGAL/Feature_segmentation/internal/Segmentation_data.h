// SPDX-License-Identifier: GPL-3.0-or-later
// What the segmentation precomputes once per mesh and feature set: indices, curvature
// tensors, the per-face metrics, the vertex graph G, and the features' part (feature
// edges and points, dual vertices, the Similarity and Award terms of every edge), which
// the editing engine shares between states until a sketch changes it. Solving for an alpha (or a per-edge alpha) only recombines the
// terms into weights and runs the solver; the free function and the editing class share
// this structure.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_SEGMENTATION_DATA_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_SEGMENTATION_DATA_H

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/defaults.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/compact_index.h>
#include <CGAL/Feature_segmentation/internal/edge_weights_impl.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <memory>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// Every option of the segmentation, parsed once from the named parameters.
struct Segmentation_options
{
  double alpha = default_alpha;
  double gamma = default_gamma;
  // degrees; >= 180: no creases (the paper's pipeline, crest lines only); the gap test
  // keeps the strong bends of smooth surfaces out (see the manual, Creases)
  double crease_angle = default_crease_angle;
  // rounds of bilateral filtering of the face normals before the creases are detected;
  // a clean mesh (normal roughness at most 0.01) is not filtered at all (0: the raw
  // dihedral angles everywhere)
  int crease_filter_iterations = default_crease_filter_iterations;
  // on a clean tessellation, the curvature discontinuities (a fillet meeting a plane
  // without a crease) join the creases (see the manual, Creases)
  bool tangent_discontinuities = default_tangent_discontinuities;
  // crest lines at the full alpha also on a CAD tessellation (clean, or cut into pieces
  // by its creases), as the paper; by default its creases and curvature discontinuities
  // bound its B-rep faces (crest lines cut curved faces apart: see the manual, CAD Parts)
  bool crest_lines_on_clean_tessellations = default_crest_lines_on_clean_tessellations;
  // set by the class, not by a parameter: whether prepare_segmentation_data detects
  // crest lines when no feature is given
  bool detect_crest_lines = true;
  // set by the class: prepare_segmentation_data adds seam lines (internal/seam_lines.h)
  // to the detected crest lines (a clean CAD tessellation, with tangent_discontinuities)
  bool detect_seam_lines = false;

  void check() const
  {
    if(!std::isfinite(alpha))
      throw Invalid_input("alpha must be a finite number (got " + std::to_string(alpha) + ")");
    if(!(gamma >= 0) || !std::isfinite(gamma))
      throw Invalid_input("gamma must be a finite number >= 0 (got " + std::to_string(gamma) + ")");
    if(!(crease_angle > 0) || !std::isfinite(crease_angle))
      throw Invalid_input("crease_angle must be a finite number of degrees > 0 (180 or more: no creases; got " +
                          std::to_string(crease_angle) + ")");
    if(crease_filter_iterations < 0 || crease_filter_iterations > 1000)
      throw Invalid_input("crease_filter_iterations must be an integer in 0 .. 1000 (got " +
                          std::to_string(crease_filter_iterations) + ")");
  }
};

template <typename TriangleMesh>
class Segmentation_data
{
public:
  typedef Mesh_indexing<TriangleMesh> Indexing;
  typedef Eigen::Vector3d Vec3;

  explicit Segmentation_data(const TriangleMesh& tm) : idx(tm) {}
  // on an indexing already made (a copy shares its index maps)
  explicit Segmentation_data(const Indexing& indexing) : idx(indexing) {}

  // Positions and curvatures, read through the user's maps once.
  template <typename VPM, typename CurvatureMap>
  void set_geometry(VPM vpm, CurvatureMap cmap)
  {
    vin.resize(idx.number_of_vertices());
    points.resize(idx.number_of_vertices());
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for(std::size_t i = 0; i < vin.size(); ++i)
    {
      const auto v = idx.vertex_at(i);
      const auto& p = get(vpm, v);
      const auto c = get(cmap, v);
      Vertex_tensor_input& x = vin[i];
      x.p = Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      x.k1 = CGAL::to_double(c.k1);
      x.k2 = CGAL::to_double(c.k2);
      x.d1 = Vec3(CGAL::to_double(c.d1.x()), CGAL::to_double(c.d1.y()), CGAL::to_double(c.d1.z()));
      x.d2 = Vec3(CGAL::to_double(c.d2.x()), CGAL::to_double(c.d2.y()), CGAL::to_double(c.d2.z()));
      points[i] = x.p;
      lo = lo.cwiseMin(x.p);
      hi = hi.cwiseMax(x.p);
    }
    diagonal = vin.empty() ? 0. : (hi - lo).norm();
    largest_side = vin.empty() ? 0. : (hi - lo).maxCoeff();
  }

  // Feature edges from an edge map, feature points from lines (may be empty).
  template <typename EdgeIsFeatureMap>
  void set_features(EdgeIsFeatureMap is_feature, const Feature_lines<TriangleMesh>& lines)
  {
    const TriangleMesh& tm = idx.mesh();
    const std::size_t ne = idx.number_of_edges();
    Feature_terms& f = features;
    f.is_feature_edge.assign(ne, 0);
    f.clear_points(ne);
    for(std::size_t e = 0; e < ne; ++e)
      f.is_feature_edge[e] = get(is_feature, idx.edge_at(e)) ? 1 : 0;
    // the feature edges are the edges that contain a feature point (paper, 3.1)
    for(const auto& l : lines.lines)
      for(const auto& fp : l.points)
      {
        const std::size_t e = idx.edge_id(fp.halfedge);
        f.add_point(e, (1 - fp.t) * points[idx.id(source(fp.halfedge, tm))] +
                         fp.t * points[idx.id(target(fp.halfedge, tm))]);
        f.is_feature_edge[e] = 1;
      }
    f.number_of_feature_edges = std::size_t(std::count(f.is_feature_edge.begin(), f.is_feature_edge.end(), 1));
  }

  // Similarity and Award; the vertex graph's topology.
  // `parallel`: the faces and edges are computed by TBB's threads (the same terms).
  void compute_terms(double gamma, bool parallel = false)
  {
    // gamma (Eq. 5-6) multiplies a curvature, so it is given for curvatures measured on
    // the mesh scaled so that the largest side of its bounding box is 1, as the authors'
    // tool does before anything else: the result does not depend on the file's units.
    auto face_metrics = std::make_shared<std::vector<Triangle_metric> >();
    Edge_weight_terms<TriangleMesh>::compute(idx, vin, points, gamma, largest_side, *face_metrics, features, parallel);
    metrics = std::move(face_metrics);
    // the curvature tensors are in the metrics now: only the positions are kept
    std::vector<Vertex_tensor_input>().swap(vin);
    const TriangleMesh& tm = idx.mesh();
    check_compact_index_range(idx.number_of_vertices());
    edge_vertices.resize(idx.number_of_edges());
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      auto h = halfedge(idx.edge_at(e), tm);
      edge_vertices[e] = { idx.id(source(h, tm)), idx.id(target(h, tm)) };
    }
  }

  // w(e) = Similarity(e) - alpha_e Award(e), Eq. 3.
  double weight(std::size_t e, double alpha_e) const { return features.weight(e, alpha_e); }

  Correlation_clustering_graph graph(const std::vector<double>& alpha_e) const
  {
    Correlation_clustering_graph g(idx.number_of_vertices());
    g.reserve_edges(edge_vertices.size());
    for(std::size_t e = 0; e < edge_vertices.size(); ++e)
      g.add_edge(edge_vertices[e].first, edge_vertices[e].second, weight(e, alpha_e[e]));
    return g;
  }

  std::vector<double> default_alpha(double alpha) const
  {
    std::vector<double> a(features.is_feature_edge.size(), 0.);
    for(std::size_t e = 0; e < a.size(); ++e) if(features.is_feature_edge[e]) a[e] = alpha;
    return a;
  }

  Indexing idx;
  std::vector<Vertex_tensor_input> vin; // from set_geometry() to compute_terms(), then freed
  std::vector<Vec3> points;             // vertex positions
  double diagonal = 0;
  double largest_side = 0;
  // per face: the anisotropic metric of the weights (shared with the boundaries' states)
  std::shared_ptr<const std::vector<Triangle_metric> > metrics;
  Edge_vertex_list edge_vertices;        // per edge (and crease tie)
  Feature_terms features;               // the feature edges and points, the terms
  std::vector<char> is_seam_edge;        // per edge: crossed by a seam line (empty without them)
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_SEGMENTATION_DATA_H
