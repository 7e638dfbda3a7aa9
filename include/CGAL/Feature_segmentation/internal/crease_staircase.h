// SPDX-License-Identifier: GPL-3.0-or-later
// Creases of heavily noisy meshes that are steps of a smooth turn. The bilateral filter
// of the face normals (crease_detection.h) gathers the steady turn of a curved face
// whose facets bend by nearly the crease angle (a torus or tube some twenty facets
// round) into flat strips and steps far steeper than the crease angle, which no angle
// test can tell from creases. Two views of the same normals tell them apart:
// - the normals filtered along their gradient (filter_face_normals_along_gradient(),
//   normal_filters.h):
//   each face carries its neighbours' normals back along the gradient it fits over its
//   ring before averaging them, so a steady turn stays smooth and its steps do not form;
//   but a moderate crease that turns the way its curved side curves (a barrel meeting
//   its end disk) looks like more of the same turn and fades;
// - the steps themselves: a step of a smooth turn has another step nearly parallel to
//   it on both sides within a few edge lengths (staircase_creases()), a crease at most
//   on one side (a rib's or a thin wall's other crease).
// A heavily noisy mesh keeps the creases of the gradient-filtered normals and those of
// the bilateral filter that are not staircase steps (detect_creases()).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_STAIRCASE_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_STAIRCASE_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the staircase rule (those of the gradient filter are Gradient_filter
// in normal_filters.h), chosen on the 30 development parts and the generated ones at
// 0.1% and 0.3% noise (manual, Creases).
struct Crease_staircase
{
  // The raw roughness (normal_roughness) from which a noisy mesh gets the rule: heavy
  // noise (0.3% of the diagonal: 0.1 to 0.22); from 0 on, light noise (0.035 to 0.1)
  // loses narrow faces (the knurls of CAD part 30419 at 0.1% noise: F 0.98 -> 0.90).
  static constexpr double roughness = 0.08;
  // A step's neighbours: candidates whose direction is within acos(0.85) (32 degrees)
  // of it, at 0.5 to `reach` mean edge lengths across it and within 1.5 along it.
  static constexpr double parallel_cosine = 0.85;
  static constexpr double reach = 4.;
};

// The midpoint and unit direction (source to target; zero for an edge of length 0) of
// every edge of the mesh of `idx`, and its length in `length` if given; returns the mean
// edge length (0 without edges).
template <typename TriangleMesh, typename VPM>
double edge_middles_and_directions(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                   std::vector<Eigen::Vector3d>& middle, std::vector<Eigen::Vector3d>& direction,
                                   std::vector<double>* length = nullptr)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t ne = idx.number_of_edges();
  middle.resize(ne);
  direction.resize(ne);
  if(length) length->resize(ne);
  double sum = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    const auto& p = get(vpm, source(h, tm));
    const auto& q = get(vpm, target(h, tm));
    const Eigen::Vector3d a(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const Eigen::Vector3d b(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    middle[e] = 0.5 * (a + b);
    direction[e] = b - a;
    const double len = direction[e].norm();
    sum += len;
    if(len > 0) direction[e] /= len;
    if(length) (*length)[e] = len;
  }
  return ne > 0 ? sum / double(ne) : 0.;
}

// The median of the edge lengths `length` (reordered; 0 if empty): the length unit of
// the noisy-mesh crease rules (the mean is longer on meshes with slivers).
inline double median_length(std::vector<double>& length)
{
  if(length.empty()) return 0.;
  std::nth_element(length.begin(), length.begin() + std::ptrdiff_t(length.size() / 2), length.end());
  return length[length.size() / 2];
}

// Per edge of the mesh of `idx`, whether it is a candidate (nonzero in `candidate`) with
// another candidate nearly parallel to it on both sides (Crease_staircase): the
// candidates met on the faces reached from its two faces across edges, staying within
// `reach` mean edge lengths across it and two along it (a search ends once both sides
// have one); `normal`: unit face normals (the across direction is the edge's direction
// times the sum of its faces' normals), `centroid`: the faces'; the candidates by TBB's
// threads if `parallel`.
template <typename TriangleMesh, typename VPM>
std::vector<char> staircase_creases(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, const std::vector<char>& candidate,
                                    const std::vector<Eigen::Vector3d>& normal,
                                    const std::vector<Eigen::Vector3d>& centroid, bool parallel = false)
{
  typedef Crease_staircase Limits;
  typedef std::uint32_t Id; // detect_creases() has checked that 3 ids per face fit
  const TriangleMesh& tm = idx.mesh();
  const std::size_t ne = idx.number_of_edges(), nf = idx.number_of_faces();
  const Id none = Id(-1);
  // every edge's midpoint and unit direction, every face's edges and the faces across them
  std::vector<Eigen::Vector3d> middle, direction;
  const double w = edge_middles_and_directions(idx, vpm, middle, direction);
  std::vector<Id> face_edge, across;
  face_edges_and_neighbours(idx, none, face_edge, across);
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < ne; ++e)
    if(candidate[e]) candidates.push_back(e);
  std::vector<char> out(ne, 0);
  // each candidate on its own (its search reads `candidate` only): the same at any
  // thread count
  for_each_range(candidates.size(), parallel, 64, [&](std::size_t first, std::size_t last) {
    std::vector<char> mark(nf, 0);
    std::vector<Id> stack, seen;
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t e = candidates[c];
      const auto h = halfedge(idx.edge_at(e), tm);
      const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, tm));
      if(f == idx.npos || g == idx.npos) continue;
      const Eigen::Vector3d& m = middle[e];
      const Eigen::Vector3d& t = direction[e];
      const Eigen::Vector3d up = normal[f] + normal[g];
      if(!(t.squaredNorm() > 0) || !(up.norm() > 0)) continue;
      Eigen::Vector3d side_direction = t.cross(up);
      if(!(side_direction.norm() > 0)) continue;
      side_direction.normalize();
      bool side[2] = { false, false };
      stack.assign({ Id(f), Id(g) });
      seen = stack;
      mark[f] = mark[g] = 1;
      while(!stack.empty() && !(side[0] && side[1]))
      {
        const Id x = stack.back();
        stack.pop_back();
        for(int k = 0; k < 3; ++k)
        {
          const Id e2 = face_edge[3 * x + k];
          if(e2 != e && candidate[e2])
          {
            const Eigen::Vector3d d = middle[e2] - m;
            const double s = d.dot(side_direction);
            if(std::abs(direction[e2].dot(t)) >= Limits::parallel_cosine && std::abs(s) >= 0.5 * w &&
               std::abs(d.dot(t)) <= 1.5 * w)
              side[s > 0 ? 0 : 1] = true;
          }
          const Id y = across[3 * x + k];
          if(y == none || mark[y]) continue;
          const Eigen::Vector3d d = centroid[y] - m;
          if(std::abs(d.dot(side_direction)) > Limits::reach * w || std::abs(d.dot(t)) > 2 * w) continue;
          mark[y] = 1;
          seen.push_back(y);
          stack.push_back(y);
        }
      }
      for(Id x : seen) mark[x] = 0;
      out[e] = side[0] && side[1];
    }
  });
  return out;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_STAIRCASE_H
