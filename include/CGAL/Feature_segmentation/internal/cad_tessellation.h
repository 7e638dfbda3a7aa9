// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a tessellation is one of a CAD part, whose creases and curvature
// discontinuities bound its faces, or a smooth model, whose crest lines are its features
// (edit_precomputation.h): on a clean tessellation (no noise: crease_detection.h) by its
// creases and its exactly planar regions, on a rough one by its creases alone.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CAD_TESSELLATION_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CAD_TESSELLATION_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/face_components.h>

#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// A clean tessellation is one of a CAD part (its crest lines then weigh less, see
// clean_crest_alpha_offset) if its creases cut it into its faces, or if much of it lies
// in large exactly planar regions. A fine or remeshed smooth model is clean too, but its
// few creases leave one piece of almost all of it (99% or more on the paper's models
// remeshed to 200k faces or subdivided by Loop's scheme, against 8% to 71% on the clean
// parts of the evaluation and CGAL's CAD meshes), and next to none of it is exactly
// planar (at most 0.3%, against 0.6% to 100%). A CAD part of one dominant face, a shaft
// or a pin, is tessellated in planar strips along its rulings (a plain rod: all of it).
constexpr double cad_largest_piece_share = 0.9;
// Faces joined by edges whose normals differ by less than this (about radians) lie in
// one exactly planar region: a plane or a ruled strip, up to the rounding of the file.
constexpr double cad_planar_difference = 1e-4;
// The share of the area in planar regions of at least (cad_planar_side x diagonal)^2
// that makes a clean tessellation one of a CAD part whatever its creases.
constexpr double cad_planar_share = 0.05;
constexpr double cad_planar_side = 0.02;

// The share of the area of the mesh of `idx` (`area`: per face) in the largest of the
// pieces that the edges with `cut(e)` bound or, if `sum`, in all those of at least
// `least_area`.
template <typename TriangleMesh, typename Cut>
double piece_share(const Mesh_indexing<TriangleMesh>& idx, const std::vector<double>& area, Cut cut,
                   double least_area, bool sum)
{
  const std::size_t nf = idx.number_of_faces();
  const std::vector<std::size_t> component = face_components(idx, [&cut](std::size_t e) { return !cut(e); });
  std::vector<double> piece(nf, 0.);
  double total = 0.;
  for(std::size_t f = 0; f < nf; ++f)
  {
    total += area[f];
    piece[component[f]] += area[f];
  }
  double share = 0.;
  for(std::size_t f = 0; f < nf; ++f)
    if(component[f] == f && piece[f] >= least_area) share = sum ? share + piece[f] : (std::max)(share, piece[f]);
  return total > 0 ? share / total : 0.;
}

// Whether the creases `is_crease` cut the mesh of `idx` into pieces, the largest holding
// less than cad_largest_piece_share of the area (`area`: per face). This is the test of
// a rough mesh (noisy, or a coarse smooth model) too, which has no exactly planar region
// to tell: the creases found on its filtered normals still cut a noisy CAD part into its
// faces (ABC 00000655 and 00006102 at 0.1% noise of the diagonal: largest pieces of 69%
// and 64%), while those of the paper's smooth models as they are distributed leave one
// piece of 99.9% or more of their area. With noise of 0.1% of the diagonal added, some of
// them fall below 90% (pulley, vase, lamp, fertility) and count as CAD parts too; a long
// part with small ends (ABC 00004494, a rod with flat ends: 96%) does not.
template <typename TriangleMesh>
bool creases_cut_into_pieces(const Mesh_indexing<TriangleMesh>& idx, const std::vector<char>& is_crease,
                             const std::vector<double>& area)
{
  const auto creased = [&](std::size_t e) { return is_crease[e] != 0; };
  return piece_share(idx, area, creased, 0., false) < cad_largest_piece_share;
}

// Whether cad_planar_share of the area of the mesh of `idx` or more lies in exactly planar
// regions of at least (cad_planar_side x diagonal)^2: `normal` and `area` per face,
// `diagonal` the bounding box's. The planes and ruled strips of a CAD tessellator.
template <typename TriangleMesh>
bool has_large_planar_regions(const Mesh_indexing<TriangleMesh>& idx, const std::vector<Eigen::Vector3d>& normal,
                              const std::vector<double>& area, double diagonal)
{
  const TriangleMesh& tm = idx.mesh();
  const auto not_planar = [&](std::size_t e) { // asked of interior edges only
    const auto h = halfedge(idx.edge_at(e), tm);
    return (normal[idx.face_id(h)] - normal[idx.face_id(opposite(h, tm))]).squaredNorm() >=
           cad_planar_difference * cad_planar_difference;
  };
  return piece_share(idx, area, not_planar, CGAL::square(cad_planar_side * diagonal), true) >= cad_planar_share;
}

// Whether a clean tessellation is one of a CAD part (cad_largest_piece_share and
// cad_planar_share): `is_crease` the creases, `area` per face, `planar` whether it has
// large planar regions (has_large_planar_regions()).
template <typename TriangleMesh>
bool is_cad_tessellation(const Mesh_indexing<TriangleMesh>& idx, const std::vector<char>& is_crease,
                         const std::vector<double>& area, bool planar)
{
  return planar || creases_cut_into_pieces(idx, is_crease, area);
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CAD_TESSELLATION_H
