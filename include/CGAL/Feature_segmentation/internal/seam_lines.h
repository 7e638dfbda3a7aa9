// SPDX-License-Identifier: GPL-3.0-or-later
// Seam lines: where two curved faces of a CAD part meet without a crease and the smaller
// principal curvature jumps (a cylinder running into a torus along a bent pipe, into a
// sphere or a corner blend), which neither the dihedral angles nor the flat regions of
// the curvature discontinuities (tangent_discontinuities.h) see. The fitted k2 (the
// principal curvature of smaller magnitude) steps there over the width of the fit, so
// the derivative of k2 along its own direction, dk2, peaks on the seam and is about zero
// on either side (a cylinder, a torus and a sphere have dk2 = 0: k2 is constant along its
// lines of curvature). A seam line is a ridge of the jump q = |dk2| h / |k1| (the change
// of k2 across the fit's width h, relative to the larger curvature) along the direction
// of k2: the crest-line detector of crest_lines_impl.h run on q, its derivative along d2
// and d2. A point keeps its jump only where it is a step between two faces: q low and k2
// steady at some distance on both sides along d2, and the two sides' k2 apart. A blip
// is no seam: the fits of a coarse tessellation subdivided flat see its facets, and
// their dk2 peaks along every facet edge with the same k2 on both sides. The pipeline
// looks for seam lines on clean CAD tessellations only (edit_precomputation.h): a noisy
// mesh's fitted k2 is steady nowhere.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_SEAM_LINES_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_SEAM_LINES_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/crest_lines_impl.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the seam lines, chosen on the development and generated parts
// (evaluate_quality --only cad, clean; manual, Creases). They are relative: the jump to
// the larger curvature, lengths to the bounding box's diagonal.
struct Seam_thresholds
{
  // The width h over which the fit spreads a jump: 1% of the diagonal (the fit radius),
  // or `edges` mean edge lengths if more (two rings set the fit's scale on a coarse mesh).
  static constexpr double width = 0.01, edges = 2.;
  // The least jump q at a point of a seam line: the jump of a bent pipe's k2 is 0.13 to
  // 0.22 of its k1 where the pipe bends most and falls to zero where it bends least, so
  // a seam line ends there and the correlation clustering closes the loop. The windows
  // below reject what a lower jump lets in. The figures of these comments but the
  // windows' were measured with the windows searched vertex by vertex 1.5 widths away:
  // at 0.01 and at 0.02 the evaluation is the same; at 0.03 and 0.05 the bent pipes lose
  // pieces of their inner seams (generated parts 0.976 -> 0.970 and 0.954).
  static constexpr double least_jump = 0.02;
  // The least strength of a seam line (the integral of q along it) and its least length,
  // in diagonals: the fit's fragments near creases and on freeform faces are short.
  // Without the length, fandisk gets 27 patches and its flat subdivision 28 (26 with it);
  // at twice the length, part 127460 loses seams (F 0.86 -> 0.80).
  static constexpr double least_strength = 0.004, least_length = 0.02;
  // alpha_e of a seam line's edges: alpha plus this. A seam runs along the larger
  // curvature, so the dual edges that cross it run along the smaller one, where the
  // anisotropic metric measures the Euclidean length: Similarity equals Award and only
  // alpha_e > 1 makes cutting them pay (at alpha 0.6 + 0.5 the bent pipes' inner seams
  // stay whole: F 0.97 -> 0.78 and 0.94 -> 0.67).
  static constexpr double alpha_offset = 1.0;
  // The windows ahead of and behind a point of a seam line along d2: centred `away`
  // widths from it, about one width across (Window_grid). Within them the mean q must
  // stay below `steady` times the point's (the fits are steady on both faces), and the
  // mean k2 must differ by `least_step` times |k1| (a step, not a blip). Chosen on the
  // development and generated parts with CGAL's fandisk and its flat subdivision into 16
  // (test_resolution.cpp), whose fits see the coarse facets and whose dk2 peaks along
  // each of them: without the windows the subdivision gets 272 patches for 26. With the
  // grid, fandisk stays at 26 patches at both resolutions with steady 0.4 to 0.6
  // and a least step of 0.05 or 0.06, but gets 27 at one of them with a least step of
  // 0.04 or the windows 1.1 or 1.5 widths away; a larger least step costs the bent pipes
  // pieces of their inner seams (generated parts 0.977 at 0.05, 0.957 at 0.07).
  static constexpr double away = 1.25, steady = 0.5, least_step = 0.05;
  // The least |k1| of a point of a seam line, times the diagonal: where the surface is
  // nearly flat across as well as along (an inflection of a lobed section), the jump
  // relative to |k1| means nothing (a rod with four lobes whose girth swells gets short
  // seam lines along its inflections; none from 1.01 to 1.75).
  static constexpr double least_curvature = 1.5;
};

// The means of the jump q and of k2 near a point of the surface, by vertex, from a grid
// of cubic cells: the sums of each cell's vertices, apart by the side their normals face
// (the axis of their largest component and its sign, so that the two sides of a thin
// wall do not mix), blended trilinearly over the eight cells round the point.
class Window_grid
{
public:
  struct Mean
  {
    bool found = false;
    double jump = 0, k2 = 0;
  };

  // `parallel`: the vertices keyed and sorted by TBB's threads (the pairs are distinct:
  // the same order at any thread count).
  Window_grid(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normal,
              const std::vector<double>& jump, const std::vector<double>& k2, const Eigen::Vector3d& lo, double cell,
              bool parallel = false)
    : m_lo(lo), m_cell(cell)
  {
    std::vector<std::pair<std::uint64_t, std::size_t> > keyed(points.size());
    for_each_range(points.size(), parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
      {
        const Eigen::Vector3d g = (points[i] - m_lo) / m_cell;
        keyed[i] = { key(std::int64_t(std::floor(g.x())), std::int64_t(std::floor(g.y())), std::int64_t(std::floor(g.z())),
                         side(normal[i])), i };
      }
    });
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel)
      tbb::parallel_sort(keyed.begin(), keyed.end());
    else
#endif
      std::sort(keyed.begin(), keyed.end());
    for(const auto& k : keyed)
    {
      if(m_keys.empty() || m_keys.back() != k.first)
      {
        m_keys.push_back(k.first);
        m_sums.push_back(Sums());
      }
      Sums& s = m_sums.back();
      s.jump += jump[k.second];
      s.k2 += k2[k.second];
      s.count += 1;
    }
  }

  // the means near p of the vertices whose normals face the side of `n`
  Mean mean(const Eigen::Vector3d& p, const Eigen::Vector3d& n) const
  {
    const Eigen::Vector3d g = (p - m_lo) / m_cell - Eigen::Vector3d::Constant(0.5);
    const Eigen::Vector3d base(std::floor(g.x()), std::floor(g.y()), std::floor(g.z()));
    const Eigen::Vector3d f = g - base;
    const int s = side(n);
    double jump = 0, k2 = 0, count = 0;
    for(int corner = 0; corner < 8; ++corner)
    {
      const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
      const double w = (dx ? f.x() : 1 - f.x()) * (dy ? f.y() : 1 - f.y()) * (dz ? f.z() : 1 - f.z());
      if(!(w > 0)) continue;
      const std::uint64_t k = key(std::int64_t(base.x()) + dx, std::int64_t(base.y()) + dy, std::int64_t(base.z()) + dz, s);
      const auto it = std::lower_bound(m_keys.begin(), m_keys.end(), k);
      if(it == m_keys.end() || *it != k) continue;
      const Sums& c = m_sums[std::size_t(it - m_keys.begin())];
      jump += w * c.jump;
      k2 += w * c.k2;
      count += w * c.count;
    }
    Mean m;
    if(count > 0) { m.found = true; m.jump = jump / count; m.k2 = k2 / count; }
    return m;
  }

private:
  struct Sums
  {
    double jump = 0, k2 = 0, count = 0;
  };

  static int side(const Eigen::Vector3d& n)
  {
    int axis = 0;
    for(int i = 1; i < 3; ++i)
      if(std::abs(n[i]) > std::abs(n[axis])) axis = i;
    return 2 * axis + (n[axis] < 0 ? 1 : 0);
  }
  // cells within the box and a ring round it (coordinates from -1): 20 bits each
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z, int side)
  {
    const auto c = [](std::int64_t v) { return std::uint64_t(std::clamp<std::int64_t>(v + 2, 0, (1 << 20) - 1)); };
    return (((c(x) << 20 | c(y)) << 20 | c(z)) << 3) | std::uint64_t(side);
  }

  Eigen::Vector3d m_lo;
  double m_cell;
  std::vector<std::uint64_t> m_keys; // sorted
  std::vector<Sums> m_sums;
};

// The seam lines of the mesh of `idx` (Feature_line_type::SEAM, strongest first): `vpm`
// its points, `curvature` its principal curvatures (a vertex property map of
// Principal_curvatures); `parallel`: the windows of the points read by TBB's threads (the
// same lines at any thread count).
template <typename TriangleMesh, typename VPM, typename CurvatureMap>
Feature_lines<TriangleMesh> detect_seam_lines(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                              CurvatureMap curvature, bool parallel = false)
{
  typedef Seam_thresholds Limits;
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nv = idx.number_of_vertices(), nf = idx.number_of_faces(), ne = idx.number_of_edges();
  Feature_lines<TriangleMesh> out;
  if(nv == 0 || nf == 0) return out;
  std::vector<Eigen::Vector3d> points(nv);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const auto& p = get(vpm, idx.vertex_at(i));
    points[i] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    lo = lo.cwiseMin(points[i]);
    hi = hi.cwiseMax(points[i]);
  }
  const double diagonal = (hi - lo).norm();
  if(!(diagonal > 0)) return out;
  double mean_edge = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    mean_edge += (points[idx.id(source(h, tm))] - points[idx.id(target(h, tm))]).norm();
  }
  mean_edge /= double((std::max)(ne, std::size_t(1)));
  const double width = (std::max)(Limits::width * diagonal, Limits::edges * mean_edge);

  // the three vertices of face f
  const auto triangle = [&](std::size_t f) {
    std::array<std::size_t, 3> v = { 0, 0, 0 };
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
    {
      v[k++] = idx.id(target(h, tm));
      if(k == 3) break;
    }
    return v;
  };
  // the jump q and the direction of k2 per vertex
  std::vector<Crest_vertex_data> data(nv);
  std::vector<double> k2(nv, 0.), k1a(nv, 0.);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const auto& c = get(curvature, idx.vertex_at(i));
    const double k1 = (std::max)(std::abs(CGAL::to_double(c.k1)), 1. / diagonal);
    k1a[i] = k1;
    k2[i] = std::isfinite(CGAL::to_double(c.k2)) ? CGAL::to_double(c.k2) : 0.;
    const double q = std::abs(CGAL::to_double(c.dk2)) * width / k1;
    data[i].k = std::isfinite(q) && k1 * diagonal >= Limits::least_curvature ? q : 0.;
    data[i].t = Eigen::Vector3d(CGAL::to_double(c.d2.x()), CGAL::to_double(c.d2.y()), CGAL::to_double(c.d2.z()));
  }
  // A seam is a step between two regions of steady k2 (the fits of a flat-subdivided
  // coarse tessellation see its facets instead, and their dk2 peaks along every one of
  // them: file comment): a point of a seam keeps its jump only if, in the windows
  // `Limits::away` widths ahead of and behind it along d2, the mean q stays below
  // `Limits::steady` times its own and the mean k2 differs by at least
  // `Limits::least_step` of |k1|. The means are read from a grid of cells of half a width
  // (Window_grid): a constant cost per point at any resolution.
  {
    std::vector<double> jump(nv);
    for(std::size_t i = 0; i < nv; ++i) jump[i] = data[i].k;
    std::vector<Eigen::Vector3d> normal(nv, Eigen::Vector3d::Zero());
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::array<std::size_t, 3> v = triangle(f);
      const Eigen::Vector3d n = (points[v[1]] - points[v[0]]).cross(points[v[2]] - points[v[0]]);
      for(std::size_t x : v) normal[x] += n; // weighted by area
    }
    const Window_grid grid(points, normal, jump, k2, lo, 0.5 * width, parallel);
    for_each_range(nv, parallel, 4096, [&](std::size_t first, std::size_t last) {
      for(std::size_t v = first; v < last; ++v)
      {
        if(jump[v] < Limits::least_jump) continue;
        const Eigen::Vector3d& t = data[v].t;
        const Window_grid::Mean ahead = grid.mean(points[v] + Limits::away * width * t, normal[v]),
                                behind = grid.mean(points[v] - Limits::away * width * t, normal[v]);
        const bool steady = ahead.found && behind.found &&
                            (std::max)(ahead.jump, behind.jump) <= Limits::steady * jump[v] &&
                            std::abs(ahead.k2 - behind.k2) >= Limits::least_step * k1a[v];
        if(!steady) data[v].k = 0.;
      }
    });
  }
  // the derivative of q along d2: the gradient of q linear over each face, averaged over
  // the faces round each vertex by area
  std::vector<Eigen::Vector3d> gradient(nv, Eigen::Vector3d::Zero());
  std::vector<double> weight(nv, 0.);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::array<std::size_t, 3> v = triangle(f);
    const Eigen::Vector3d &a = points[v[0]], &b = points[v[1]], &c = points[v[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double twice_area = n.norm();
    if(!(twice_area > 0)) continue;
    const Eigen::Vector3d u = n / twice_area;
    // the gradient of the linear interpolant, times twice the area
    const Eigen::Vector3d g =
      data[v[0]].k * u.cross(c - b) + data[v[1]].k * u.cross(a - c) + data[v[2]].k * u.cross(b - a);
    for(std::size_t x : v)
    {
      gradient[x] += 0.5 * g;          // area times the gradient
      weight[x] += 0.5 * twice_area;
    }
  }
  for(std::size_t i = 0; i < nv; ++i)
  {
    data[i].e = weight[i] > 0 ? gradient[i].dot(data[i].t) / weight[i] : 0.;
    // a point below the least jump is no seam: its crossings fail the ridge test (k > 0)
    if(data[i].k < Limits::least_jump) data[i].k = 0.;
  }
  Crest_options options;
  options.strength_threshold = Limits::least_strength * diagonal;
  options.umbilic_ratio = 0.; // k_other is 0: the test is k > 0
  Crest_line_detector<TriangleMesh> detector(idx, points);
  Feature_lines<TriangleMesh> found;
  detector.detect(Feature_line_type::RIDGE, data, options, found, parallel); // the maxima of q
  for(auto& l : found.lines)
    if(l.length >= Limits::least_length * diagonal)
    {
      l.type = Feature_line_type::SEAM;
      out.lines.push_back(std::move(l));
    }
  detector.sort_lines(out);
  return out;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_SEAM_LINES_H
