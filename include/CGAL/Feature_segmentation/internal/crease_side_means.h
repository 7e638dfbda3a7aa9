// SPDX-License-Identifier: GPL-3.0-or-later
// Moderate creases of noisy meshes, from the mean raw normals on the two sides of an
// edge. Under noise of 0.3% of the diagonal a face's normal is off by 17 to 44
// degrees (the median over a development part's faces; 28 on ABC part 3817), as much as
// a crease of 25 to 35 degrees (a cone meeting a cylinder, a hopper's walls): the
// bilateral filter of crease_detection.h weighs a neighbour across such a crease nearly
// as much as a noisy one beside it, and over its rounds it wipes the crease out (the
// cone of ABC part 3817 at 0.3% noise: 31.6 degrees clean, 5 to 10 degrees between the
// filtered normals of its two sides). Averaged over a few dozen faces, the raw normals
// keep it: the area-weighted mean normals of the faces on either side of an edge,
// within a few edge lengths of its midpoint, bend by the crease's angle (28 to 35
// degrees on 3817), while the noise left in them is a few degrees. What else bends
// them:
// - a curved face: its bend grows with the radius of the disk (twice the radius, twice
//   the bend), a crease's does not;
// - a bend farther off (a blend or crease a few edges away): the disk of half the radius
//   sees little of it, while a crease at the edge bends it as much;
// - a crease nearby: the sides stop at the creases already found;
// - the edges next to a crease, whose disks still straddle it: only the edge where the
//   bend peaks across the line is kept.
// The edges that pass these tests and join into a long line of their own become creases,
// and so do shorter lines of them that go on from the end of a long crease: noise breaks
// a moderate crease (the fine hopper's cylinder meeting its cone, 33.7 degrees, at 0.3%
// noise) into pieces whose gaps the side means fill a few edges at a time.
// A lightly noisy mesh gets them too, next to the narrow filter's creases
// (crease_narrow_filter.h): on a coarse tessellation (a cylinder of 16 facets around) the
// facets bend by 22.5 degrees, nearly as much as a cone's crease of 27 to 34, and the
// narrow filter cannot tell them apart, while the side means average the facets out.
// There the narrower disk's mean normals carry little noise, so a crease must keep more
// of its bend over half the radius than on a heavily noisy mesh: a fillet's middle does
// not.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_SIDE_MEANS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_SIDE_MEANS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/crease_narrow_filter.h>
#include <CGAL/Feature_segmentation/internal/crease_staircase.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the side-mean creases, chosen on the 30 development parts and the 14
// generated ones at 0.1% and 0.3% noise of the diagonal (manual, Creases); lengths in
// median edge lengths.
struct Side_mean_creases
{
  // the radius of the disk whose faces give the two sides' mean normals
  static constexpr double radius = 3.;
  // the bend must peak across the line: at least the bend of the disks moved by this much
  // to either side
  static constexpr double ridge_offset = 1.;
  // a crease at the edge: the bend over twice the radius is at most `wider` times the
  // bend (a curved face's doubles), and over half the radius at least `narrower` times
  // it (a bend farther off fades)
  static constexpr double wider = 1.5;
  static constexpr double narrower = 0.4;
  // the same over half the radius on a lightly noisy mesh, whose half disks are nearly
  // free of noise: a crease between flat sides keeps all of its bend there, a face of
  // even curvature half of it, a fillet as wide as 1.2 to 1.6 radii 0.53 to 0.56
  // (computed over continuous disks; test_crease_side_means.cpp checks one on a mesh)
  static constexpr double narrower_light = 0.65;
  // the fewest edges of a line of such edges that is kept, chosen among 8, 10, 11, 12, 14
  // and 16 (the narrow filter's): with 14 the development and generated means at 0.1%
  // and 0.3% noise are all as high as with 16 or higher, 12 loses ABC 00000655 and CAD
  // part 24051, 10 and 11 the fine hopper. A shorter line is kept where it goes on from
  // the end of creases that hold as many edges (add_crease_lines_and_extensions()): over
  // three noise realisations the development mean at 0.1% noise rises from 0.939 to
  // 0.944, the generated one from 0.799 to 0.809 (0.3%: 0.915 to 0.915, 0.709 to 0.717);
  // turning limits of 45 or 75 degrees instead of 60, or 7 or 28 crease edges instead of
  // 14, give the same means within 0.003.
  static constexpr std::size_t least_edges = 14;
};

// Adds to `is_crease` (marked 1, with their bend in `angle` if larger) the edges of the
// mesh of `idx` that are no crease yet and bend by `crease_angle` or more between the
// area-weighted mean raw normals of the faces on their two sides (Side_mean_creases; the
// faces within the disk around the edge's midpoint reached from its two faces without
// crossing a crease of `is_crease`, split by the plane through the edge across the
// surface), where the bend peaks across the edge, does not grow over a wider disk as a
// curved face's does nor fade over a narrower one, and such edges join into a line of
// Side_mean_creases::least_edges or more, or into a shorter one that goes on from the
// end of creases of as many edges (add_crease_lines_and_extensions()). `normal`, `area`,
// `centroid`: the faces' raw unit normals, areas and centroids; `filtered`: their
// filtered normals (which give the plane across the surface); `narrower`: the least
// ratio of the bend over half the radius to the bend (Side_mean_creases::narrower on a
// heavily noisy mesh, Side_mean_creases::narrower_light on a lightly noisy one). By TBB's
// threads if `parallel`, each edge on its own: the same result at any thread count.
// Returns the number of edges added.
template <typename TriangleMesh, typename VPM>
std::size_t add_side_mean_creases(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                  const std::vector<Eigen::Vector3d>& normal, const std::vector<double>& area,
                                  const std::vector<Eigen::Vector3d>& centroid,
                                  const std::vector<Eigen::Vector3d>& filtered, double crease_angle,
                                  std::vector<char>& is_crease, std::vector<double>& angle, bool parallel = false,
                                  double narrower = Side_mean_creases::narrower)
{
  typedef Side_mean_creases Limits;
  typedef std::uint32_t Id; // detect_creases() has checked that 3 ids per face fit
  const TriangleMesh& tm = idx.mesh();
  const std::size_t ne = idx.number_of_edges(), nf = idx.number_of_faces();
  const Id none = Id(-1);
  std::vector<Id> face_edge, across;
  face_edges_and_neighbours(idx, none, face_edge, across);
  std::vector<Eigen::Vector3d> middle, direction;
  std::vector<double> length;
  edge_middles_and_directions(idx, vpm, middle, direction, &length);
  const double w = median_length(length);
  const double radius = Limits::radius * w, offset = Limits::ridge_offset * w;
  const double to_degrees = 180. / CGAL_PI;

  std::vector<double> bend_of(ne, 0.);
  std::vector<char> candidate(ne, 0);
  // ranges of many edges: each holds a stamp per face
  for_each_range(ne, parallel, (std::max)(std::size_t(4096), ne / 32), [&](std::size_t first, std::size_t last) {
    std::vector<Id> stamp(nf, none), reached;
    // the faces whose centroids lie within `r` of `m`, reached from f and g without
    // crossing a crease (f and g always)
    auto reach = [&](Id f, Id g, const Eigen::Vector3d& m, double r, Id tag) {
      reached.assign({ f, g });
      stamp[f] = stamp[g] = tag;
      for(std::size_t i = 0; i < reached.size(); ++i)
        for(int k = 0; k < 3; ++k)
        {
          const Id y = across[3 * reached[i] + k];
          if(y == none || stamp[y] == tag || is_crease[face_edge[3 * reached[i] + k]]) continue;
          stamp[y] = tag;
          if((centroid[y] - m).squaredNorm() <= r * r) reached.push_back(y);
        }
    };
    // the angle in degrees between the mean normals of the reached faces within `r` of
    // `c` on either side of the plane through c normal to `across_direction` (0 if a
    // side has none)
    auto bend = [&](const Eigen::Vector3d& c, const Eigen::Vector3d& across_direction, double r) {
      Eigen::Vector3d side[2] = { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() };
      for(Id f : reached)
      {
        const Eigen::Vector3d d = centroid[f] - c;
        if(d.squaredNorm() <= r * r) side[d.dot(across_direction) > 0 ? 0 : 1] += area[f] * normal[f];
      }
      const double n0 = side[0].norm(), n1 = side[1].norm();
      if(!(n0 > 0) || !(n1 > 0)) return 0.;
      return std::acos((std::max)(-1., (std::min)(1., side[0].dot(side[1]) / (n0 * n1)))) * to_degrees;
    };
    for(std::size_t e = first; e < last; ++e)
    {
      if(is_crease[e]) continue;
      const auto h = halfedge(idx.edge_at(e), tm);
      const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, tm));
      if(f == idx.npos || g == idx.npos) continue;
      Eigen::Vector3d s = direction[e].cross(filtered[f] + filtered[g]);
      if(!(s.norm() > 0)) continue;
      s.normalize();
      const Eigen::Vector3d& m = middle[e];
      // two searches per edge, numbered apart from every other edge's
      reach(Id(f), Id(g), m, radius + offset, Id(2 * e));
      const double b = bend(m, s, radius);
      if(b < crease_angle || bend(m + offset * s, s, radius) > b || bend(m - offset * s, s, radius) > b ||
         bend(m, s, radius / 2) < narrower * b)
        continue;
      reach(Id(f), Id(g), m, 2 * radius, Id(2 * e + 1));
      if(bend(m, s, 2 * radius) > Limits::wider * b) continue;
      bend_of[e] = b;
      candidate[e] = 1;
    }
  });
  return add_crease_lines_and_extensions(idx, vpm, candidate, bend_of, Limits::least_edges, is_crease, angle);
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_SIDE_MEANS_H
