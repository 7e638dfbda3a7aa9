// SPDX-License-Identifier: GPL-3.0-or-later
// The smoothing of the patch boundaries: block-coordinate descent (Gauss-Seidel) of the
// boundaries' length in the per-triangle anisotropic metric, over the points of the
// boundary state, plus moves of single vertices from one patch to the other where that
// lets a boundary pass on the other side of the vertex. Every change is kept only if the
// length of the boundary pieces it touches drops, so the energy never rises; a vertex
// moves only where its ring has exactly two patches, each one contiguous run, so no
// patch, junction, adjacency or curve appears or disappears.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_SMOOTHING_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_SMOOTHING_IMPL_H

#include <CGAL/Feature_segmentation/internal/boundary_state.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Boundary_smoothing_result
{
  std::vector<double> energy, length; // before, then after every iteration
  std::size_t iterations = 0;
  std::size_t vertex_moves = 0;
  bool converged = false;
};

template <typename TriangleMesh>
class Boundary_smoother
{
public:
  typedef Boundary_state<TriangleMesh> State;
  typedef typename State::Vec3 Vec3;
  static constexpr std::size_t npos = State::npos;
  // a boundary point this close to a vertex (in edge parameter) presses against it
  static constexpr double pressed_distance = 0.1;

  explicit Boundary_smoother(State& s) : m_s(s) {}

  // `iterations` sweeps at most; stops earlier when a sweep lowers the energy by no more
  // than `tolerance` times its value.
  Boundary_smoothing_result run(std::size_t iterations, double tolerance)
  {
    Boundary_smoothing_result r;
    // Only the movable vertices change patch, so every edge that is or becomes cut has
    // a movable end and lies in its ring, and every face with cut edges has one of those
    // edges: the sweeps, the vertex moves and the energies look at these edges, faces and
    // vertices only (in increasing order, as a pass over the whole mesh would; a face
    // without cut edges adds an energy of exactly 0), so that an iteration costs what
    // the boundaries hold, not what the mesh holds.
    std::vector<std::size_t> movers, near_edges, near_faces;
    for(std::size_t v = 0; v < m_s.number_of_vertices(); ++v)
    {
      if(!m_s.movable[v]) continue;
      movers.push_back(v);
      for(std::size_t i = m_s.ring_begin(v); i < m_s.ring_end(v); ++i)
      {
        near_edges.push_back(m_s.ring_entries[i][1]);
        if(m_s.ring_entries[i][2] != npos) near_faces.push_back(m_s.ring_entries[i][2]);
      }
    }
    for(auto* list : { &near_edges, &near_faces })
    {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    auto energy = [&](bool anisotropic) {
      double e = 0;
      for(std::size_t f : near_faces) e += m_s.face_energy(f, anisotropic);
      return e;
    };
    r.energy.push_back(energy(true));
    r.length.push_back(energy(false));
    std::vector<std::size_t> cut, faces;
    std::vector<char> marked(m_s.number_of_faces(), 0);
    for(std::size_t it = 0; it < iterations; ++it)
    {
      cut.clear();
      faces.clear();
      for(std::size_t e : near_edges)
        if(m_s.is_cut(e))
        {
          cut.push_back(e);
          for(std::size_t f : m_s.edge_faces[e])
            if(f != npos && !marked[f]) { marked[f] = 1; faces.push_back(f); }
        }
      if(cut.empty())
      {
        // no boundary inside the faces: a sweep changes nothing, and its energy is 0
        r.energy.push_back(r.energy.back());
        r.length.push_back(r.length.back());
        ++r.iterations;
        r.converged = true;
        break;
      }
      std::sort(faces.begin(), faces.end());
      for(std::size_t f : faces) marked[f] = 0;
      std::vector<double> t0(cut.size());
      std::vector<Vec3> x0(faces.size());
      for(std::size_t k = 0; k < cut.size(); ++k) t0[k] = m_s.edge_t[cut[k]];
      for(std::size_t k = 0; k < faces.size(); ++k) x0[k] = m_s.face_x[faces[k]];
      for(std::size_t f : faces) update_face(f);
      for(std::size_t e : cut) update_edge(e);
      extrapolate(cut, faces, t0, x0);
      for(std::size_t v : movers)
        if(try_vertex_move(v)) ++r.vertex_moves;
      r.energy.push_back(energy(true));
      r.length.push_back(energy(false));
      ++r.iterations;
      const double before = r.energy[r.energy.size() - 2], after = r.energy.back();
      if(before - after <= tolerance * before)
      {
        r.converged = true;
        break;
      }
    }
    return r;
  }

  // The point of face f at the minimum of the face's energy: on a through triangle, the
  // midpoint of its two edge points (any point of that segment is a minimum: the metric
  // is a norm, constant on the triangle); at a junction, the Fermat-Weber point of its
  // three edge points in the metric (Weiszfeld's iteration in coordinates where the
  // metric is Euclidean), kept inside the triangle.
  bool update_face(std::size_t f)
  {
    std::array<std::size_t, 3> c;
    const int n = m_s.cut_edges(f, c);
    if(n == 0) return false;
    Vec3 x;
    if(n == 2) x = 0.5 * (m_s.edge_point(c[0]) + m_s.edge_point(c[1]));
    else
    {
      const Triangle_metric& m = (*m_s.metrics)[f];
      if(m.is_degenerate()) return false;
      const Vec3 origin = m_s.points[m_s.face_vertices[f][0]];
      const double sq = std::sqrt(m.lambda2);
      auto to2 = [&](const Vec3& p) {
        const Eigen::Vector2d w((p - origin).dot(m.u), (p - origin).dot(m.v));
        return Eigen::Vector2d(w.dot(m.e1), sq * w.dot(m.e2));
      };
      std::array<Eigen::Vector2d, 3> q;
      double scale = 0;
      for(int i = 0; i < 3; ++i) q[i] = to2(m_s.edge_point(c[i]));
      for(int i = 0; i < 3; ++i) scale = (std::max)(scale, (q[i] - q[(i + 1) % 3]).norm());
      if(!(scale > 0)) return false;
      Eigen::Vector2d y = to2(m_s.face_x[f]);
      for(int k = 0; k < 200; ++k)
      {
        Eigen::Vector2d num = Eigen::Vector2d::Zero();
        double den = 0;
        bool at_anchor = false;
        for(int i = 0; i < 3; ++i)
        {
          const double d = (y - q[i]).norm();
          if(d < 1e-12 * scale) { at_anchor = true; break; }
          num += q[i] / d;
          den += 1 / d;
        }
        if(at_anchor) break;
        const Eigen::Vector2d next = num / den;
        const double step = (next - y).norm();
        y = next;
        if(step < 1e-12 * scale) break;
      }
      const Eigen::Vector2d w = y[0] * m.e1 + (y[1] / sq) * m.e2;
      x = m_s.keep_inside(f, origin + w[0] * m.u + w[1] * m.v, State::face_margin);
    }
    const Vec3 old = m_s.face_x[f];
    const double before = m_s.face_energy(f);
    m_s.face_x[f] = x;
    if(m_s.face_energy(f) < before) return true;
    m_s.face_x[f] = old;
    return false;
  }

  // The point of cut edge e at the minimum of the length of the boundary in its (one or
  // two) triangles, with each through triangle's point on the straight segment between
  // its edge points: a convex function of the edge parameter, minimised by golden section.
  bool update_edge(std::size_t e)
  {
    std::array<std::size_t, 2> faces = { m_s.edge_faces[e][0], m_s.edge_faces[e][1] };
    std::array<Vec3, 2> target;
    std::array<bool, 2> through = { false, false };
    for(int k = 0; k < 2; ++k)
    {
      const std::size_t f = faces[k];
      if(f == npos) continue;
      std::array<std::size_t, 3> c;
      const int n = m_s.cut_edges(f, c);
      CGAL_assertion(n >= 2);
      if(n == 2) { through[k] = true; target[k] = m_s.edge_point(c[0] == e ? c[1] : c[0]); }
      else target[k] = m_s.face_x[f];
    }
    const double before = local_energy(faces);
    const double t = State::minimize_convex(State::edge_margin, 1 - State::edge_margin, [&](double s) {
      const Vec3 p = m_s.edge_point(e, s);
      double sum = 0;
      for(int k = 0; k < 2; ++k)
        if(faces[k] != npos) sum += (*m_s.metrics)[faces[k]].anisotropic(p - target[k]);
      return sum;
    });
    const double old_t = m_s.edge_t[e];
    const std::array<Vec3, 2> old_x = { faces[0] != npos ? m_s.face_x[faces[0]] : Vec3::Zero(),
                                        faces[1] != npos ? m_s.face_x[faces[1]] : Vec3::Zero() };
    m_s.edge_t[e] = t;
    for(int k = 0; k < 2; ++k)
      if(through[k]) m_s.face_x[faces[k]] = 0.5 * (m_s.edge_point(e) + target[k]);
    if(local_energy(faces) < before) return true;
    m_s.edge_t[e] = old_t;
    for(int k = 0; k < 2; ++k)
      if(faces[k] != npos) m_s.face_x[faces[k]] = old_x[k];
    return false;
  }

  // Moves vertex v to the other patch of its ring when that shortens the boundary around
  // it. Tried only where a boundary point lies within a tenth of its edge from v. Allowed only for vertices on the input boundary (`movable`), whose ring holds v's
  // patch a and one other patch b, as two contiguous runs (one run each along the ring, a
  // path for a border vertex): then the boundary near v is one piece of one a-b curve,
  // which the move reroutes to the other side of v; nothing else changes. The new cut
  // edges' points start at their midpoints and are relaxed (the ring's edges only, four
  // sweeps), and the move is kept if the length in the triangles around v drops.
  bool try_vertex_move(std::size_t v)
  {
    if(!m_s.movable[v]) return false;
    const std::size_t b0 = m_s.ring_begin(v), b1 = m_s.ring_end(v);
    if(b0 == b1) return false;
    const std::size_t a = m_s.labels[v];
    std::size_t b = a;
    for(std::size_t i = b0; i < b1; ++i)
    {
      const std::size_t l = m_s.labels[m_s.ring_entries[i][0]];
      if(l == a) continue;
      if(b == a) b = l;
      else if(l != b) return false; // a third patch around v
    }
    if(b == a) return false;
    const bool border = m_s.is_border_vertex(v);
    std::size_t changes = 0;
    for(std::size_t i = b0; i + 1 < b1; ++i)
      if(m_s.labels[m_s.ring_entries[i][0]] != m_s.labels[m_s.ring_entries[i + 1][0]]) ++changes;
    if(!border && m_s.labels[m_s.ring_entries[b1 - 1][0]] != m_s.labels[m_s.ring_entries[b0][0]]) ++changes;
    if(changes != (border ? 1u : 2u)) return false;
    // Only where the boundary presses against v: a move sends the boundary across v, and
    // is worth trying only if some boundary point next to v is already near it (a point
    // away from v would lengthen the boundary by going around v on the other side).
    bool pressed = false;
    for(std::size_t i = b0; i < b1 && !pressed; ++i)
    {
      const std::size_t e = m_s.ring_entries[i][1];
      if(!m_s.is_cut(e)) continue;
      const double from_v = (m_s.edge_vertices[e][0] == v) ? m_s.edge_t[e] : 1 - m_s.edge_t[e];
      pressed = from_v <= pressed_distance;
    }
    if(!pressed) return false;

    std::vector<std::size_t> star;
    for(std::size_t i = b0; i < b1; ++i)
      if(m_s.ring_entries[i][2] != npos) star.push_back(m_s.ring_entries[i][2]);
    double before = 0;
    for(std::size_t f : star) before += m_s.face_energy(f);
    std::vector<double> old_t;
    for(std::size_t i = b0; i < b1; ++i) old_t.push_back(m_s.edge_t[m_s.ring_entries[i][1]]);
    std::vector<Vec3> old_x;
    for(std::size_t f : star) old_x.push_back(m_s.face_x[f]);

    m_s.labels[v] = b;
    for(std::size_t i = b0; i < b1; ++i)
      if(m_s.is_cut(m_s.ring_entries[i][1])) m_s.edge_t[m_s.ring_entries[i][1]] = 0.5;
    for(std::size_t f : star)
    {
      std::array<std::size_t, 3> c;
      if(m_s.cut_edges(f, c) == 2) m_s.face_x[f] = 0.5 * (m_s.edge_point(c[0]) + m_s.edge_point(c[1]));
    }
    for(int sweep = 0; sweep < 4; ++sweep)
      for(std::size_t i = b0; i < b1; ++i)
        if(m_s.is_cut(m_s.ring_entries[i][1])) update_edge(m_s.ring_entries[i][1]);
    double after = 0;
    for(std::size_t f : star) after += m_s.face_energy(f);
    // a relative margin: a move that gains only rounding noise is not worth a topology change
    if(after < before * (1 - 1e-9)) return true;
    m_s.labels[v] = a;
    for(std::size_t i = b0; i < b1; ++i) m_s.edge_t[m_s.ring_entries[i][1]] = old_t[i - b0];
    for(std::size_t k = 0; k < star.size(); ++k) m_s.face_x[star[k]] = old_x[k];
    return false;
  }

  // Coordinate descent moves a whole curve slowly (each point alone sees a small gain,
  // e.g. to shift a boundary onto a nearby crease); so, after a sweep, the sweep's
  // displacement is extrapolated by factors 2, 4, ... 64, points kept in their domains,
  // and the best of these states is kept if it has a lower energy.
  // `cut`: the cut edges, `faces`: the faces with cut edges (both in increasing order),
  // `t0`, `x0`: their points before the sweep.
  void extrapolate(const std::vector<std::size_t>& cut, const std::vector<std::size_t>& faces,
                   const std::vector<double>& t0, const std::vector<Vec3>& x0)
  {
    std::vector<double> t1(cut.size());
    std::vector<Vec3> x1(faces.size());
    for(std::size_t k = 0; k < cut.size(); ++k) t1[k] = m_s.edge_t[cut[k]];
    for(std::size_t k = 0; k < faces.size(); ++k) x1[k] = m_s.face_x[faces[k]];
    // the energy is that of the faces with cut edges, summed in the order of total_energy()
    auto energy_of_faces = [&]() {
      double e = 0;
      for(std::size_t f : faces) e += m_s.face_energy(f, true);
      return e;
    };
    double best = energy_of_faces(), best_factor = 1;
    auto apply = [&](double factor) {
      for(std::size_t k = 0; k < cut.size(); ++k)
        m_s.edge_t[cut[k]] = (std::min)(1 - State::edge_margin,
                                        (std::max)(State::edge_margin, t0[k] + factor * (t1[k] - t0[k])));
      for(std::size_t k = 0; k < faces.size(); ++k)
      {
        const std::size_t f = faces[k];
        std::array<std::size_t, 3> c;
        const int n = m_s.cut_edges(f, c);
        if(n == 2) m_s.face_x[f] = 0.5 * (m_s.edge_point(c[0]) + m_s.edge_point(c[1]));
        else if(n == 3)
          m_s.face_x[f] = m_s.keep_inside(f, x0[k] + factor * (x1[k] - x0[k]), State::face_margin);
      }
    };
    for(double factor = 2; factor <= 64; factor *= 2)
    {
      apply(factor);
      const double energy = energy_of_faces();
      if(energy < best) { best = energy; best_factor = factor; }
      else break; // the energy along the ray is convex: past its minimum
    }
    if(best_factor > 1) apply(best_factor);
    else
    {
      for(std::size_t k = 0; k < cut.size(); ++k) m_s.edge_t[cut[k]] = t1[k];
      for(std::size_t k = 0; k < faces.size(); ++k) m_s.face_x[faces[k]] = x1[k];
    }
  }

private:
  double local_energy(const std::array<std::size_t, 2>& faces) const
  {
    double s = 0;
    for(std::size_t f : faces) if(f != npos) s += m_s.face_energy(f);
    return s;
  }

  State& m_s;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_BOUNDARY_SMOOTHING_IMPL_H
