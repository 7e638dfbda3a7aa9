// SPDX-License-Identifier: GPL-3.0-or-later
// The creases of a tessellation (edges whose two faces bend by at least an angle), found
// on face normals that a bilateral filter has cleaned of noise when the tessellation is
// rough, kept where the gap test says they are no strong bend of a smooth surface, and
// the curvature discontinuities: between flat regions on a clean tessellation, at the
// borders of planes on a noisy one and on a rough one that is largely planes, the seams
// of surfaces of revolution and pipes, and the corners of rolling-ball blends; used by
// crease_cut.h, which cuts the mesh open along them.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_DETECTION_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_DETECTION_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/blend_corners.h>
#include <CGAL/Feature_segmentation/internal/cad_tessellation.h>
#include <CGAL/Feature_segmentation/internal/crease_gap_test.h>
#include <CGAL/Feature_segmentation/internal/crease_narrow_filter.h>
#include <CGAL/Feature_segmentation/internal/crease_side_means.h>
#include <CGAL/Feature_segmentation/internal/crease_staircase.h>
#include <CGAL/Feature_segmentation/internal/isolated_crease_faces.h>
#include <CGAL/Feature_segmentation/internal/normal_filters.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>
#include <CGAL/Feature_segmentation/internal/plane_borders.h>
#include <CGAL/Feature_segmentation/internal/revolution_seams.h>
#include <CGAL/Feature_segmentation/internal/tangent_discontinuities.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// Unit face normals (zero for a degenerate face), face areas and centroids; by TBB's
// threads if `parallel` (each face on its own: the same at any count).
template <typename TriangleMesh, typename VPM>
void face_geometry(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, std::vector<Eigen::Vector3d>& normal,
                   std::vector<double>& area, std::vector<Eigen::Vector3d>& centroid, bool parallel = false)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces();
  normal.assign(nf, Eigen::Vector3d::Zero());
  area.assign(nf, 0.);
  centroid.assign(nf, Eigen::Vector3d::Zero());
  for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
    {
      std::array<Eigen::Vector3d, 3> p = { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() };
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
      {
        const auto& q = get(vpm, target(h, tm));
        p[k++] = Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
        if(k == 3) break;
      }
      centroid[f] = (p[0] + p[1] + p[2]) / 3.;
      const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
      const double len = n.norm();
      if(len > 0 && std::isfinite(len)) { normal[f] = n / len; area[f] = 0.5 * len; }
    }
  });
}

// The faces that share a vertex with each face (itself included), as offsets into one
// array (CSR), in increasing order; 32-bit ids (13 per face on a regular mesh). Made from
// the faces of every vertex (listed in increasing order by one pass over the faces): each
// face's ring merges the sorted lists of its three vertices.
template <typename TriangleMesh>
void vertex_adjacent_faces(const Mesh_indexing<TriangleMesh>& idx, std::vector<std::uint32_t>& begin,
                           std::vector<std::uint32_t>& faces, bool parallel = false)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces(), nv = idx.number_of_vertices();
  if(3 * nf >= std::size_t(UINT32_MAX) || nv >= std::size_t(UINT32_MAX))
    throw std::length_error("the mesh has too many faces for the crease detection's 32-bit face rings");
  // the corners of every face, then the faces of every vertex (CSR)
  std::vector<std::uint32_t> corner(3 * nf, std::uint32_t(-1)), vertex_begin(nv + 1, 0);
  for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
    {
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
      {
        corner[3 * f + k] = std::uint32_t(idx.id(target(h, tm)));
        if(++k == 3) break;
      }
    }
  });
  for(std::uint32_t v : corner)
    if(v != std::uint32_t(-1)) ++vertex_begin[v + 1];
  for(std::size_t v = 0; v < nv; ++v) vertex_begin[v + 1] += vertex_begin[v];
  std::vector<std::uint32_t> vertex_faces(vertex_begin[nv]);
  {
    std::vector<std::uint32_t> fill(vertex_begin.begin(), vertex_begin.end() - 1);
    for(std::size_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        if(corner[3 * f + k] != std::uint32_t(-1)) vertex_faces[fill[corner[3 * f + k]]++] = std::uint32_t(f);
  }
  // Each face's ring merges the sorted lists of its three vertices, dropping repeats:
  // counted by face, then written at its offset (by TBB's threads if `parallel`).
  const auto merge = [&](std::size_t f, std::uint32_t* out) {
    const std::uint32_t* at[3];
    const std::uint32_t* end[3];
    for(int k = 0; k < 3; ++k)
    {
      const std::uint32_t v = corner[3 * f + k];
      at[k] = v == std::uint32_t(-1) ? nullptr : vertex_faces.data() + vertex_begin[v];
      end[k] = v == std::uint32_t(-1) ? nullptr : vertex_faces.data() + vertex_begin[v + 1];
    }
    std::uint32_t count = 0;
    for(;;)
    {
      std::uint32_t least = std::uint32_t(-1);
      for(int k = 0; k < 3; ++k)
        if(at[k] != end[k] && *at[k] < least) least = *at[k];
      if(least == std::uint32_t(-1)) break;
      if(out != nullptr) out[count] = least;
      ++count;
      for(int k = 0; k < 3; ++k)
        if(at[k] != end[k] && *at[k] == least) ++at[k];
    }
    return count;
  };
  std::vector<std::size_t> offset(nf + 1, 0);
  for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f) offset[f + 1] = merge(f, nullptr);
  });
  for(std::size_t f = 0; f < nf; ++f) offset[f + 1] += offset[f];
  if(offset[nf] >= std::size_t(UINT32_MAX))
    throw std::length_error("the mesh has too many faces for the crease detection's 32-bit face rings");
  faces.resize(offset[nf]);
  begin.resize(nf + 1);
  for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
    {
      merge(f, faces.data() + offset[f]);
      begin[f] = std::uint32_t(offset[f]);
    }
  });
  begin[nf] = std::uint32_t(offset[nf]);
}

// The range parameter of the bilateral filter of the normals, on |n_f - n_g| (0.3: the
// weight of a neighbour falls to 1/e at 25 degrees). Chosen on the CAD parts with and
// without noise (manual, Creases).
constexpr double crease_filter_sigma_r = 0.3;

// The roughness (normal_roughness) up to which the normals count as clean and are not
// filtered at all.
constexpr double crease_filter_roughness = 0.01;

// The roughness of a normal field: the median over the faces of the smallest |n_f - n_g|
// over the faces g sharing a vertex with f (about an angle in radians). On a clean
// tessellation almost every face has a neighbour with its own normal (in a flat part,
// along a cylinder's axis), even next to creases and on coarse cylinders: at most
// 0.0085 on the 14 CAD parts of the evaluation; noise of 0.1% of the diagonal along the
// normals makes it 0.035 to 0.1.
inline double normal_roughness(const std::vector<Eigen::Vector3d>& n, const std::vector<std::uint32_t>& begin,
                               const std::vector<std::uint32_t>& ring, bool parallel = false)
{
  const std::size_t nf = n.size();
  if(nf == 0) return 0.;
  std::vector<double> r(nf, 0.); // squared; the median's root is taken once
  for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
    {
      double least = 4.;
      for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
        if(ring[i] != f && n[ring[i]].squaredNorm() > 0) least = (std::min)(least, (n[f] - n[ring[i]]).squaredNorm());
      r[f] = least;
    }
  });
  std::nth_element(r.begin(), r.begin() + nf / 2, r.end());
  return std::sqrt(r[nf / 2]);
}

// The most rounds of filtering a smooth model gets (raw roughness between
// crease_filter_roughness and Crease_gap::raw_roughness). Its roughness is mostly the
// curvature of the surface, which the filter barely lowers (rockerarm took 32 rounds to
// reach 0.01, pulley never did in 40); 3 rounds already give the patch counts of 40 on
// the paper's models, and 10 leave a margin for noisier scans.
constexpr int crease_smooth_filter_iterations = 10;

// The rounds of filtering a noisy mesh (raw roughness above Crease_gap::raw_roughness)
// gets, of at most `max_rounds`: they grow with the cube of the roughness, reaching
// max_rounds at crease_noisy_full_roughness, and are at least crease_noisy_least_rounds.
// Light noise (0.1% of the diagonal: roughness 0.035 to 0.1) needs few rounds, and each
// further round blurs narrow faces of the part (the knurls of CAD part 30419 lose two
// thirds of their creases in 40 rounds, 30% in 3); heavy noise (0.3%: 0.1 to 0.22) needs
// all of them, or the faces tilted far from all their neighbours stay as spurious creases.
// Chosen on the 30 development parts at both noise levels among fixed counts and rules
// of this kind (manual, Creases).
constexpr double crease_noisy_full_roughness = 0.15;
constexpr int crease_noisy_least_rounds = 5;

inline int noisy_filter_rounds(double raw_roughness, int max_rounds)
{
  const double x = raw_roughness / crease_noisy_full_roughness;
  const double wanted = std::ceil(double(max_rounds) * x * x * x);
  return (std::min)(max_rounds, (std::max)(crease_noisy_least_rounds, int((std::min)(wanted, 1e6))));
}

// The least share of the area in planes (mark_plane_borders) for which a rough mesh that
// is not noisy (raw roughness between crease_filter_roughness and
// Crease_gap::raw_roughness) gets the borders of its planes: a smooth model, or a CAD
// part with light noise. The paper's smooth models measure at most 0.18 (lamp;
// rockerarm 0.11, screwdriver 0.09), and plane borders would cut their gently curved
// regions (rockerarm: 3 patches instead of 14); the coarse generated CAD parts that
// 0.1% noise of the diagonal leaves in this range measure 0.25 to 0.83 (hopper, rounded
// box, plate with holes), and without plane borders a rounded box is one patch.
constexpr double crease_rough_plane_share = 0.2;

// The creases of the mesh of `idx` (per edge): the edges whose dihedral angle is at
// least crease_angle on the face normals after at most `filter_iterations` rounds of
// bilateral filtering (none on a clean mesh; 0: the raw normals), so that noise along
// the normals neither makes creases in flat parts nor breaks real ones (on a heavily
// noisy mesh also those of the normals filtered along their gradient, and not those that
// are staircase steps: crease_staircase.h), and that pass the gap test
// (keep_creases_with_gap), marked 1, and on a lightly noisy one (raw roughness from
// Crease_gap::raw_roughness to Crease_staircase::roughness) those of a narrower filter
// (add_narrow_filter_creases, crease_narrow_filter.h), and on every noisy one (raw
// roughness above Crease_gap::raw_roughness) those of the mean raw normals on the two
// sides of an edge (add_side_mean_creases, crease_side_means.h), marked 1; on a clean
// tessellation (raw roughness at most crease_filter_roughness) and if `tangent`, the
// curvature discontinuities
// (mark_tangent_discontinuities), marked 2; on a noisy one (raw roughness above
// Crease_gap::raw_roughness) and if `tangent`, the borders of its planes on the filtered
// normals (mark_plane_borders), marked 2, and so on any other rough one whose planes
// hold crease_rough_plane_share of its area or more; on every one that is filtered, and
// if `tangent`, also the seams between the pieces of its surfaces of revolution and, on
// one that gets the plane borders, of its bent pipes (mark_revolution_seams), marked 2;
// a piece of one or two faces (if not clean, of up to crease_noisy_piece_max_faces)
// that these would cut out keeps its flattest edge
// (join_isolated_crease_faces). `angle` receives the filtered angles (of a crease of a
// heavily noisy mesh, the larger of the two filters'), `clean` whether the tessellation
// is clean, `cad` whether its crest lines weigh less, as those of a CAD
// part: is_cad_tessellation if clean; on a noisy mesh (raw roughness above
// Crease_gap::raw_roughness) always, since noise makes crest lines along every cylinder
// and round every torus, which at the full alpha cut a noisy part's faces (a torus of
// one face: 4 or 5 patches at 0.1% noise) and a noisy smooth model alike (rockerarm: 14
// patches clean, 46 at 0.1% noise with them at the full alpha, 15 weaker); else (a
// smooth model) creases_cut_into_pieces.
template <typename TriangleMesh, typename VPM>
std::vector<char> detect_creases(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, double crease_angle,
                                 int filter_iterations, bool tangent, std::vector<double>& angle, bool& clean,
                                 bool& cad, bool parallel = false)
{
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area;
  face_geometry(idx, vpm, normal, area, centroid, parallel);
  std::vector<std::uint32_t> begin, ring;
  vertex_adjacent_faces(idx, begin, ring, parallel);
  const std::vector<double> raw = dihedral_angles(idx, normal, parallel);
  const double raw_roughness = normal_roughness(normal, begin, ring, parallel);
  clean = raw_roughness <= crease_filter_roughness;
  // A clean tessellation is not filtered. A smooth model (raw roughness up to
  // Crease_gap::raw_roughness) is filtered until its median face is smooth or for
  // crease_smooth_filter_iterations rounds: each round also blurs its moderate bends. A
  // noisy mesh gets the rounds of noisy_filter_rounds without a stop: stopping when the
  // median face is smooth leaves the faces tilted far from all their neighbours (which
  // the range Gaussian protects) as spurious creases.
  const bool smooth = raw_roughness <= Crease_gap::raw_roughness;
  const double stop = smooth ? crease_filter_roughness : 0.;
  const bool filtered = raw_roughness > crease_filter_roughness && filter_iterations > 0;
  // the rings and spatial weights of every filter below, computed once
  std::optional<Normal_filter_ring> rings;
  std::vector<Eigen::Vector3d> filtered_normal;
  if(filtered)
  {
    rings.emplace(area, centroid, begin, ring);
    filtered_normal = filter_face_normals(normal, raw_roughness, *rings,
                                          stop > 0 ? (std::min)(filter_iterations, crease_smooth_filter_iterations)
                                                   : noisy_filter_rounds(raw_roughness, filter_iterations),
                                          crease_filter_sigma_r, stop, parallel);
  }
  angle = filtered ? dihedral_angles(idx, filtered_normal, parallel) : raw;
  // the plane borders: on every rough mesh, those of a mesh that is not noisy only if
  // its planes hold crease_rough_plane_share of its area
  const bool planes = !clean && tangent && filtered;
  // the bounding box's diagonal, for the rules of all but noisy tessellations (and the
  // planes of noisy ones)
  double diagonal = 0.;
  if(smooth || planes)
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
    for(auto v : vertices(idx.mesh()))
    {
      const auto& p = get(vpm, v);
      const Eigen::Vector3d x(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    diagonal = (hi - lo).norm();
  }
  // The planes and ruled strips of a CAD tessellator (none on a noisy mesh). With them,
  // the gap test weighs the band by direction: the facets of a coarse cylinder or cone
  // run across the crease where it ends. A smooth model has none, and its strong bends
  // come with weaker ones across them too (twirl: 37 crease edges more, weighted).
  const bool planar = smooth && has_large_planar_regions(idx, normal, area, diagonal);
  std::vector<char> is_crease(angle.size(), 0);
  for(std::size_t e = 0; e < angle.size(); ++e) is_crease[e] = angle[e] >= crease_angle ? 1 : 0;
  // On a heavily noisy mesh, the candidates are the edges that bend by crease_angle on
  // the normals filtered along their gradient, and those of the bilateral filter that
  // are no staircase step (crease_staircase.h); an edge's angle is the larger of the two.
  if(!smooth && filtered && raw_roughness >= Crease_staircase::roughness)
  {
    const std::vector<double> along = dihedral_angles(
      idx,
      filter_face_normals_along_gradient(normal, *rings, noisy_filter_rounds(raw_roughness, filter_iterations),
                                         crease_filter_sigma_r, parallel),
      parallel);
    const std::vector<char> step = staircase_creases(idx, vpm, is_crease, filtered_normal, centroid, parallel);
    for(std::size_t e = 0; e < angle.size(); ++e)
    {
      is_crease[e] = along[e] >= crease_angle || (is_crease[e] && !step[e]) ? 1 : 0;
      if(is_crease[e]) angle[e] = (std::max)(angle[e], along[e]);
    }
  }
  keep_creases_with_gap(idx, vpm, angle, raw, raw_roughness, crease_angle, is_crease, parallel,
                        Crease_gap::strong_angle, planar);
  // a lightly noisy mesh also gets the moderate creases that its bilateral filter blurs
  // and those that its coarse facets hide, a heavily noisy one those that it wipes out
  if(!smooth && filtered)
  {
    const bool lightly_noisy = raw_roughness < Crease_staircase::roughness;
    if(lightly_noisy)
      add_narrow_filter_creases(idx, vpm, normal, raw_roughness, *rings,
                                noisy_filter_rounds(raw_roughness, filter_iterations), crease_angle, is_crease, angle,
                                parallel);
    add_side_mean_creases(idx, vpm, normal, area, centroid, filtered_normal, crease_angle, is_crease, angle, parallel,
                          lightly_noisy ? Side_mean_creases::narrower_light : Side_mean_creases::narrower);
  }
  if(tangent && clean) mark_tangent_discontinuities(idx, vpm, raw, area, diagonal, is_crease);
  double plane_share = 0.;
  if(planes)
    plane_share = mark_plane_borders(idx, filtered_normal, normal, area, centroid, diagonal, is_crease,
                                     smooth ? crease_rough_plane_share : 0.);
  // a filtered mesh that is noisy, or smooth with planes holding
  // crease_rough_plane_share of its area: the one that gets the plane borders' edges
  const bool plane_bordered = filtered && (!smooth || plane_share >= crease_rough_plane_share);
  // the surfaces of revolution of a filtered mesh, a smooth model as a noisy one (the
  // nail ABC 00000655, whose shank bends into its tip by 7 degrees, is rough enough to
  // be filtered), get the seams between their pieces, and lose the creases inside their
  // pieces; the bent pipes of a plane-bordered mesh get theirs (the search for a pipe's
  // radius, on every region of a smooth model whose normals go round, makes the bunny's
  // run 1.2 s instead of 0.7 s). A clean tessellation has the seam lines; there the
  // profiles' round-off and the facets of a flat subdivision would decide the pieces (an
  // exact rod 40 radii long cut in two).
  if(tangent && filtered)
    mark_revolution_seams(idx, vpm, normal, area, centroid, begin, ring, is_crease, &angle, plane_bordered,
                          raw_roughness >= crease_noisy_full_roughness);
  // the corners of the rolling-ball blends that the marked edges bound, on a clean
  // tessellation and a plane-bordered mesh
  if(tangent && (clean || plane_bordered))
    mark_blend_corners(idx, normal, area, centroid, begin, ring, is_crease);
  if(clean) join_isolated_crease_faces(idx, angle, is_crease);
  else join_isolated_crease_faces(idx, angle, is_crease, crease_noisy_piece_max_faces, 180.);
  // a noisy mesh's crest lines weigh less whatever its creases (see above)
  cad = clean ? is_cad_tessellation(idx, is_crease, area, planar)
              : raw_roughness > Crease_gap::raw_roughness || creases_cut_into_pieces(idx, is_crease, area);
  return is_crease;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_DETECTION_H
