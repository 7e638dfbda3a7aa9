// SPDX-License-Identifier: GPL-3.0-or-later
// The patch boundaries as the smoothing sees them: a vertex labelling, one point on every
// cut edge (a parameter along the edge) and one point inside every triangle that has cut
// edges. A triangle's vertices carry two or three labels, so it has two cut edges (the
// boundary passes through it) or three (a junction). The boundary inside a triangle is
// the polyline from its point to the points of its cut edges; its length in the
// triangle's anisotropic metric is the energy. Curves (ordered polylines with their two
// patches and their ends) are read off this state; all indices are contiguous ids of
// the mesh's vertices, edges and faces.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_STATE_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_STATE_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/compact_index.h>
#include <CGAL/Feature_segmentation/internal/edge_weights_impl.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// A curve read off the state: alternately face nodes and edge nodes (ids), with the
// halfedge through which the curve crosses each edge node (from the previous face).
struct Boundary_path
{
  enum End { JUNCTION, BORDER, CLOSED };
  struct Node
  {
    bool on_edge;
    std::size_t id;       // face id or edge id
    std::size_t halfedge; // on an edge: 0 for the edge's first halfedge, 1 for its opposite;
                          // the one whose face is the face the curve comes from (or goes to,
                          // for the first node of a curve that starts on the border)
  };
  std::vector<Node> nodes;
  std::size_t left = 0, right = 0; // patches on either side, with the mesh's orientation
  End front = CLOSED, back = CLOSED;
};

template <typename TriangleMesh>
class Boundary_state
{
public:
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  typedef Eigen::Vector3d Vec3;
  static constexpr std::size_t npos = std::size_t(-1);

  // A point on a cut edge stays this far (in edge parameter) from the edge's ends, so
  // that no boundary touches a mesh vertex and two boundaries never meet there.
  static constexpr double edge_margin = 1e-3;
  // A junction point keeps barycentric coordinates of at least this.
  static constexpr double face_margin = 1e-3;

  // The initial boundaries of the labelling `vertex_labels` (see initialize()), with the
  // topology and geometry copied from the indexing and the weights' terms, so that the
  // state does not refer to the indexing's property maps after construction; the face
  // metrics are shared with the segmentation's data (read only, kept alive by the state).
  // The rings are made for the vertices that may move (`movable`) only: the smoothing
  // reads no other, and on a mesh whose patches meet along creases there is none.
  Boundary_state(const Mesh_indexing<TriangleMesh>& idx, const std::vector<Vec3>& vertex_points,
                 std::shared_ptr<const std::vector<Triangle_metric> > face_metrics,
                 const std::vector<std::size_t>& vertex_labels, const std::vector<Vec3>& dual_vertices)
    : m_tm(&idx.mesh()), metrics(std::move(face_metrics))
  {
    const TriangleMesh& tm = idx.mesh();
    const std::size_t nv = idx.number_of_vertices(), ne = idx.number_of_edges(), nf = idx.number_of_faces();
    CGAL_precondition(vertex_points.size() == nv && metrics != nullptr && metrics->size() == nf);
    check_compact_index_range(std::max({ nv, 2 * ne, nf }));
    vertex_list.assign(idx.vertex_list().begin(), idx.vertex_list().end());
    face_list.assign(idx.face_list().begin(), idx.face_list().end());
    points = vertex_points;
    edge_halfedge.resize(ne);
    edge_vertices.resize(ne);
    edge_faces.resize(ne);
    for(std::size_t e = 0; e < ne; ++e)
    {
      const halfedge_descriptor h = halfedge(idx.edge_at(e), tm);
      edge_halfedge[e] = h;
      edge_vertices[e] = { idx.id(source(h, tm)), idx.id(target(h, tm)) };
      edge_faces[e] = { idx.face_id(h), idx.face_id(opposite(h, tm)) };
    }
    face_vertices.resize(nf);
    face_edges.resize(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const halfedge_descriptor h = halfedge(idx.face_at(f), tm);
      face_vertices[f] = { idx.id(source(h, tm)), idx.id(target(h, tm)), idx.id(target(next(h, tm), tm)) };
      face_edges[f] = { idx.edge_id(h), idx.edge_id(next(h, tm)), idx.edge_id(prev(h, tm)) };
    }
    labels.assign(nv, 0);
    edge_t.assign(ne, 0.5);
    face_x.assign(nf, Vec3::Zero());
    movable.assign(nv, 0);
    initialize(vertex_labels, dual_vertices);
    // The ring of every movable vertex, in the order of halfedges_around_target:
    // neighbour i, the edge to it, and the face between edges i and i+1 (npos across the
    // border, which is rotated to the end of the ring); empty for the others.
    ring_offset.assign(nv + 1, 0);
    std::vector<std::array<Compact_index, 3> > ring;
    for(std::size_t v = 0; v < nv; ++v)
    {
      const auto vd = idx.vertex_at(v);
      ring.clear();
      if(movable[v] && halfedge(vd, tm) != GTr::null_halfedge())
        for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vd, tm), tm))
          ring.push_back({ idx.id(source(h, tm)), idx.edge_id(h), idx.face_id(h) });
      const auto gap = std::find_if(ring.begin(), ring.end(),
                                    [](const std::array<Compact_index, 3>& r) { return r[2] == npos; });
      if(gap != ring.end()) std::rotate(ring.begin(), gap + 1, ring.end());
      for(const auto& r : ring) ring_entries.push_back(r);
      ring_offset[v + 1] = ring_entries.size();
    }
  }

private:
  // The initial boundaries of a labelling (paper, Fig. 3(c)): the point of a triangle
  // with cut edges is its dual vertex (of the weights); the point of a cut edge is where
  // the shortest path between its two triangles' dual vertices through the edge crosses
  // it (where the unfolded dual segment crosses it, when it does); on a border edge, its
  // midpoint, the end the weights give a border edge's dual segment.
  void initialize(const std::vector<std::size_t>& vertex_labels, const std::vector<Vec3>& dual_vertices)
  {
    CGAL_precondition(vertex_labels.size() == number_of_vertices());
    CGAL_precondition(dual_vertices.size() == number_of_faces());
    labels = vertex_labels;
    movable.assign(number_of_vertices(), 0);
    for(std::size_t e = 0; e < number_of_edges(); ++e)
    {
      edge_t[e] = 0.5;
      if(!is_cut(e)) continue;
      movable[edge_vertices[e][0]] = movable[edge_vertices[e][1]] = 1;
      const std::size_t f0 = edge_faces[e][0], f1 = edge_faces[e][1];
      if(f0 == npos || f1 == npos) continue;
      edge_t[e] = initial_edge_t(points[edge_vertices[e][0]], points[edge_vertices[e][1]], dual_vertices[f0],
                                 dual_vertices[f1]);
    }
    for(std::size_t f = 0; f < number_of_faces(); ++f)
      face_x[f] = has_cut_edges(f) ? keep_inside(f, dual_vertices[f], face_margin) : Vec3::Zero();
  }

public:

  // The initial point of an edge from p0 to p1 between two faces with dual vertices d0
  // and d1 (as a parameter from p0): where the shortest path from d0 to d1 through the
  // edge's line crosses it, clamped to [edge_margin, 1 - edge_margin]. In closed form:
  // |p(t) - d| depends only on t and on d's distance r to the line, so turning d1 about
  // the line to the side opposite d0 changes nothing, and in that plane the path is
  // straight; it crosses the line at t0 + (t1 - t0) r0 / (r0 + r1), where t0, t1 are the
  // parameters of the projections of d0, d1 (the sum of distances is convex in t, so its
  // minimum on the clamped interval is the clamped minimum).
  static double initial_edge_t(const Vec3& p0, const Vec3& p1, const Vec3& d0, const Vec3& d1)
  {
    const Vec3 u = p1 - p0;
    const double uu = u.squaredNorm();
    double t = 0.5;
    if(uu > 0)
    {
      const double t0 = u.dot(d0 - p0) / uu, t1 = u.dot(d1 - p0) / uu;
      const double r0 = (d0 - p0 - t0 * u).norm(), r1 = (d1 - p0 - t1 * u).norm();
      t = (r0 + r1 > 0) ? t0 + (t1 - t0) * (r0 / (r0 + r1)) : 0.5 * (t0 + t1);
      if(!(t == t)) t = 0.5; // not a number: an infinite or undefined input
    }
    return (std::min)(1 - edge_margin, (std::max)(edge_margin, t));
  }

  // Golden-section search for the minimum of a convex function on [lo, hi] (deterministic;
  // 36 steps shrink the interval below 3e-8 of its length).
  template <typename F>
  static double minimize_convex(double lo, double hi, F fn)
  {
    const double r = 0.5 * (std::sqrt(5.) - 1);
    double a = lo, b = hi;
    double x1 = b - r * (b - a), x2 = a + r * (b - a);
    double f1 = fn(x1), f2 = fn(x2);
    for(int i = 0; i < 36; ++i)
    {
      if(f1 <= f2) { b = x2; x2 = x1; f2 = f1; x1 = b - r * (b - a); f1 = fn(x1); }
      else { a = x1; x1 = x2; f1 = f2; x2 = a + r * (b - a); f2 = fn(x2); }
    }
    return f1 <= f2 ? x1 : x2;
  }

  const TriangleMesh& mesh() const { return *m_tm; }
  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_edges() const { return edge_vertices.size(); }
  std::size_t number_of_faces() const { return face_vertices.size(); }

  bool is_cut(std::size_t e) const { return labels[edge_vertices[e][0]] != labels[edge_vertices[e][1]]; }
  bool is_border_edge(std::size_t e) const { return edge_faces[e][0] == npos || edge_faces[e][1] == npos; }

  Vec3 edge_point(std::size_t e) const { return edge_point(e, edge_t[e]); }
  Vec3 edge_point(std::size_t e, double t) const
  {
    return (1 - t) * points[edge_vertices[e][0]] + t * points[edge_vertices[e][1]];
  }

  // The cut edges of face f (in the order of face_edges[f]); returns their number: 0, 2 or 3.
  int cut_edges(std::size_t f, std::array<std::size_t, 3>& out) const
  {
    int n = 0;
    for(std::size_t e : face_edges[f]) if(is_cut(e)) out[n++] = e;
    return n;
  }
  bool has_cut_edges(std::size_t f) const
  {
    const auto& t = face_vertices[f];
    return labels[t[0]] != labels[t[1]] || labels[t[1]] != labels[t[2]];
  }

  double length(std::size_t f, const Vec3& w, bool anisotropic) const
  {
    return anisotropic ? (*metrics)[f].anisotropic(w) : w.norm();
  }

  // Length of the boundary inside face f.
  double face_energy(std::size_t f, bool anisotropic = true) const
  {
    std::array<std::size_t, 3> c;
    const int n = cut_edges(f, c);
    double s = 0;
    for(int i = 0; i < n; ++i) s += length(f, edge_point(c[i]) - face_x[f], anisotropic);
    return s;
  }

  double total_energy(bool anisotropic = true) const
  {
    double s = 0;
    for(std::size_t f = 0; f < number_of_faces(); ++f) s += face_energy(f, anisotropic);
    return s;
  }

  // Barycentric coordinates of x in triangle abc; the centroid's on a degenerate one.
  static std::array<double, 3> barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x)
  {
    const Vec3 n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    if(!(n2 > 0)) return { 1. / 3, 1. / 3, 1. / 3 };
    const double wa = (c - b).cross(x - b).dot(n) / n2, wb = (a - c).cross(x - c).dot(n) / n2;
    return { wa, wb, 1 - wa - wb };
  }
  // x moved towards the centroid of abc until its barycentric coordinates are >= margin.
  static Vec3 keep_inside(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x, double margin)
  {
    std::array<double, 3> w = barycentric(a, b, c, x);
    const double m = (std::min)(w[0], (std::min)(w[1], w[2]));
    if(m < margin)
    {
      // (1-s) w + s/3 >= margin at the smallest coordinate
      const double s = (margin - m) / (1. / 3 - m);
      for(double& k : w) k = (1 - s) * k + s / 3;
    }
    return w[0] * a + w[1] * b + w[2] * c;
  }
  // The same in face f (w.r.t. face_vertices[f]).
  std::array<double, 3> barycentric(std::size_t f, const Vec3& x) const
  {
    const auto& t = face_vertices[f];
    return barycentric(points[t[0]], points[t[1]], points[t[2]], x);
  }
  Vec3 from_barycentric(std::size_t f, const std::array<double, 3>& w) const
  {
    const auto& t = face_vertices[f];
    return w[0] * points[t[0]] + w[1] * points[t[1]] + w[2] * points[t[2]];
  }
  Vec3 keep_inside(std::size_t f, const Vec3& x, double margin) const
  {
    const auto& t = face_vertices[f];
    return keep_inside(points[t[0]], points[t[1]], points[t[2]], x, margin);
  }

  // Ring of vertex v: entries [ring_begin(v), ring_end(v)) of ring_entries.
  std::size_t ring_begin(std::size_t v) const { return ring_offset[v]; }
  std::size_t ring_end(std::size_t v) const { return ring_offset[v + 1]; }
  bool is_border_vertex(std::size_t v) const
  {
    return ring_end(v) > ring_begin(v) && ring_entries[ring_end(v) - 1][2] == npos;
  }

  // The curves: maximal paths of the node graph (a face node is linked to the nodes of
  // its cut edges) between junction faces and border edges, then the closed cycles.
  std::vector<Boundary_path> paths() const
  {
    const TriangleMesh& tm = mesh();
    std::vector<Boundary_path> out;
    std::vector<char> edge_done(number_of_edges(), 0);

    // Follows the curve from face f, entered through edge `from`, until an end.
    auto walk = [&](Boundary_path& p, std::size_t f, std::size_t from) -> Boundary_path::End {
      for(;;)
      {
        p.nodes.push_back({ false, f, 0 });
        std::array<std::size_t, 3> c;
        const int n = cut_edges(f, c);
        if(n == 3) return Boundary_path::JUNCTION;
        CGAL_assertion(n == 2);
        const std::size_t e = (c[0] == from) ? c[1] : c[0];
        if(edge_done[e]) return Boundary_path::CLOSED;
        edge_done[e] = 1;
        const std::size_t side = (edge_faces[e][0] == f) ? 0 : 1;
        p.nodes.push_back({ true, e, side });
        const std::size_t g = edge_faces[e][1 - side];
        if(g == npos) return Boundary_path::BORDER;
        f = g;
        from = e;
      }
    };
    // The curve that leaves face f (npos: starts on border edge e) through edge e.
    auto trace = [&](std::size_t f, std::size_t e, Boundary_path::End front) {
      Boundary_path p;
      p.front = front;
      std::size_t side;
      if(f != npos)
      {
        p.nodes.push_back({ false, f, 0 });
        side = (edge_faces[e][0] == f) ? 0 : 1;
      }
      else
        side = (edge_faces[e][0] == npos) ? 1 : 0; // the halfedge that has the face
      edge_done[e] = 1;
      p.nodes.push_back({ true, e, side });
      const std::size_t g = (f != npos) ? edge_faces[e][1 - side] : edge_faces[e][side];
      if(g == npos) p.back = Boundary_path::BORDER;
      else p.back = walk(p, g, e);
      // Sides from the first edge node: crossing halfedge h from its face to the other
      // side, target(h) is on the left (faces are to the left of their halfedges).
      halfedge_descriptor h = edge_halfedge[e];
      if(side == 1) h = opposite(h, tm);
      std::size_t l = labels[edge_vertices[e][side == 0 ? 1 : 0]];
      std::size_t r = labels[edge_vertices[e][side == 0 ? 0 : 1]];
      if(f == npos) std::swap(l, r); // entering the face from the border: reversed
      p.left = l;
      p.right = r;
      out.push_back(p);
    };

    for(std::size_t f = 0; f < number_of_faces(); ++f)
    {
      std::array<std::size_t, 3> c;
      if(cut_edges(f, c) != 3) continue;
      for(std::size_t e : c)
        if(!edge_done[e]) trace(f, e, Boundary_path::JUNCTION);
    }
    for(std::size_t e = 0; e < number_of_edges(); ++e)
      if(!edge_done[e] && is_cut(e) && is_border_edge(e) && (edge_faces[e][0] != npos || edge_faces[e][1] != npos))
        trace(npos, e, Boundary_path::BORDER);
    for(std::size_t e = 0; e < number_of_edges(); ++e)
    {
      if(edge_done[e] || !is_cut(e) || edge_faces[e][0] == npos) continue;
      // a closed curve: start on edge e, leave towards its first face's other side
      Boundary_path p;
      p.front = Boundary_path::CLOSED;
      edge_done[e] = 1;
      p.nodes.push_back({ true, e, 1 });
      const std::size_t g = edge_faces[e][0];
      const Boundary_path::End end = walk(p, g, e);
      CGAL_assertion(end == Boundary_path::CLOSED);
      p.back = end;
      // crossing halfedge opposite(h) from face(opposite) into face(h): source(h) on the left
      p.left = labels[edge_vertices[e][0]];
      p.right = labels[edge_vertices[e][1]];
      out.push_back(p);
    }
    return out;
  }

  const TriangleMesh* m_tm;
  std::vector<typename GTr::vertex_descriptor> vertex_list;
  std::vector<typename GTr::face_descriptor> face_list;
  std::vector<halfedge_descriptor> edge_halfedge;
  std::vector<Vec3> points;
  std::shared_ptr<const std::vector<Triangle_metric> > metrics; // of the segmentation's data, shared
  // ids in 32 bits (Compact_index): the topology is a third of the state's memory
  std::vector<std::array<Compact_index, 2> > edge_vertices, edge_faces;
  std::vector<std::array<Compact_index, 3> > face_vertices, face_edges;
  std::vector<Compact_index> ring_offset;
  std::vector<std::array<Compact_index, 3> > ring_entries; // (neighbour, edge, face)

  std::vector<std::size_t> labels; // patch per vertex
  std::vector<double> edge_t;      // per cut edge: the point (1-t) source + t target of edge_halfedge
  std::vector<Vec3> face_x;        // per face with cut edges: its point
  std::vector<char> movable;       // per vertex: may change patch during smoothing
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_STATE_H
