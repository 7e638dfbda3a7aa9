// SPDX-License-Identifier: GPL-3.0-or-later
// The work behind detect_crest_lines(): zero crossings of the extremality coefficients
// on edges, the ridge/valley tests, segments inside triangles, and tracing into lines.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREST_LINES_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREST_LINES_IMPL_H

#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Crest_options
{
  double strength_threshold = 0;
  double umbilic_ratio = 0.1;
  bool ridges = true, valleys = true;
};

// The per-vertex quantities the detector reads, for one line type: the curvature whose
// extremum is sought (k), the other one, its direction and its extremality coefficient.
struct Crest_vertex_data
{
  double k = 0, k_other = 0, e = 0;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

template <typename TriangleMesh>
class Crest_line_detector
{
public:
  typedef Mesh_indexing<TriangleMesh> Indexing;
  typedef typename Indexing::halfedge_descriptor halfedge_descriptor;
  typedef Eigen::Vector3d Vec3;

  Crest_line_detector(const Indexing& idx, const std::vector<Vec3>& points)
    : m_idx(idx), m_points(points)
  {
    Eigen::Vector3d lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for(const Vec3& p : points) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
    m_diagonal = points.empty() ? 0. : (hi - lo).norm();
  }

  // `data[v]` describes vertex v for `type`; appends the lines found to `out`.
  void detect(Feature_line_type type, const std::vector<Crest_vertex_data>& data,
              const Crest_options& opt, Feature_lines<TriangleMesh>& out, bool parallel = false) const
  {
    const TriangleMesh& tm = m_idx.mesh();
    const std::size_t ne = m_idx.number_of_edges();
    const double sign = (type == Feature_line_type::RIDGE) ? 1. : -1.;
    // a curvature radius over a million diagonals is flat: its crossings are noise
    const double flat = m_diagonal > 0 ? 1e-6 / m_diagonal : 0.;

    // 1. One crossing at most per edge.
    std::vector<double> cross_t(ne, -1.), cross_k(ne, 0.);
    for_each_range(ne, parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t ei = first; ei < last; ++ei)
      {
        halfedge_descriptor h = halfedge(m_idx.edge_at(ei), tm);
        const std::size_t a = m_idx.id(source(h, tm)), b = m_idx.id(target(h, tm));
        const Crest_vertex_data& A = data[a];
        const Crest_vertex_data& B = data[b];
        // orient B's direction like A's: the directions are defined up to sign, and the
        // extremality coefficient flips with the direction
        const double flip = (A.t.dot(B.t) < 0) ? -1. : 1.;
        const double ea = A.e, eb = flip * B.e;
        if(!(ea * eb < 0))
          continue;
        const Vec3 tbar = A.t + flip * B.t;
        // maximum (ridge, sign +1) or minimum (valley, sign -1) along the direction: the
        // coefficient decreases (ridge) or increases (valley) when moving along tbar. The
        // gradient of its linear interpolant over the edge's triangles decides: unlike the
        // difference along the edge alone, it stays informative when the edge runs along
        // the crest (creases of CAD meshes often do).
        if(!(sign * extremality_gradient(h, data, ea, eb, A.t).dot(tbar) < 0))
          continue;
        const double s = ea / (ea - eb);
        const double k = (1 - s) * A.k + s * B.k;
        const double ko = (1 - s) * A.k_other + s * B.k_other;
        // Yoshizawa et al.: k_max > |k_min| on ridges, k_min < -|k_max| on valleys; away
        // from umbilics, where the directions carry no information
        if(!(sign * k > std::abs(ko)) || !(sign * k - std::abs(ko) > opt.umbilic_ratio * std::abs(k)) ||
           !(std::abs(k) > flat))
          continue;
        cross_t[ei] = s;
        cross_k[ei] = std::abs(k);
      }
    });

    // 2. Segments inside triangles: two crossed edges are joined; with three, the two
    //    strongest are, and the third crossing ends a line.
    std::vector<std::array<std::size_t, 2> > link(ne, {npos, npos});
    auto add_link = [&](std::size_t x, std::size_t y) {
      (link[x][0] == npos ? link[x][0] : link[x][1]) = y;
      (link[y][0] == npos ? link[y][0] : link[y][1]) = x;
    };
    auto crossed_edges = [&](std::size_t fi, std::array<std::size_t, 3>& crossed) {
      halfedge_descriptor h = halfedge(m_idx.face_at(fi), tm);
      const std::array<std::size_t, 3> es = { m_idx.edge_id(h), m_idx.edge_id(next(h, tm)),
                                              m_idx.edge_id(prev(h, tm)) };
      int nc = 0;
      for(std::size_t e : es) if(cross_t[e] >= 0) crossed[nc++] = e;
      return nc;
    };
    // the faces with two or three crossings are found by the threads, linked in order
    const std::size_t nf = m_idx.number_of_faces();
    std::vector<char> joins(nf, 0);
    for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
      std::array<std::size_t, 3> crossed;
      for(std::size_t fi = first; fi < last; ++fi) joins[fi] = crossed_edges(fi, crossed) >= 2;
    });
    for(std::size_t fi = 0; fi < nf; ++fi)
    {
      if(!joins[fi]) continue;
      std::array<std::size_t, 3> crossed;
      const int nc = crossed_edges(fi, crossed);
      if(nc == 2)
        add_link(crossed[0], crossed[1]);
      else if(nc == 3)
      {
        int weakest = 0;
        for(int i = 1; i < 3; ++i)
          if(cross_k[crossed[i]] < cross_k[crossed[weakest]]) weakest = i;
        add_link(crossed[(weakest + 1) % 3], crossed[(weakest + 2) % 3]);
      }
    }

    // 3. Tracing: every crossing has at most two links (one per adjacent face), so the
    //    components are paths and cycles. Paths first, from their lowest-index end.
    std::vector<char> used(ne, 0);
    auto trace = [&](std::size_t start, bool closed) {
      Feature_line<TriangleMesh> line;
      line.type = type;
      line.is_closed = closed;
      std::size_t prev_e = npos, cur = start;
      while(cur != npos && !used[cur])
      {
        used[cur] = 1;
        line.points.push_back(point_on(cur, cross_t[cur]));
        std::size_t nxt = (link[cur][0] != prev_e) ? link[cur][0] : link[cur][1];
        if(link[cur][0] == prev_e && link[cur][1] == prev_e) nxt = npos; // doubled link
        prev_e = cur;
        cur = nxt;
      }
      const std::size_t np = line.points.size();
      const std::size_t nseg = closed ? np : np - 1;
      for(std::size_t i = 0; i < nseg; ++i)
      {
        const std::size_t j = (i + 1) % np;
        const double len = (position(line.points[i]) - position(line.points[j])).norm();
        line.length += len;
        line.strength += 0.5 * len * (cross_k[edge_of(line.points[i])] + cross_k[edge_of(line.points[j])]);
      }
      if(np >= 2 && line.strength >= opt.strength_threshold)
        out.lines.push_back(std::move(line));
    };
    for(std::size_t e = 0; e < ne; ++e)
      if(cross_t[e] >= 0 && !used[e] && (link[e][0] == npos || link[e][1] == npos))
        trace(e, false);
    for(std::size_t e = 0; e < ne; ++e)
      if(cross_t[e] >= 0 && !used[e])
        trace(e, true);
  }

  // Strongest first; ties by the first point's edge, so the order is deterministic.
  void sort_lines(Feature_lines<TriangleMesh>& out) const
  {
    std::stable_sort(out.lines.begin(), out.lines.end(),
                     [&](const Feature_line<TriangleMesh>& a, const Feature_line<TriangleMesh>& b) {
                       if(a.strength != b.strength) return a.strength > b.strength;
                       return edge_of(a.points.front()) < edge_of(b.points.front());
                     });
  }

private:
  static constexpr std::size_t npos = std::size_t(-1);

  Feature_point<TriangleMesh> point_on(std::size_t ei, double s) const
  {
    Feature_point<TriangleMesh> p;
    p.halfedge = halfedge(m_idx.edge_at(ei), m_idx.mesh());
    p.t = s;
    return p;
  }
  // Sum over the (one or two) faces of edge h = (a, b) of the gradient of the linear
  // interpolant of e, times twice the face area; e at the third vertex is oriented
  // like a's direction `ta`.
  Vec3 extremality_gradient(halfedge_descriptor h, const std::vector<Crest_vertex_data>& data,
                            double ea, double eb, const Vec3& ta) const
  {
    const TriangleMesh& tm = m_idx.mesh();
    Vec3 g = Vec3::Zero();
    for(halfedge_descriptor hh : {h, opposite(h, tm)})
    {
      if(is_border(hh, tm))
        continue;
      const std::size_t a = m_idx.id(source(hh, tm)), b = m_idx.id(target(hh, tm));
      const std::size_t c = m_idx.id(target(next(hh, tm), tm));
      const double e_a = (hh == h) ? ea : eb, e_b = (hh == h) ? eb : ea;
      const double e_c = (ta.dot(data[c].t) < 0 ? -1. : 1.) * data[c].e;
      const Vec3 n = (m_points[b] - m_points[a]).cross(m_points[c] - m_points[a]);
      const double len = n.norm();
      if(!(len > 0))
        continue;
      const Vec3 u = n / len;
      // grad = sum_i e_i (u x opposite edge_i) / (2 area); scaled by 2 area here
      g += e_a * u.cross(m_points[c] - m_points[b]) + e_b * u.cross(m_points[a] - m_points[c]) +
           e_c * u.cross(m_points[b] - m_points[a]);
    }
    return g;
  }

  std::size_t edge_of(const Feature_point<TriangleMesh>& p) const { return m_idx.edge_id(p.halfedge); }
  Vec3 position(const Feature_point<TriangleMesh>& p) const
  {
    const TriangleMesh& tm = m_idx.mesh();
    return (1 - p.t) * m_points[m_idx.id(source(p.halfedge, tm))] +
           p.t * m_points[m_idx.id(target(p.halfedge, tm))];
  }

  const Indexing& m_idx;
  const std::vector<Vec3>& m_points;
  double m_diagonal = 0;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREST_LINES_IMPL_H
