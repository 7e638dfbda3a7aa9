// SPDX-License-Identifier: GPL-3.0-or-later
// Moderate creases of lightly noisy meshes. The bilateral filter of the face normals
// (crease_detection.h) weighs a neighbour across a bend of 25 degrees by 1/e
// (crease_filter_sigma_r = 0.3), so over its rounds it also spreads a crease of 25 to 35
// degrees (a cone meeting a cylinder on a turned part or a hopper) over a band of edges
// none of which bends by the crease angle: at 0.1% noise of the diagonal the generated
// turned parts and the fine hopper lose those creases and come out as two or three
// patches instead of five. A narrower range kernel keeps such creases sharp, but it also
// gathers the steady turn of every curved face into flat strips and steps. The rule
// below adds of the narrow filter's creases those that are no staircase step
// (staircase_creases(), crease_staircase.h) and not yet creases, where they join into
// a long line of their own: the steps that the staircase test misses are short
// pieces, and so are the spurs and gap fills along the creases already found.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_NARROW_FILTER_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_NARROW_FILTER_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/crease_staircase.h>
#include <CGAL/Feature_segmentation/internal/normal_filters.h>
#include <CGAL/Feature_segmentation/internal/union_find.h>

#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the narrow filter's creases, chosen on the 30 development parts and
// the 14 generated ones at 0.1% noise of the diagonal (manual, Creases): sigma_r from
// 0.10 to 0.15 and lines of 12 to 24 edges give the same development mean (within
// 0.001) and generated means from 0.720 to 0.737; 0.18 loses the turned parts' creases,
// lines of 8 edges cut curved faces.
struct Narrow_filter_creases
{
  // the range parameter of the narrow bilateral filter (a neighbour across a bend of 10
  // degrees weighs 1/e)
  static constexpr double sigma_r = 0.12;
  // the fewest edges of a line of the narrow filter's creases that is kept
  static constexpr std::size_t least_edges = 16;
};

// The edges of `candidate` (nonzero) grouped into lines, edges sharing a vertex in one
// line: per edge of the mesh of `idx`, the number of edges of its line (0 for an edge
// that is no candidate).
template <typename TriangleMesh>
std::vector<std::size_t> crease_line_sizes(const Mesh_indexing<TriangleMesh>& idx, const std::vector<char>& candidate)
{
  const TriangleMesh& tm = idx.mesh();
  Smallest_root_union_find lines(idx.number_of_vertices());
  auto first_vertex = [&](std::size_t e) { return idx.id(source(halfedge(idx.edge_at(e), tm), tm)); };
  for(std::size_t e = 0; e < candidate.size(); ++e)
    if(candidate[e]) lines.unite(first_vertex(e), idx.id(target(halfedge(idx.edge_at(e), tm), tm)));
  const std::vector<std::size_t> root = lines.roots();
  std::vector<std::size_t> size_of_root(root.size(), 0), size(candidate.size(), 0);
  for(std::size_t e = 0; e < candidate.size(); ++e)
    if(candidate[e]) ++size_of_root[root[first_vertex(e)]];
  for(std::size_t e = 0; e < candidate.size(); ++e)
    if(candidate[e]) size[e] = size_of_root[root[first_vertex(e)]];
  return size;
}

// Marks in `is_crease` (1) the edges of `candidate` (nonzero) that lie on a line of at
// least `least_edges` of them (crease_line_sizes()), raising their `angle` to their
// `value` if larger; returns their number.
template <typename TriangleMesh>
std::size_t add_crease_lines(const Mesh_indexing<TriangleMesh>& idx, const std::vector<char>& candidate,
                             const std::vector<double>& value, std::size_t least_edges, std::vector<char>& is_crease,
                             std::vector<double>& angle)
{
  const std::vector<std::size_t> line = crease_line_sizes(idx, candidate);
  std::size_t added = 0;
  for(std::size_t e = 0; e < line.size(); ++e)
    if(line[e] >= least_edges)
    {
      is_crease[e] = 1;
      angle[e] = (std::max)(angle[e], value[e]);
      ++added;
    }
  return added;
}

// Marks in `is_crease` (1) the edges of `candidate` (nonzero) that lie on a line of at
// least `least_edges` of them (crease_line_sizes()), or on a shorter line that goes on
// from the end of a crease of `is_crease` (nonzero), or fills a gap between two: at a
// vertex where a crease ends (one crease edge) it has an edge that turns from the
// crease's by less than 60 degrees, and the creases it meets hold at least
// `least_edges` edges besides its own (counted on the lines of the candidates and the
// creases together). A stub off the middle of a crease, one that turns off at its end,
// or one that cuts across a corner between two creases of a noisy box is noise. `vpm`:
// the points of the mesh of `idx`. Raises their `angle` to their `value` if larger;
// returns their number.
template <typename TriangleMesh, typename VPM>
std::size_t add_crease_lines_and_extensions(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                            const std::vector<char>& candidate, const std::vector<double>& value,
                                            std::size_t least_edges, std::vector<char>& is_crease,
                                            std::vector<double>& angle)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t ne = candidate.size(), nv = idx.number_of_vertices();
  auto ends = [&](std::size_t e) {
    const auto h = halfedge(idx.edge_at(e), tm);
    return std::make_pair(std::size_t(idx.id(source(h, tm))), std::size_t(idx.id(target(h, tm))));
  };
  // the candidates' lines (by their smallest vertex) and the creases at each vertex
  Smallest_root_union_find lines(nv);
  std::vector<std::uint32_t> creases_at(nv, 0);
  std::vector<std::size_t> along_crease(nv, 0); // the other vertex of a crease edge
  std::vector<char> with_creases(ne, 0);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto v = ends(e);
    if(candidate[e]) lines.unite(v.first, v.second);
    if(is_crease[e])
    {
      ++creases_at[v.first];
      ++creases_at[v.second];
      along_crease[v.first] = v.second;
      along_crease[v.second] = v.first;
    }
    with_creases[e] = (candidate[e] || is_crease[e]) ? 1 : 0;
  }
  auto point = [&](std::size_t v) {
    const auto& p = get(vpm, idx.vertex_at(v));
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  // a candidate edge from v to w going on from the end of a crease at v
  auto goes_on = [&](std::size_t v, std::size_t w) {
    if(creases_at[v] != 1) return false;
    const Eigen::Vector3d in = point(v) - point(along_crease[v]), out = point(w) - point(v);
    const double n = in.norm() * out.norm();
    return n > 0 && in.dot(out) > 0.5 * n;
  };
  // per line (at its root): its edges, and whether it goes on from the end of a crease
  const std::vector<std::size_t> root = lines.roots();
  std::vector<std::size_t> line_edges(nv, 0);
  std::vector<char> goes_on_from_an_end(nv, 0);
  for(std::size_t e = 0; e < ne; ++e)
    if(candidate[e])
    {
      const auto v = ends(e);
      ++line_edges[root[v.first]];
      if(goes_on(v.first, v.second) || goes_on(v.second, v.first)) goes_on_from_an_end[root[v.first]] = 1;
    }
  const std::vector<std::size_t> joint = crease_line_sizes(idx, with_creases);
  std::size_t added = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    if(!candidate[e]) continue;
    const std::size_t r = root[ends(e).first];
    if(line_edges[r] >= least_edges || (goes_on_from_an_end[r] && joint[e] - line_edges[r] >= least_edges))
    {
      is_crease[e] = 1;
      angle[e] = (std::max)(angle[e], value[e]);
      ++added;
    }
  }
  return added;
}

// Adds to `is_crease` (marked 1, with their angle on the narrow filter in `angle` if
// larger) the edges of the mesh of `idx` that bend by `crease_angle` or more on the face
// normals `normal` (of raw roughness `raw_roughness`) after `rounds` rounds of the
// bilateral filter on `rings` with Narrow_filter_creases::sigma_r, are no staircase
// step of these creases (staircase_creases()), are no crease yet and lie on a line of
// at least Narrow_filter_creases::least_edges such edges (crease_line_sizes()); by
// TBB's threads if `parallel` (the same result at any count). Returns the number of
// edges added.
template <typename TriangleMesh, typename VPM>
std::size_t add_narrow_filter_creases(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                      const std::vector<Eigen::Vector3d>& normal, double raw_roughness,
                                      const Normal_filter_ring& rings, int rounds, double crease_angle,
                                      std::vector<char>& is_crease, std::vector<double>& angle, bool parallel = false)
{
  const std::vector<Eigen::Vector3d> narrow_normal =
    filter_face_normals(normal, raw_roughness, rings, rounds, Narrow_filter_creases::sigma_r, 0., parallel);
  const std::vector<double> narrow = dihedral_angles(idx, narrow_normal, parallel);
  std::vector<char> candidate(narrow.size(), 0);
  for(std::size_t e = 0; e < narrow.size(); ++e) candidate[e] = narrow[e] >= crease_angle ? 1 : 0;
  const std::vector<char> step = staircase_creases(idx, vpm, candidate, narrow_normal, rings.centroid, parallel);
  for(std::size_t e = 0; e < narrow.size(); ++e)
    if(step[e] || is_crease[e]) candidate[e] = 0;
  return add_crease_lines(idx, candidate, narrow, Narrow_filter_creases::least_edges, is_crease, angle);
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_NARROW_FILTER_H
