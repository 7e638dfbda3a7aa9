// SPDX-License-Identifier: GPL-3.0-or-later
// Tangent-continuous boundaries of clean CAD tessellations: where a fillet (or any
// curved face) meets a plane without a crease. A CAD tessellator puts the vertices of a
// cylinder or cone on straight rulings, so its triangles come in flat strips, and those
// of a plane in one flat region; the edges between two flat regions carry the bends.
// The mean curvature of a region is the bending of its border edges (half of each edge's
// dihedral angle times its length) over its area: 1/r on a strip of a cylinder of
// radius r, close to zero on a plane whatever bends it borders. A bent edge is a
// curvature discontinuity where the flatter side is a region of some extent (a plane,
// or a wide strip of a cylinder or cone) and the other side bends more than three times
// as much (Tangent_thresholds). Everything but the least face count of the flatter side
// is a length, an area or an angle, so the flat subdivision of a mesh has the same
// discontinuities (each edge split in two) unless a flat region of one or two triangles
// borders a bend.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_TANGENT_DISCONTINUITIES_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_TANGENT_DISCONTINUITIES_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/face_components.h>

#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The thresholds of the rule (file comment), measured on the 14 CAD parts of the
// evaluation (constants, not options).
struct Tangent_thresholds
{
  // Dihedral angle (degrees) below which two faces lie in one flat region: a CAD
  // tessellation makes the faces of a plane or of one ruling strip coplanar to rounding.
  static constexpr double flat_angle = 0.5;
  // The least dihedral angle (degrees) of a discontinuity: the plane-to-fillet lines of
  // the parts mostly bend by 2 to 10 degrees (half the angle step of the fillet's
  // tessellation), while large nearly flat faces tessellated irregularly (44647) carry
  // bends of 0.5 to 1.5 degrees between their flat regions.
  static constexpr double least_angle = 1.5;
  // A discontinuity: the flat side's mean curvature below this fraction of the other's.
  // Chosen on the development and generated parts (cad/, abc-dev/ and the generated set,
  // evaluate_quality): 0.1 keeps mostly the plane-to-fillet edges; 0.3 also finds the
  // seams where a wide curved strip meets a tighter blend (turned parts, rounded bars
  // and boxes), and lowers the boundary F of no part (means: development 0.972 ->
  // 0.975, generated 0.769 -> 0.917; manual, Creases).
  static constexpr double curvature_ratio = 0.3;
  // The least number of faces of the flat side: one or two triangles between the
  // rulings of a coarse fan (the wedges of a rotor's hub) are not a surface of their own
  // whatever their area.
  static constexpr std::size_t least_flat_faces = 3;
  // The least area of the flat side, as the square of this fraction of the bounding-box
  // diagonal: a single triangle or a few of a doubly curved tessellation have no
  // curvature of their own to compare (a length, so that a finer tessellation of the
  // same shape finds the same discontinuities).
  static constexpr double least_flat_side = 0.02;
};

// Marks with 2 in `is_crease` the non-crease edges of the mesh of `idx` that are
// curvature discontinuities (file comment); `angle`: the dihedral angles (degrees) of
// the raw face normals, `area`: the face areas, `diagonal`: the bounding box's. Meant
// for clean tessellations only
// (noise splits every flat region into single faces, which the rule then ignores).
template <typename TriangleMesh, typename VPM>
void mark_tangent_discontinuities(const Mesh_indexing<TriangleMesh>& idx, VPM vpm, const std::vector<double>& angle,
                                  const std::vector<double>& area, double diagonal, std::vector<char>& is_crease)
{
  typedef Tangent_thresholds Limits;
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces(), ne = idx.number_of_edges();
  std::vector<std::size_t> face0(ne, idx.npos), face1(ne, idx.npos);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    face0[e] = idx.face_id(h);
    face1[e] = idx.face_id(opposite(h, tm));
  }
  auto interior = [&](std::size_t e) { return face0[e] != idx.npos && face1[e] != idx.npos; };

  // flat regions, each named by its smallest face index
  const std::vector<std::size_t> region =
    face_components(idx, [&](std::size_t e) { return !is_crease[e] && angle[e] < Limits::flat_angle; });
  std::vector<double> region_area(nf, 0.), bend(nf, 0.);
  std::vector<std::size_t> region_faces(nf, 0);
  for(std::size_t f = 0; f < nf; ++f)
  {
    region_area[region[f]] += area[f];
    ++region_faces[region[f]];
  }
  const double least_area = CGAL::square(Limits::least_flat_side * diagonal);
  std::vector<double> length(ne, 0.);
  for(std::size_t e = 0; e < ne; ++e)
  {
    if(!interior(e) || is_crease[e] || angle[e] < Limits::flat_angle) continue;
    const auto h = halfedge(idx.edge_at(e), tm);
    const auto& p = get(vpm, source(h, tm));
    const auto& q = get(vpm, target(h, tm));
    length[e] = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    const double b = 0.5 * angle[e] * (3.14159265358979323846 / 180.) * length[e];
    bend[region[face0[e]]] += b;
    bend[region[face1[e]]] += b;
  }
  for(std::size_t e = 0; e < ne; ++e)
  {
    if(!interior(e) || is_crease[e] || angle[e] < Limits::least_angle) continue;
    const std::size_t a = region[face0[e]], b = region[face1[e]];
    if(a == b || !(region_area[a] > 0) || !(region_area[b] > 0)) continue;
    const double ka = bend[a] / region_area[a], kb = bend[b] / region_area[b];
    const std::size_t flat = ka < kb ? a : b;
    if((std::min)(ka, kb) < Limits::curvature_ratio * (std::max)(ka, kb) && region_area[flat] >= least_area &&
       region_faces[flat] >= Limits::least_flat_faces)
      is_crease[e] = 2;
  }
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_TANGENT_DISCONTINUITIES_H
