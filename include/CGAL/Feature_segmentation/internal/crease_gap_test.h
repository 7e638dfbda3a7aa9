// SPDX-License-Identifier: GPL-3.0-or-later
// The gap test of the crease candidates (crease_cut.h): a crease of a CAD tessellation
// stands alone, a strong bend of a smooth surface comes with slightly weaker ones.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_TEST_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_TEST_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The test that tells a crease from a strong bend of a smooth surface: within the ball
// around a candidate edge's midpoint (radius crease_gap_radius of the diagonal, at least
// two mean edge lengths), on the surface reached from the candidate, the edges bending
// by [crease_gap_band * crease_angle, crease_angle)
// may have at most crease_gap_ratio times the length of the candidates. A CAD
// tessellation leaves a gap below its creases (on the 14 parts of the evaluation, no
// edge between 15 and 30 degrees apart from the creases); a coarse or scanned smooth
// surface bends by every angle, so its strong bends come with as many slightly weaker
// ones around them.
constexpr double crease_gap_band = 0.75;
constexpr double crease_gap_ratio = 0.5;
constexpr double crease_gap_radius = 0.05;
// The raw roughness (normal_roughness) up to which the band is read on the raw angles:
// clean CAD parts measure at most 0.0085 and the paper's smooth models 0.012 to 0.028,
// whose filtered normals turn smooth bends into staircases with gaps; noisy meshes
// (0.035 and more at 0.1% of the diagonal) are read on the filtered angles.
constexpr double crease_gap_raw_roughness = 0.03;

// Drops the candidates (is_crease, from `angle`) that fail the gap test; `raw` are the
// dihedral angles of the unfiltered normals, `raw_roughness` their roughness. Each
// candidate's test reads the angles only, never is_crease, so the candidates are tested
// independently: by TBB's threads if `parallel`, with the same result at any count.
template <typename TriangleMesh, typename VPM>
void keep_creases_with_gap(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, const std::vector<double>& angle,
                           const std::vector<double>& raw, double raw_roughness, double crease_angle,
                           std::vector<char>& is_crease, bool parallel = false)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces(), ne = idx.number_of_edges();
  if(ne == 0) return;
  const std::vector<double>& band_angle = raw_roughness <= crease_gap_raw_roughness ? raw : angle;
  std::vector<Eigen::Vector3d> end0(ne), end1(ne);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  double mean_edge = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    const auto& p = get(vpm, source(h, tm));
    const auto& q = get(vpm, target(h, tm));
    end0[e] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    end1[e] = Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    lo = lo.cwiseMin(end0[e]).cwiseMin(end1[e]);
    hi = hi.cwiseMax(end0[e]).cwiseMax(end1[e]);
    mean_edge += (end1[e] - end0[e]).norm();
  }
  mean_edge /= double(ne);
  // on a coarse mesh the ball must still reach the candidate's neighbours
  const double r = (std::max)(crease_gap_radius * (hi - lo).norm(), 2 * mean_edge);
  // The length of the part of edge x inside the ball of radius r around c: lengths of
  // curves within a ball, the same on a mesh and on its flat subdivision.
  auto length_inside = [&](std::size_t x, const Eigen::Vector3d& c) {
    const Eigen::Vector3d d = end1[x] - end0[x], m = end0[x] - c;
    const double a = d.squaredNorm(), b = m.dot(d), k = m.squaredNorm() - r * r;
    const double disc = b * b - a * k;
    if(a == 0 || disc <= 0) return 0.;
    const double root = std::sqrt(disc);
    const double t0 = (std::max)(0., (-b - root) / a), t1 = (std::min)(1., (-b + root) / a);
    return t1 > t0 ? (t1 - t0) * std::sqrt(a) : 0.;
  };
  std::vector<std::array<std::size_t, 3> > adj(nf), adj_edge(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
    {
      adj[f][k] = idx.face_id(opposite(h, tm));
      adj_edge[f][k] = idx.edge_id(h);
      if(++k == 3) break;
    }
  }
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < ne; ++e)
    if(is_crease[e]) candidates.push_back(e);
  // A search over the faces from the candidate's two faces, across the edges that enter
  // the ball; the stamps and the queue are a thread's own.
  struct Work_space
  {
    std::vector<std::size_t> face_stamp, edge_stamp, queue;
  };
  std::vector<char> fails(candidates.size(), 0);
  auto test_range = [&](std::size_t first, std::size_t last, Work_space& ws) {
    if(ws.face_stamp.size() != nf)
    {
      ws.face_stamp.assign(nf, std::size_t(-1));
      ws.edge_stamp.assign(ne, std::size_t(-1));
    }
    for(std::size_t i = first; i < last; ++i)
    {
      const std::size_t e = candidates[i];
      const Eigen::Vector3d c = 0.5 * (end0[e] + end1[e]);
      const auto h = halfedge(idx.edge_at(e), tm);
      ws.queue.clear();
      for(std::size_t f : { idx.face_id(h), idx.face_id(opposite(h, tm)) })
        if(f != idx.npos && ws.face_stamp[f] != e) { ws.face_stamp[f] = e; ws.queue.push_back(f); }
      double band_length = 0, crease_length = 0;
      for(std::size_t j = 0; j < ws.queue.size(); ++j)
      {
        const std::size_t x = ws.queue[j];
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t y = adj[x][k], ye = adj_edge[x][k];
          if(ws.edge_stamp[ye] == e) continue; // seen from its other face
          ws.edge_stamp[ye] = e;
          const double inside = length_inside(ye, c);
          if(inside <= 0) continue;
          if(angle[ye] >= crease_angle) crease_length += inside;
          else if(band_angle[ye] >= crease_gap_band * crease_angle) band_length += inside;
          if(y == idx.npos || ws.face_stamp[y] == e) continue;
          ws.face_stamp[y] = e;
          ws.queue.push_back(y);
        }
      }
      fails[i] = band_length > crease_gap_ratio * crease_length;
    }
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::enumerable_thread_specific<Work_space> spaces;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& b) { test_range(b.begin(), b.end(), spaces.local()); });
  }
  else
#endif
  {
    (void)parallel;
    Work_space ws;
    test_range(0, candidates.size(), ws);
  }
  for(std::size_t i = 0; i < candidates.size(); ++i)
    if(fails[i]) is_crease[candidates[i]] = 0;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_TEST_H
